package org.fclcert.plot;

import org.fclcert.check.Analysis;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;

/** Small programs whose pictures are known by hand. */
final class PlotPrograms {
    private PlotPrograms() {
    }

    /**
     * One input x on [0, 10] (low falls, high rises), singletons 0 and 10, CoGS: the degrees sum to 1 and
     * high's is x/10, so y = 10 * (x/10) = x. The transfer curve is the diagonal.
     */
    static final String DIAGONAL = """
            FUNCTION_BLOCK line
            VAR_INPUT x : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY x
                TERM low := (0, 1) (10, 0);
                TERM high := (0, 0) (10, 1);
            END_FUZZIFY
            DEFUZZIFY y
                TERM zero := 0;
                TERM ten := 10;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK r
                ACCU : MAX;
                RULE 1 : IF x IS low THEN y IS zero;
                RULE 2 : IF x IS high THEN y IS ten;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * Two inputs a, b on [0, 10]; each pulls y to 0 when low and 10 when high, accumulated with MAX:
     * ten = max(a, b)/10, zero = max(10 - a, 10 - b)/10, y = 10 ten / (ten + zero). So y is lowest at
     * (0, 0), highest at (10, 10), and exactly halfway where one input is high and the other low.
     */
    static final String TWO_INPUTS = """
            FUNCTION_BLOCK pair
            VAR_INPUT a : REAL; b : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY a
                TERM low := (0, 1) (10, 0);
                TERM high := (0, 0) (10, 1);
            END_FUZZIFY
            FUZZIFY b
                TERM low := (0, 1) (10, 0);
                TERM high := (0, 0) (10, 1);
            END_FUZZIFY
            DEFUZZIFY y
                TERM zero := 0;
                TERM ten := 10;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK r
                ACCU : MAX;
                RULE 1 : IF a IS low THEN y IS zero;
                RULE 2 : IF a IS high THEN y IS ten;
                RULE 3 : IF b IS low THEN y IS zero;
                RULE 4 : IF b IS high THEN y IS ten;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    static Program program(String text) {
        Analysis a = Analysis.analyze(new StrictReader(), "p.fcl", text);
        return a.program().orElseThrow(() -> new AssertionError(a.diagnostics().toString()));
    }
}
