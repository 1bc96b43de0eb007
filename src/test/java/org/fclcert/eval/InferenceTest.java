package org.fclcert.eval;

import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.num;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;
import static org.fclcert.eval.Fcl.var;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.Subconclusion;
import org.junit.jupiter.api.Test;

/**
 * Semantics points 3 (activation and weighting), 4 (accumulation) and 5 (defuzzification).
 * Every program has inputs p and q with the term "deg" := (0,0)(1,1), so the degree of
 * {@code p IS deg} is the value given to p: the tests choose rule degrees directly.
 */
class InferenceTest {
    private static final MembershipFunction IDENTITY = pts(0, 0, 1, 1);

    /** Output y with the given terms; rule 1: p IS deg THEN first; rule 2: q IS deg THEN second. */
    private static FunctionBlockInstance program(Fcl.Out out, ActivationMethod act, AccumulationMethod accu,
            Subconclusion first, Subconclusion second) {
        return Fcl.block("fb").input("p").input("q").input("w").output("y")
                .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                .defuzzify(out)
                .rules(Fcl.ruleBlock("r").act(act).accu(accu)
                        .rule(is("p", "deg"), first).rule(is("q", "deg"), second))
                .instance();
    }

    private static double run(FunctionBlockInstance fb, double p, double q) throws EvaluationException {
        fb.set("p", p);
        fb.set("q", q);
        fb.evaluate();
        return fb.get("y");
    }

    private static Fcl.Out triangle(DefuzzificationMethod m) {
        return Fcl.defuzzify("y", m).term("t", pts(0, 0, 10, 1, 20, 0)).term("u", pts(0, 0, 10, 1, 20, 0));
    }

    /*
     * Weight after activation (A.15, Table A.1): d=0.8, w=0.5, ACT MIN, T=(0,0)(10,1)(20,0).
     * fclcert: 0.5*min(0.8, T) has its plateau where T >= 0.8, i.e. [8, 12]: LM 8, RM 12.
     * Weight folded into the degree first, min(0.4, T), would have its plateau where T >= 0.4,
     * i.e. [4, 16]: LM 4, RM 16.
     */
    @Test
    void weightMultipliesTheResultOfMinActivation() throws EvaluationException {
        Subconclusion weighted = then("y", "t", num(0.5));
        Subconclusion unused = then("y", "u");
        assertEquals(8.0, run(program(triangle(DefuzzificationMethod.LM), ActivationMethod.MIN,
                AccumulationMethod.MAX, weighted, unused), 0.8, 0), 1e-12);
        assertEquals(12.0, run(program(triangle(DefuzzificationMethod.RM), ActivationMethod.MIN,
                AccumulationMethod.MAX, weighted, unused), 0.8, 0), 1e-12);
    }

    /*
     * The activated set is exactly w*min(d, T): d=0.8, w=0.5 gives vertices (0,0) (8,0.4) (12,0.4) (20,0).
     * ACT PROD gives w*d*T: (0,0) (10,0.4) (20,0).
     */
    @Test
    void activatedSetsInTheTrace() throws EvaluationException {
        Subconclusion weighted = then("y", "t", num(0.5));
        Subconclusion unused = then("y", "u");
        FunctionBlockInstance min = program(triangle(DefuzzificationMethod.COG), ActivationMethod.MIN,
                AccumulationMethod.MAX, weighted, unused);
        assertBreakpoints(min, 0.8, 0, 0, 0, 8, 0.4, 12, 0.4, 20, 0);
        FunctionBlockInstance prod = program(triangle(DefuzzificationMethod.COG), ActivationMethod.PROD,
                AccumulationMethod.MAX, weighted, unused);
        assertBreakpoints(prod, 0.8, 0, 0, 0, 10, 0.4, 20, 0);
    }

    private static void assertBreakpoints(FunctionBlockInstance fb, double p, double q, double... uy)
            throws EvaluationException {
        fb.set("p", p);
        fb.set("q", q);
        Trace trace = new Trace();
        fb.evaluate(trace);
        List<Trace.Breakpoint> bps = trace.accumulatedSet("y").orElseThrow().breakpoints();
        assertEquals(uy.length / 2, bps.size(), () -> "breakpoints " + bps);
        for (int i = 0; i < bps.size(); i++) {
            assertEquals(uy[2 * i], bps.get(i).u(), 1e-12, "u of breakpoint " + i);
            assertEquals(uy[2 * i + 1], bps.get(i).degree(), 1e-12, "degree of breakpoint " + i);
        }
    }

