package org.fclcert.eval;

import static org.fclcert.eval.Fcl.and;
import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.isNot;
import static org.fclcert.eval.Fcl.not;
import static org.fclcert.eval.Fcl.num;
import static org.fclcert.eval.Fcl.or;
import static org.fclcert.eval.Fcl.paren;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.ptsOf;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;
import static org.fclcert.eval.Fcl.v;
import static org.fclcert.eval.Fcl.var;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.OrAlgorithm;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Semantics points 1 (fuzzification, 5.2.2) and 2 (aggregation, 5.2.4, Tables 3 and 6). */
class FuzzificationAndAggregationTest {

    /** One input x with one term t, a dummy output; the trace gives the degree of x IS t. */
    private static double degree(MembershipFunction t, double x) throws EvaluationException {
        FunctionBlockInstance fb = Fcl.block("fb").input("x").input("a").input("b").output("y")
                .fuzzify("x", Fcl.term("t", t))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("one", single(1)))
                .rules(Fcl.ruleBlock("r").rule(is("x", "t"), then("y", "one")))
                .instance();
        fb.set("x", x);
        Trace trace = new Trace();
        fb.evaluate(trace);
        return trace.termDegree("x", "t").orElseThrow();
    }

    /*
     * Triangle (0,0)(10,1)(20,0): 2.5 -> 2.5/10 = 0.25; 15 -> (20-15)/10 = 0.5; beyond the outer
     * points the outer degrees (0) hold. Ramp (0,0.2)(10,0.8): 5 -> 0.2+0.6*0.5 = 0.5; below the
     * first point 0.2, above the last 0.8 (not 0: the outer degree is kept, 5.2.2).
     */
    @ParameterizedTest(name = "triangle at {0} = {1}")
    @CsvSource({"-5, 0", "0, 0", "2.5, 0.25", "10, 1", "15, 0.5", "20, 0", "25, 0"})
    void triangleInterpolatesLinearly(double x, double expected) throws EvaluationException {
        assertEquals(expected, degree(pts(0, 0, 10, 1, 20, 0), x), 1e-15);
    }

    @ParameterizedTest(name = "ramp at {0} = {1}")
    @CsvSource({"-100, 0.2", "0, 0.2", "5, 0.5", "10, 0.8", "1e6, 0.8"})
    void outerDegreesHoldBeyondTheOuterPoints(double x, double expected) throws EvaluationException {
        assertEquals(expected, degree(pts(0, 0.2, 10, 0.8), x), 1e-15);
    }

    /*
     * (0,0)(5,0)(5,1)(5,0.3)(10,0.3): at exactly 5 three points share x; the degree there is the
     * largest, 1. Left of 5 the segment (0,0)-(5,0) gives 0; right of 5 the segment (5,0.3)-(10,0.3).
     */
    @ParameterizedTest(name = "shared x at {0} = {1}")
    @CsvSource({"4.999, 0", "5, 1", "5.001, 0.3", "7.5, 0.3"})
    void sharedAbscissaTakesTheLargestDegree(double x, double expected) throws EvaluationException {
        assertEquals(expected, degree(pts(0, 0, 5, 0, 5, 1, 5, 0.3, 10, 0.3), x), 1e-15);
    }

    /** An input singleton term: degree 1 exactly at its value, 0 anywhere else. */
    @ParameterizedTest(name = "singleton 5 at {0} = {1}")
    @CsvSource({"5, 1", "5.000000001, 0", "4.999999999, 0", "-5, 0"})
    void inputSingletonIsOneOnlyAtItsValue(double x, double expected) throws EvaluationException {
        assertEquals(expected, degree(single(5), x), 0.0);
    }

    /*
     * TERM warm := (a, 0) (21, 1) (b, 0) with a=25, b=17 at run time: the points are sorted by x,
     * giving (17,0)(21,1)(25,0) (5.2.2 NOTE). At 19: (19-17)/4 = 0.5; at 23: (25-23)/4 = 0.5.
     * Read in the written order instead, 19 would fall below the first point (25) and give 0.
     */
    @Test
    void variablePointsOutOfSequenceAreSorted() throws EvaluationException {
        MembershipFunction warm = ptsOf(var("a"), num(0), num(21), num(1), var("b"), num(0));
        FunctionBlockInstance fb = Fcl.block("fb").input("x").input("a").input("b").output("y")
                .fuzzify("x", Fcl.term("warm", warm))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("one", single(1)))
                .rules(Fcl.ruleBlock("r").rule(is("x", "warm"), then("y", "one")))
                .instance();
        fb.set("a", 25);
        fb.set("b", 17);
        Trace trace = new Trace();
        fb.set("x", 19);
        fb.evaluate(trace);
        assertEquals(0.5, trace.termDegree("x", "warm").orElseThrow(), 1e-15);
        fb.set("x", 23);
        fb.evaluate(trace);
        assertEquals(0.5, trace.termDegree("x", "warm").orElseThrow(), 1e-15);
    }

    @Test
    void nanAndInfiniteInputsAreEvaluationErrors() {
        FunctionBlockInstance fb = ValveExampleTest.valve().instance();
        EvaluationException nan = assertThrows(EvaluationException.class, () -> fb.set("temp", Double.NaN));
        assertEquals("FCL-V002", nan.code());
        EvaluationException inf = assertThrows(EvaluationException.class,
                () -> fb.set("pressure", Double.POSITIVE_INFINITY));
        assertEquals("FCL-V002", inf.code());
    }

    /**
     * Inputs a, b, c each with term "hi" := (0,0)(1,1), so the degree of {@code a IS hi} is a.
     * Returns the degree of the condition (the first rule's aggregation).
     */
    private static double condition(Condition c, AndAlgorithm andAlg, OrAlgorithm orAlg, double a, double b,
            double c3) throws EvaluationException {
        Fcl.Rules rules = Fcl.ruleBlock("r").rule(c, then("y", "one"));
        if (andAlg != null) {
            rules.and(andAlg);
        }
        if (orAlg != null) {
            rules.or(orAlg);
        }
        FunctionBlockInstance fb = Fcl.block("fb").input("a").input("b").input("c").output("y")
                .fuzzify("a", Fcl.term("hi", pts(0, 0, 1, 1)))
                .fuzzify("b", Fcl.term("hi", pts(0, 0, 1, 1)))
                .fuzzify("c", Fcl.term("hi", pts(0, 0, 1, 1)))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("one", single(1)))
                .rules(rules).instance();
        fb.set("a", a);
        fb.set("b", b);
        fb.set("c", c3);
        Trace trace = new Trace();
        fb.evaluate(trace);
        return trace.ruleDegrees().get(0).degree();
    }

    private static final Condition A_AND_B = and(is("a", "hi"), is("b", "hi"));
    private static final Condition A_OR_B = or(is("a", "hi"), is("b", "hi"));

    /*
     * Table 3 with a=0.3, b=0.6: MIN 0.3; PROD 0.18; BDIF max(0, 0.9-1) = 0; with a=0.7: BDIF 0.3.
     * OR: MAX 0.6; ASUM 0.3+0.6-0.18 = 0.72; BSUM min(1, 0.9) = 0.9; with a=0.7: BSUM 1.
     */
    @Test
    void table3Algorithms() throws EvaluationException {
        assertEquals(0.3, condition(A_AND_B, AndAlgorithm.MIN, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.18, condition(A_AND_B, AndAlgorithm.PROD, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.0, condition(A_AND_B, AndAlgorithm.BDIF, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.3, condition(A_AND_B, AndAlgorithm.BDIF, null, 0.7, 0.6, 0), 1e-15);
        assertEquals(0.6, condition(A_OR_B, null, OrAlgorithm.MAX, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.72, condition(A_OR_B, null, OrAlgorithm.ASUM, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.9, condition(A_OR_B, null, OrAlgorithm.BSUM, 0.3, 0.6, 0), 1e-15);
        assertEquals(1.0, condition(A_OR_B, null, OrAlgorithm.BSUM, 0.7, 0.6, 0), 1e-15);
    }

    /*
     * Only one of AND/OR declared: the other is its Table 3 pair (not MIN/MAX, not left over from
     * somewhere else). OR ASUM declared -> AND is PROD: 0.3*0.6 = 0.18. AND PROD -> OR ASUM 0.72.
     * AND BDIF -> OR BSUM: min(1, 0.3+0.6) = 0.9.
     */
    @Test
    void undeclaredOperatorIsThePairOfTheDeclaredOne() throws EvaluationException {
        assertEquals(0.18, condition(A_AND_B, null, OrAlgorithm.ASUM, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.72, condition(A_OR_B, AndAlgorithm.PROD, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.9, condition(A_OR_B, AndAlgorithm.BDIF, null, 0.3, 0.6, 0), 1e-15);
    }

    /*
     * NOT a = 1 - a; a IS NOT hi = 1 - 0.3 = 0.7; NOT (a IS hi AND b IS hi) = 1 - 0.3 = 0.7.
     * n-ary chains fold left to right: a AND b AND c with PROD = 0.3*0.6*0.5 = 0.09.
     */
    @Test
    void negationAndChains() throws EvaluationException {
        assertEquals(0.7, condition(not(is("a", "hi")), AndAlgorithm.MIN, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.7, condition(isNot("a", "hi"), AndAlgorithm.MIN, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.7, condition(not(paren(A_AND_B)), AndAlgorithm.MIN, null, 0.3, 0.6, 0), 1e-15);
        assertEquals(0.09, condition(and(is("a", "hi"), is("b", "hi"), is("c", "hi")), AndAlgorithm.PROD, null,
                0.3, 0.6, 0.5), 1e-15);
    }

    /*
     * Table 6, AND before OR: "a OR b AND c" is a OR (b AND c). a=0.3, b=0.6, c=0.1, MIN/MAX:
     * max(0.3, min(0.6, 0.1)) = 0.3. Left to right with equal priority would give
     * min(max(0.3, 0.6), 0.1) = 0.1. (The reader resolves priority; this pins the tree the model
     * holds; FclTextSemanticsTest pins it from source text.)
     */
    @Test
    void andBindsTighterThanOr() throws EvaluationException {
        Condition c = or(is("a", "hi"), and(is("b", "hi"), is("c", "hi")));
        assertEquals(0.3, condition(c, AndAlgorithm.MIN, null, 0.3, 0.6, 0.1), 1e-15);
        Condition grouped = and(paren(or(is("a", "hi"), is("b", "hi"))), is("c", "hi"));
        assertEquals(0.1, condition(grouped, AndAlgorithm.MIN, null, 0.3, 0.6, 0.1), 1e-15);
    }

    /** A bare input variable in a condition contributes its value clamped to [0, 1]. */
    @ParameterizedTest(name = "variable {0} -> {1}")
    @CsvSource({"0.4, 0.4", "1.7, 1", "-0.5, 0", "0, 0", "1, 1"})
    void bareVariableConditionIsClamped(double value, double expected) throws EvaluationException {
        assertEquals(expected, condition(v("c"), AndAlgorithm.MIN, null, 0, 0, value), 1e-15);
    }
}
