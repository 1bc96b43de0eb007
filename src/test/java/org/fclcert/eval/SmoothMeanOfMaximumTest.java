package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.check.Analysis;
import org.fclcert.syntax.dialect.JFuzzyLogicReader;
import org.junit.jupiter.api.Test;

/**
 * MoM on sets that are not piece-wise linear (SmoothSet), docs/semantics.md point 9: plateaus weigh by length,
 * otherwise isolated maxima count once each, as on point terms. Inputs p and q have deg := (0,0)(1,1), so the
 * value of p (q) is the degree of rule 1 (rule 2); the output's terms are Gaussians of sd 2 at 10 and 20.
 */
class SmoothMeanOfMaximumTest {
    private static FunctionBlockInstance block(String act, String bTerm) {
        String text = "FUNCTION_BLOCK m\nVAR_INPUT\n p : REAL;\n q : REAL;\nEND_VAR\nVAR_OUTPUT\n y : REAL;\nEND_VAR\n"
                + "FUZZIFY p\n TERM deg := (0, 0) (1, 1);\nEND_FUZZIFY\n"
                + "FUZZIFY q\n TERM deg := (0, 0) (1, 1);\nEND_FUZZIFY\n"
                + "DEFUZZIFY y\n RANGE := (0 .. 30);\n TERM a := gauss 10 2;\n TERM b := " + bTerm + ";\n"
                + " METHOD : MM;\n DEFAULT := -1;\nEND_DEFUZZIFY\n"
                + "RULEBLOCK r\n AND : MIN;\n ACT : " + act + ";\n ACCU : MAX;\n"
                + " RULE 1 : IF p IS deg THEN y IS a;\n RULE 2 : IF q IS deg THEN y IS b;\nEND_RULEBLOCK\n"
                + "END_FUNCTION_BLOCK\n";
        Analysis a = Analysis.analyze(new JFuzzyLogicReader(), "m.fcl", text);
        return Evaluator.load(a.program().orElseThrow(() -> new AssertionError(a.diagnostics()))).newInstance();
    }

    private static double run(FunctionBlockInstance fb, double p, double q) throws EvaluationException {
        fb.set("p", p);
        fb.set("q", q);
        fb.evaluate();
        return fb.get("y");
    }

    /*
     * MIN clips a at 0.5: the plateau is |u − 10| ≤ 2·√(2 ln 2) ≈ 2.355, midpoint 10 (b, clipped at 0.2, is
     * lower). Both clipped at 0.5: two plateaus of equal length, midpoints 10 and 20: MoM = 15. Nothing fired:
     * the DEFAULT.
     */
    @Test
    void clippedGaussiansArePlateaus() throws EvaluationException {
        FunctionBlockInstance fb = block("MIN", "gauss 20 2");
        assertEquals(10.0, run(fb, 0.5, 0.2), 1e-9);
        assertEquals(15.0, run(fb, 0.5, 0.5), 1e-9);
        assertEquals(-1.0, run(fb, 0, 0), 0.0);
    }

    /*
     * PROD keeps the peaks: one at 10 (degree 1) beats b's at 20 (degree 0.5): MoM = 10; both at degree 1: two
     * isolated maxima, mean 15. (b's tail at 10 is e^(−12.5) ≈ 4·10⁻⁶, far below the top.)
     */
    @Test
    void smoothPeaksAreIsolatedMaxima() throws EvaluationException {
        FunctionBlockInstance fb = block("PROD", "gauss 20 2");
        assertEquals(10.0, run(fb, 1, 0.5), 1e-6);
        assertEquals(15.0, run(fb, 1, 1), 1e-6);
    }

    /*
     * A plateau beats an isolated peak of the same height, as on point terms: b is a Gaussian product flat at 1
     * on [18, 24] (left shoulder mean 18, right shoulder mean 24); with a's peak at 10 also at 1 (PROD, p = 1),
     * the plateau [18, 24] alone decides: MoM = 21.
     */
    @Test
    void aPlateauOutweighsAPeak() throws EvaluationException {
        FunctionBlockInstance fb = block("PROD", "gauss2 18 1 24 1");
        assertEquals(21.0, run(fb, 1, 1), 1e-9);
        assertEquals(10.0, run(fb, 1, 0.5), 1e-6);
    }
}