    /*
     * CoG of an asymmetric triangle (0,0)(10,1)(40,0) clipped at d=0.5 (ACT MIN): vertices
     * (0,0)(5,0.5)(25,0.5)(40,0). Pieces: area 1.25 centroid 10/3; area 10 centroid 15; area 3.75
     * centroid 30. Moment 25/6 + 150 + 225/2 = 800/3, area 15: CoG = 160/9.
     * ACT PROD, d=0.5: 0.5*T, CoG of the triangle = (0+10+40)/3 = 50/3.
     */
    @Test
    void centreOfGravityOfClippedAndScaledSets() throws EvaluationException {
        Fcl.Out out = Fcl.defuzzify("y", DefuzzificationMethod.COG).term("t", pts(0, 0, 10, 1, 40, 0))
                .term("u", pts(0, 0, 1, 1, 2, 0));
        Subconclusion t = then("y", "t");
        Subconclusion u = then("y", "u");
        assertEquals(160.0 / 9, run(program(out, ActivationMethod.MIN, AccumulationMethod.MAX, t, u), 0.5, 0),
                1e-12);
        assertEquals(50.0 / 3, run(program(out, ActivationMethod.PROD, AccumulationMethod.MAX, t, u), 0.5, 0),
                1e-12);
    }

    /*
     * CoA of the unclipped triangle (0,0)(10,1)(40,0): area 20. The area right of u in [10,40]
     * is (40-u)^2/60; it is 10 when (40-u)^2 = 600: u = 40 - sqrt(600).
     */
    @Test
    void centreOfAreaInClosedForm() throws EvaluationException {
        Fcl.Out out = Fcl.defuzzify("y", DefuzzificationMethod.COA).term("t", pts(0, 0, 10, 1, 40, 0))
                .term("u", pts(0, 0, 1, 1, 2, 0));
        assertEquals(40 - Math.sqrt(600), run(program(out, ActivationMethod.MIN, AccumulationMethod.MAX,
                then("y", "t"), then("y", "u")), 1, 0), 1e-12);
    }

    /*
     * Zero gap: A=(0,0)(5,1)(10,0) and B=(20,0)(22,1)(30,0), both fully activated; each has area 5.
     * Every u' in [10, 20] halves the area; CoA is the midpoint 15 (not 10 or 20).
     */
    @Test
    void centreOfAreaWithAZeroGapIsTheMidpointOfTheGap() throws EvaluationException {
        Fcl.Out out = Fcl.defuzzify("y", DefuzzificationMethod.COA).term("a", pts(0, 0, 5, 1, 10, 0))
                .term("b", pts(20, 0, 22, 1, 30, 0));
        assertEquals(15.0, run(program(out, ActivationMethod.MIN, AccumulationMethod.MAX,
                then("y", "a"), then("y", "b")), 1, 1), 1e-12);
    }

    /*
     * Plateau: T=(0,0)(10,1)(30,1)(40,0) clipped at 0.5 is 0.5 on [5, 35]: LM 5, RM 35
     * (the ends of the plateau; a mean of maxima would give 20).
     */
    @Test
    void leftmostAndRightmostMaximumAreThePlateauEnds() throws EvaluationException {
        for (DefuzzificationMethod m : new DefuzzificationMethod[] {DefuzzificationMethod.LM,
            DefuzzificationMethod.RM}) {
            Fcl.Out out = Fcl.defuzzify("y", m).term("t", pts(0, 0, 10, 1, 30, 1, 40, 0))
                    .term("u", pts(0, 0, 1, 1, 2, 0));
            double expected = m == DefuzzificationMethod.LM ? 5 : 35;
            assertEquals(expected, run(program(out, ActivationMethod.MIN, AccumulationMethod.MAX,
                    then("y", "t"), then("y", "u")), 0.5, 0), 1e-12, m.keyword());
        }
    }

