package org.fclcert.eval;

import static org.fclcert.eval.Fcl.and;
import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefuzzificationMethod;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The container crane of Annex C (figure C.16) with rule 2's undefined {@code pos_big} corrected
 * to {@code pos_high}, and the three-rule subset of figure C.8.
 */
class ContainerCraneTest {

    private static Fcl.Block crane(boolean subset) {
        Fcl.Rules rules = Fcl.ruleBlock("No1").and(AndAlgorithm.MIN);
        if (subset) {
            rules.rule(and(is("distance", "medium"), is("angle", "pos_small")), then("power", "pos_medium"))
                    .rule(and(is("distance", "medium"), is("angle", "zero")), then("power", "zero"))
                    .rule(and(is("distance", "far"), is("angle", "zero")), then("power", "pos_medium"));
        } else {
            rules.rule(and(is("distance", "far"), is("angle", "zero")), then("power", "pos_medium"))
                    .rule(and(is("distance", "far"), is("angle", "neg_small")), then("power", "pos_high"))
                    .rule(and(is("distance", "far"), is("angle", "neg_big")), then("power", "pos_medium"))
                    .rule(and(is("distance", "medium"), is("angle", "neg_small")), then("power", "neg_medium"))
                    .rule(and(is("distance", "close"), is("angle", "pos_small")), then("power", "pos_medium"))
                    .rule(and(is("distance", "zero"), is("angle", "zero")), then("power", "zero"));
        }
        return Fcl.block("container_crane").input("distance").input("angle").output("power")
                .fuzzify("distance",
                        Fcl.term("too_far", pts(-5, 1, 0, 0)),
                        Fcl.term("zero", pts(-5, 0, 0, 1, 5, 0)),
                        Fcl.term("close", pts(0, 0, 5, 1, 10, 0)),
                        Fcl.term("medium", pts(5, 0, 10, 1, 22, 0)),
                        Fcl.term("far", pts(10, 0, 22, 1)))
                .fuzzify("angle",
                        Fcl.term("neg_big", pts(-50, 1, -5, 0)),
                        Fcl.term("neg_small", pts(-50, 0, -5, 1, 0, 0)),
                        Fcl.term("zero", pts(-5, 0, 0, 1, 5, 0)),
                        Fcl.term("pos_small", pts(0, 0, 5, 1, 50, 0)),
                        Fcl.term("pos_big", pts(5, 0, 50, 1)))
                .defuzzify(Fcl.defuzzify("power", DefuzzificationMethod.COGS)
                        .term("neg_high", single(-27)).term("neg_medium", single(-9)).term("zero", single(0))
                        .term("pos_medium", single(9)).term("pos_high", single(27)).defaultValue(0))
                .rules(rules);
    }

    /*
     * Figures C.6/C.7 at distance 12, angle 4, computed from the points of figure C.16:
     * distance: too_far 0 (12 is right of its last point (0,0)); zero 0 and close 0 (12 is beyond
     * their last points); medium on (10,1)-(22,0): (22-12)/12 = 5/6; far on (10,0)-(22,1): 2/12 = 1/6.
     * angle: neg_big 0, neg_small 0 (4 > 0); zero on (0,1)-(5,0): (5-4)/5 = 0.2; pos_small on
     * (0,0)-(5,1): 4/5 = 0.8; pos_big 0 (4 < 5).
     * The text of Annex C gives distance {0.1, 0.9, 0, 0, 0} (far, medium, ...): those numbers come
     * from the drawing of the committee draft, whose terms differ from figure C.16; with C.16's
     * points far is 1/6 and medium 5/6. The angle degrees {0, 0, 0.2, 0.8, 0} agree exactly.
     */
    @Test
    void fuzzificationDegreesOfFiguresC6AndC7() throws EvaluationException {
        FunctionBlockInstance fb = crane(false).instance();
        fb.set("distance", 12);
        fb.set("angle", 4);
        Trace trace = new Trace();
        fb.evaluate(trace);
        double[] distance = {0, 0, 0, 5.0 / 6, 1.0 / 6};
        String[] dTerms = {"too_far", "zero", "close", "medium", "far"};
        for (int i = 0; i < 5; i++) {
            assertEquals(distance[i], trace.termDegree("distance", dTerms[i]).orElseThrow(), 1e-15, dTerms[i]);
        }
        double[] angle = {0, 0, 0.2, 0.8, 0};
        String[] aTerms = {"neg_big", "neg_small", "zero", "pos_small", "pos_big"};
        for (int i = 0; i < 5; i++) {
            assertEquals(angle[i], trace.termDegree("angle", aTerms[i]).orElseThrow(), 1e-15, aTerms[i]);
        }
    }

