package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The decision points of issue 12 (docs/semantics.md, points 5, 6, 8, 10): programs on which a tiny rounding
 * error flips a discrete choice. The exact path must give the value exact arithmetic on the literals (read as
 * the decimals written) and the inputs gives; the fast path, where its fix reaches, the same.
 */
class DecisionPointTest {

    private static LoadedProgram load(String text) {
        return Evaluator.load(FclTextSemanticsTest.checked("decision.fcl", text));
    }

    private static String program(String inputTerms, String outputBlock, String ruleBlock) {
        return "FUNCTION_BLOCK d\nVAR_INPUT x : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
                + "FUZZIFY x " + inputTerms + " END_FUZZIFY\n" + outputBlock + "\n" + ruleBlock + "\nEND_FUNCTION_BLOCK\n";
    }

    private static double exact(LoadedProgram p, double x) throws EvaluationException {
        ExactInstance fb = p.newExactInstance();
        fb.set("x", x);
        fb.evaluate();
        return fb.get("y");
    }

    private static double fast(LoadedProgram p, double x) throws EvaluationException {
        FunctionBlockInstance fb = p.newInstance();
        fb.set("x", x);
        fb.evaluate();
        return fb.get("y");
    }

    /*
     * x = 0.00000125 on up := (0,0)(1,1): degree L = 1.25e-6. ACT MIN clips t := (20.1,0)(20.2,1)(21,1) at L:
     * the clip crosses the rising segment where (u − 20.1)/0.1 = L, u = 20.1 + 0.1 · 1.25e-6 = 20.100000125,
     * and the set is L from there to 21. LM is the left end of that plateau: 20.100000125 exactly.
     */
    @Test
    void leftmostMaximumAtAClipCrossing() throws EvaluationException {
        LoadedProgram p = load(program("TERM up := (0, 0) (1, 1);",
                "DEFUZZIFY y RANGE := (20 .. 21); TERM t := (20.1, 0) (20.2, 1) (21, 1); METHOD : LM; DEFAULT := 0;"
                        + " END_DEFUZZIFY",
                "RULEBLOCK r AND : MIN; ACT : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS t; END_RULEBLOCK"));
        assertEquals(20.100000125, exact(p, 0.00000125));
        assertEquals(20.100000125, fast(p, 0.00000125), 1e-12);
    }

    /*
     * x = 1e-20 clips t := (0,0)(2,1)(10,0) at L = 1e-20: rising 0 → L on [0, 2L], flat L on [2L, 10 − 8L],
     * falling to 0 on [10 − 8L, 10]. Areas L², L(10 − 10L), 4L² with centroids 4L/3, 5 − 3L, 10 − 8L/3: CoG =
     * 5 − O(L), i.e. 5.0 to double precision (the error, about 1e-19, is far below the ulp of 5). Rounding the
     * crossing at 10 − 8e-20 onto 10 would make [2, 10] one falling line and give 3.444.
     */
    @Test
    void centreOfGravityWhenTheClipCrossingIsWithinAnUlpOfAPoint() throws EvaluationException {
        LoadedProgram p = load(program("TERM up := (0, 0) (1, 1);",
                "DEFUZZIFY y TERM t := (0, 0) (2, 1) (10, 0); METHOD : CoG; DEFAULT := 0; END_DEFUZZIFY",
                "RULEBLOCK r AND : MIN; ACT : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS t; END_RULEBLOCK"));
        assertEquals(5.0, exact(p, 1e-20));
        assertEquals(5.0, fast(p, 1e-20), 1e-12);
    }

    /*
     * x = 13: one = 1, up = 13/100. ASUM: 1 + 0.13 − 1 · 0.13 = 1 exactly, NOT gives 0: no rule fires, the
     * output is DEFAULT 35. In doubles (1 + 0.13) − 0.13 = 0.9999999999999999, NOT gives 1.1e-16 and the
     * singleton 10 would win.
     */
    @Test
    void notOfAnAlgebraicSumThatIsExactlyOne() throws EvaluationException {
        LoadedProgram p = load(program("TERM one := (0, 1) (100, 1); TERM up := (0, 0) (100, 1);",
                "DEFUZZIFY y TERM s := 10; METHOD : CoGS; DEFAULT := 35; END_DEFUZZIFY",
                "RULEBLOCK r OR : ASUM; ACCU : MAX; RULE 1 : IF NOT (x IS one OR x IS up) THEN y IS s; END_RULEBLOCK"));
        assertEquals(35.0, exact(p, 13));
        assertEquals(35.0, fast(p, 13));
    }

    /*
     * y : INT, singletons a := -10, b := -85, up := (0,0)(1,1), down := (0,1)(1,0), x = 0.3: degrees 0.3 and
     * 0.7, CoGS = (−10 · 0.3 − 85 · 0.7) / (0.3 + 0.7) = (−3 − 59.5) / 1 = −62.5, half away from zero: −63.
     * Plain doubles compute −62.49999999999999 and round it to −62: the vector is a knife edge for judging other
     * implementations (doubles miss the exact .5), which FairVectors reports; the reference's bound on the CoGS
     * cannot exclude .5, so it decides the rounding exactly: −63 (issue 24).
     */
    @Test
    void integerOutputExactlyHalfWayRoundsAwayFromZero() throws EvaluationException {
        String text = program("TERM up := (0, 0) (1, 1); TERM down := (0, 1) (1, 0);",
                "DEFUZZIFY y TERM a := -10; TERM b := -85; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY",
                "RULEBLOCK r AND : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS a; RULE 2 : IF x IS down THEN y IS b;"
                        + " END_RULEBLOCK").replace("y : REAL", "y : INT");
        LoadedProgram p = load(text);
        assertEquals(-63.0, exact(p, 0.3));
        assertEquals(-63.0, fast(p, 0.3));
        FunctionBlockInstance plain = p.newDoubleInstance(null);
        plain.set("x", 0.3);
        plain.evaluate();
        assertEquals(-62.0, plain.get("y"), "plain doubles: the knife edge FairVectors must see");
        FairVectors.Verdict v = FairVectors.judge(p, null, java.util.List.of(java.util.Map.of("x", 0.3)),
                FairVectors.DEFAULT_AGREEMENT);
        assertTrue(!v.fair() && v.knifeEdges().get(0).output().equals("y"), v.toString());
    }