    /*
     * A=(0,0)(10,1)(20,0), B=(10,0)(20,1)(30,0), both degree 1.
     * MAX: the envelope crosses at 15 (degree 0.5): (0,0)(10,1)(15,0.5)(20,1)(30,0); LM 10, RM 20,
     *   CoG 15 and CoA 15 by symmetry.
     * BSUM: on [10,20] A+B = 1 exactly: (0,0)(10,1)(20,1)(30,0); the plateau gives LM 10, RM 20.
     */
    @Test
    void maxEnvelopeCrossingAndBoundedSumPlateau() throws EvaluationException {
        Fcl.Out out = Fcl.defuzzify("y", DefuzzificationMethod.COG).term("a", pts(0, 0, 10, 1, 20, 0))
                .term("b", pts(10, 0, 20, 1, 30, 0));
        FunctionBlockInstance max = program(out, ActivationMethod.MIN, AccumulationMethod.MAX,
                then("y", "a"), then("y", "b"));
        assertBreakpoints(max, 1, 1, 0, 0, 10, 1, 15, 0.5, 20, 1, 30, 0);
        assertEquals(15.0, max.get("y"), 1e-12);
        FunctionBlockInstance bsum = program(out, ActivationMethod.MIN, AccumulationMethod.BSUM,
                then("y", "a"), then("y", "b"));
        assertBreakpoints(bsum, 1, 1, 0, 0, 10, 1, 20, 1, 30, 0);
    }

    /*
     * NSUM vs BSUM vs MAX. A = 1 on [0,20) (points (0,1)(20,1)(20,0)), B = 1 on (10,40]
     * (points (10,0)(10,1)(40,1)), RANGE 0..40, both rules at degree 0.6 (ACT MIN).
     * Sum: 0.6 on [0,10), 1.2 on (10,20), 0.6 on (20,40].
     * MAX: 0.6 everywhere -> CoG 20.
     * BSUM: 0.6, 1, 0.6 -> area 6+10+12 = 28, moment 6*5+10*15+12*30 = 540 -> 135/7.
     * NSUM: 0.5, 1, 0.5 (divided by the largest sum 1.2) -> area 5+10+10 = 25,
     *   moment 5*5+10*15+10*30 = 475 -> 19. (NSUM read as BSUM would give 135/7.)
     */
    @Test
    void normalisedSumIsNotBoundedSum() throws EvaluationException {
        Fcl.Out out = Fcl.defuzzify("y", DefuzzificationMethod.COG).range(0, 40)
                .term("a", pts(0, 1, 20, 1, 20, 0)).term("b", pts(10, 0, 10, 1, 40, 1));
        Subconclusion a = then("y", "a");
        Subconclusion b = then("y", "b");
        assertEquals(20.0, run(program(out, ActivationMethod.MIN, AccumulationMethod.MAX, a, b), 0.6, 0.6), 1e-12);
        assertEquals(135.0 / 7, run(program(out, ActivationMethod.MIN, AccumulationMethod.BSUM, a, b), 0.6, 0.6),
                1e-12);
        FunctionBlockInstance nsum = program(out, ActivationMethod.MIN, AccumulationMethod.NSUM, a, b);
        assertEquals(19.0, run(nsum, 0.6, 0.6), 1e-12);
        assertBreakpoints(nsum, 0.6, 0.6, 0, 0.5, 10, 0.5, 10, 1, 20, 1, 20, 0.5, 40, 0.5);
    }

    /*
     * RANGE limits every term to [lo, hi] and a term keeps its outer degree outside its points:
     * T=(10,0)(20,1) with RANGE 0..30, degree 1: 0 on [0,10], ramp to 1 at 20, 1 on [20,30].
     * Area 5 + 10 = 15; moment: ramp 5 * (10 + 2/3*10) = 250/3, plateau 10*25 = 250 -> 1000/3.
     * CoG = (1000/3)/15 = 200/9. RM = 30 (the plateau reaches the RANGE end).
     */
    @Test
    void rangeLimitsTermsThatKeepTheirOuterDegree() throws EvaluationException {
        Fcl.Out cog = Fcl.defuzzify("y", DefuzzificationMethod.COG).range(0, 30)
                .term("t", pts(10, 0, 20, 1)).term("u", pts(0, 1, 1, 0));
        assertEquals(200.0 / 9, run(program(cog, ActivationMethod.MIN, AccumulationMethod.MAX,
                then("y", "t"), then("y", "u")), 1, 0), 1e-12);
        Fcl.Out rm = Fcl.defuzzify("y", DefuzzificationMethod.RM).range(0, 30)
                .term("t", pts(10, 0, 20, 1)).term("u", pts(0, 1, 1, 0));
        assertEquals(30.0, run(program(rm, ActivationMethod.MIN, AccumulationMethod.MAX,
                then("y", "t"), then("y", "u")), 1, 0), 1e-12);
    }