    /*
     * Full rule base (C.16, pos_big read as pos_high):
     * 12, 4: only rule 1 fires (far 1/6 AND zero 0.2 = 1/6) -> pos_medium alone -> 9.
     * 20, -2: medium 2/12 = 1/6, far 10/12 = 5/6; neg_small (0+2)/5 = 0.4, zero 3/5 = 0.6.
     *   R1 far^zero = 0.6 -> pos_medium; R2 far^neg_small = 0.4 -> pos_high; R4 medium^neg_small
     *   = 1/6 -> neg_medium. CoGS = (9*0.6 + 27*0.4 - 9/6)/(0.6+0.4+1/6) = 14.7/(7/6) = 12.6.
     * 8, -2: close (10-8)/5 = 0.4, medium (8-5)/5 = 0.6; neg_small 0.4, zero 0.6.
     *   R4 medium^neg_small = 0.4 -> neg_medium only (R5 needs pos_small = 0) -> -9.
     * 2, -3: zero (5-2)/5 = 0.6, close 0.4; neg_small 0.6, zero 0.4. R6 zero^zero = 0.4 -> 0.
     * 30, 60: far 1 (beyond (22,1)); pos_big 1, zero 0 -> no rule of C.16 fires -> DEFAULT 0.
     */
    @ParameterizedTest(name = "distance={0} angle={1} -> {2}")
    @CsvSource({"12, 4, 9", "20, -2, 12.6", "8, -2, -9", "2, -3, 0", "30, 60, 0"})
    void fullRuleBase(double distance, double angle, double expected) throws EvaluationException {
        FunctionBlockInstance fb = crane(false).instance();
        fb.set("distance", distance);
        fb.set("angle", angle);
        fb.evaluate();
        assertEquals(expected, fb.get("power"), 1e-12);
    }

    /*
     * The subset of figure C.8 at 12, 4: R1 medium^pos_small = min(5/6, 0.8) = 0.8 -> pos_medium;
     * R2 medium^zero = 0.2 -> zero; R3 far^zero = min(1/6, 0.2) = 1/6 -> pos_medium.
     * Accumulation per term (C.13): pos_medium = max(0.8, 1/6) = 0.8 (the text's Max(0.8; 0.1) with
     * its far = 0.1), zero = 0.2. CoGS = (9*0.8 + 0*0.2)/1.0 = 7.2.
     */
    @Test
    void threeRuleSubsetOfFigureC8() throws EvaluationException {
        FunctionBlockInstance fb = crane(true).instance();
        fb.set("distance", 12);
        fb.set("angle", 4);
        Trace trace = new Trace();
        fb.evaluate(trace);
        assertEquals(0.8, trace.ruleDegrees().get(0).degree(), 1e-15);
        assertEquals(0.2, trace.ruleDegrees().get(1).degree(), 1e-15);
        assertEquals(1.0 / 6, trace.ruleDegrees().get(2).degree(), 1e-15);
        Trace.AccumulatedSet set = trace.accumulatedSet("power").orElseThrow();
        assertEquals(0.8, set.breakpoints().get(3).degree(), 1e-15);
        assertEquals(0.2, set.breakpoints().get(2).degree(), 1e-15);
        assertEquals(7.2, fb.get("power"), 1e-12);
    }
}