    /*
     * Issue 24: y : INT with one singleton s := -62.5, fired at any degree d: CoGS = (−62.5 · d) / d = −62.5 exactly,
     * half away from zero: −63, for every input that fires the rule. x = 0.3, 0.7, 0.13, 0.55, 0.67, 1: d = x (up :=
     * (0,0)(1,1)); plain doubles give −62.49999999999999 at 0.55 and 0.67 (−62.5 · d / d), the reference −63. x = 0:
     * nothing fires, DEFAULT 0.
     */
    @Test
    void integerOutputOfOneSingletonAtAHalfIsAlwaysRoundedAwayFromZero() throws EvaluationException {
        LoadedProgram p = load(program("TERM up := (0, 0) (1, 1);",
                "DEFUZZIFY y TERM s := -62.5; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY",
                "RULEBLOCK r AND : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS s; END_RULEBLOCK")
                .replace("y : REAL", "y : INT"));
        for (double x : new double[] {0.3, 0.7, 0.13, 0.55, 0.67, 1}) {
            assertEquals(-63.0, exact(p, x), "x = " + x);
            assertEquals(-63.0, fast(p, x), "x = " + x);
        }
        assertEquals(0.0, fast(p, 0));
    }

    /*
     * DEFAULT := NC with a bare conclusion on the same output: RULE 1 : IF x IS up THEN y IS s, y. x = 0.5: the
     * bare y gets 0.5 at the end of the block, then defuzzification writes CoGS = 10. x = 0: nothing fires, the
     * bare y gets 0, and NC keeps the value y had when the evaluation began: 10 (semantics point 6).
     */
    @Test
    void noChangeKeepsTheValueOfThePreviousEvaluationDespiteABareConclusion() throws EvaluationException {
        LoadedProgram p = load(program("TERM up := (0, 0) (1, 1);",
                "DEFUZZIFY y TERM s := 10; METHOD : CoGS; DEFAULT := NC; END_DEFUZZIFY",
                "RULEBLOCK r AND : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS s, y; END_RULEBLOCK"));
        ExactInstance e = p.newExactInstance();
        FunctionBlockInstance f = p.newInstance();
        for (double[] step : new double[][] {{0.5, 10}, {0, 10}, {0, 10}, {1, 10}}) {
            e.set("x", step[0]);
            e.evaluate();
            f.set("x", step[0]);
            f.evaluate();
            assertEquals(step[1], e.get("y"));
            assertEquals(step[1], f.get("y"));
        }
    }

    private static final String VARIABLE_POINT = "FUNCTION_BLOCK v\nVAR_INPUT x : REAL; p : REAL; END_VAR\n"
            + "VAR_OUTPUT y : REAL; END_VAR\nFUZZIFY x TERM up := (0, 0) (1, 1); END_FUZZIFY\n"
            + "DEFUZZIFY y TERM t := (p, 0) (4, 1) (8, 0); METHOD : CoG; DEFAULT := 0; END_DEFUZZIFY\n"
            + "RULEBLOCK r AND : MIN; ACT : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS t; END_RULEBLOCK\n"
            + "END_FUNCTION_BLOCK\n";

    /*
     * TERM t := (p,0)(4,1)(8,0), no RANGE, x = 1 (level 1). p = 2: the triangle (2,0)(4,1)(8,0), CoG =
     * (2 + 4 + 8)/3 = 14/3. p = 6: re-sorted (4,1)(6,0)(8,0) — degree 1 at its first point, so it keeps degree 1
     * to the left without bound (5.2.2) and, without RANGE, has no centre: FCL-V006 on both paths (it used to be
     * cut at x = 4 and give 4.667).
     */
    @Test
    void variablePointsThatUnboundAnOutputWithoutRangeAreAnEvaluationError() throws EvaluationException {
        LoadedProgram p = Evaluator.load(FclTextSemanticsTest.checked("v.fcl", VARIABLE_POINT));
        ExactInstance e = p.newExactInstance();
        FunctionBlockInstance f = p.newInstance();
        e.set("x", 1);
        e.set("p", 2);
        e.evaluate();
        f.set("x", 1);
        f.set("p", 2);
        f.evaluate();
        assertEquals(14.0 / 3, e.get("y"));
        assertEquals(14.0 / 3, f.get("y"), 1e-12);
        e.set("p", 6);
        f.set("p", 6);
        assertEquals(EvaluationCode.UNBOUNDED.code(), assertThrows(EvaluationException.class, e::evaluate).code());
        assertEquals(EvaluationCode.UNBOUNDED.code(), assertThrows(EvaluationException.class, f::evaluate).code());
        // not fired (x = 0): nothing is unbounded, DEFAULT
        e.set("x", 0);
        f.set("x", 0);
        e.evaluate();
        f.evaluate();
        assertEquals(0.0, e.get("y"));
        assertEquals(0.0, f.get("y"));
    }
}