    /*
     * Singletons: CoGS accumulates per term, not per rule. Both rules conclude "hi" (100) with
     * degrees 0.8 and 0.5; a third conclusion "lo" (0) has 0.5. MAX per term: hi = 0.8, lo = 0.5,
     * CoGS = 80/1.3 = 800/13. Summing every rule separately would give (80+50)/1.8 = 650/9.
     */
    @Test
    void centreOfGravityForSingletonsAccumulatesPerTerm() throws EvaluationException {
        FunctionBlockInstance fb = Fcl.block("fb").input("p").input("q").output("y")
                .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("lo", single(0))
                        .term("hi", single(100)))
                .rules(Fcl.ruleBlock("r").rule(is("p", "deg"), then("y", "hi"))
                        .rule(is("q", "deg"), then("y", "hi"), then("y", "lo")))
                .instance();
        assertEquals(800.0 / 13, run(fb, 0.8, 0.5), 1e-12);
    }

    /*
     * Singleton outputs: CoG = CoGS; LM/RM are the leftmost/rightmost singleton of maximal degree.
     * Terms a=-5, b=10, c=3: rule 1 gives a and b 0.7, rule 2 gives c 0.4.
     * CoG = (-3.5+7+1.2)/1.8 = 4.7/1.8; LM = -5; RM = 10. NSUM leaves CoGS unchanged (a factor).
     */
    @Test
    void singletonLeftmostRightmostAndCog() throws EvaluationException {
        for (DefuzzificationMethod m : new DefuzzificationMethod[] {DefuzzificationMethod.COG,
            DefuzzificationMethod.COGS, DefuzzificationMethod.LM, DefuzzificationMethod.RM}) {
            Fcl.Out out = Fcl.defuzzify("y", m).term("a", single(-5)).term("b", single(10)).term("c", single(3));
            FunctionBlockInstance fb = Fcl.block("fb").input("p").input("q").output("y")
                    .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                    .defuzzify(out)
                    .rules(Fcl.ruleBlock("r").accu(AccumulationMethod.NSUM)
                            .rule(is("p", "deg"), then("y", "a"), then("y", "b")).rule(is("q", "deg"), then("y", "c")))
                    .instance();
            double expected = switch (m) {
                case LM -> -5;
                case RM -> 10;
                default -> 4.7 / 1.8;
            };
            assertEquals(expected, run(fb, 0.7, 0.4), 1e-12, m.keyword());
        }
    }

    /*
     * A weight given by an input variable is clamped to [0, 1]: singleton "hi" (10) alone,
     * degree 0.5, WITH w. CoGS of a single singleton is 10 whatever its degree, so check the
     * trace's activated degree: w=0.4 -> 0.2; w=1.5 -> 0.5; w=-1 -> 0 and the DEFAULT (0) applies.
     */
    @Test
    void variableWeightIsClampedAndMultiplies() throws EvaluationException {
        Operand w = var("w");
        FunctionBlockInstance fb = Fcl.block("fb").input("p").input("w").output("y")
                .fuzzify("p", Fcl.term("deg", IDENTITY))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("hi", single(10)).defaultValue(-1))
                .rules(Fcl.ruleBlock("r").rule(is("p", "deg"), then("y", "hi", w)))
                .instance();
        double[][] cases = {{0.4, 0.2, 10}, {1.5, 0.5, 10}, {-1, 0, -1}};
        for (double[] c : cases) {
            fb.set("p", 0.5);
            fb.set("w", c[0]);
            Trace trace = new Trace();
            fb.evaluate(trace);
            assertEquals(c[1], trace.activations().get(0).activatedDegree(), 1e-15);
            assertEquals(c[2], fb.get("y"), 0.0);
        }
    }
}
