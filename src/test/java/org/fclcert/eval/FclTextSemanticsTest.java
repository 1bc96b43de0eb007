package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.fclcert.check.Analysis;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/**
 * The evaluator on programs read from FCL text by the strict reader and passed by the checks:
 * the standard's own examples, and the readings that depend on how text becomes a model.
 */
class FclTextSemanticsTest {

    static Program checked(String name, String text) {
        Analysis a = Analysis.analyze(new StrictReader(), name, text);
        assertTrue(a.program().isPresent(), () -> "not a checked program: " + a.diagnostics());
        return a.program().get();
    }

    private static String resource(String path) throws IOException {
        try (InputStream in = FclTextSemanticsTest.class.getResourceAsStream(path)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /* Figure 7 as printed: temp=5, pressure=60 -> 9500/127 (derivation in ValveExampleTest). */
    @Test
    void figure7ValveFromText() throws Exception {
        FunctionBlockInstance fb = Evaluator.load(checked("figure7.fcl",
                resource("/org/fclcert/syntax/figure7_valve.fcl"))).newInstance();
        fb.set("temp", 5);
        fb.set("pressure", 60);
        fb.evaluate();
        assertEquals(9500.0 / 127, fb.get("valve"), 1e-12);
    }

    /*
     * Figure C.16 with rule 2's pos_big corrected to pos_high. distance=20, angle=-2:
     * far 5/6, medium 1/6, zero 0.6, neg_small 0.4 -> pos_medium 0.6, pos_high 0.4, neg_medium 1/6
     * -> (5.4 + 10.8 - 1.5)/(7/6) = 12.6 (derivation in ContainerCraneTest).
     */
    @Test
    void annexCCraneFromTextWithTheErratumCorrected() throws Exception {
        String text = resource("/org/fclcert/syntax/annexC_crane.fcl")
                .replace("THEN power IS pos_big;", "THEN power IS pos_high;");
        FunctionBlockInstance fb = Evaluator.load(checked("crane.fcl", text)).newInstance();
        fb.set("distance", 20);
        fb.set("angle", -2);
        fb.evaluate();
        assertEquals(12.6, fb.get("power"), 1e-12);
        fb.set("distance", 12);
        fb.set("angle", 4);
        fb.evaluate();
        assertEquals(9.0, fb.get("power"), 1e-12);
    }

    private static final String PRIORITY = """
            FUNCTION_BLOCK priority
            VAR_INPUT a: REAL; b: REAL; c: REAL; END_VAR
            VAR_OUTPUT y: REAL; END_VAR
            FUZZIFY a TERM hi := (0, 0) (1, 1); END_FUZZIFY
            FUZZIFY b TERM hi := (0, 0) (1, 1); END_FUZZIFY
            FUZZIFY c TERM hi := (0, 0) (1, 1); END_FUZZIFY
            DEFUZZIFY y
              TERM zero := 0; TERM ten := 10;
              METHOD: CoGS;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK r
              AND: MIN; OR: MAX; ACCU: MAX;
              RULE 1: IF a IS hi OR b IS hi AND c IS hi THEN y IS ten;
              RULE 2: IF NOT a IS hi AND b IS hi THEN y IS zero;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /*
     * Table 6 from source text, a=0.3, b=0.6, c=0.1.
     * Rule 1 "a OR b AND c" = max(0.3, min(0.6, 0.1)) = 0.3 (left to right would be 0.1).
     * Rule 2 "NOT a AND b" = min(1-0.3, 0.6) = 0.6 (NOT binds tighter than AND; NOT (a AND b)
     * would be 1 - 0.3 = 0.7).
     * CoGS = (10*0.3 + 0*0.6)/0.9 = 10/3.
     */
    @Test
    void operatorPriorityFromText() throws Exception {
        FunctionBlockInstance fb = Evaluator.load(checked("priority.fcl", PRIORITY)).newInstance();
        fb.set("a", 0.3);
        fb.set("b", 0.6);
        fb.set("c", 0.1);
        Trace trace = new Trace();
        fb.evaluate(trace);
        assertEquals(0.3, trace.ruleDegrees().get(0).degree(), 1e-15);
        assertEquals(0.6, trace.ruleDegrees().get(1).degree(), 1e-15);
        assertEquals(10.0 / 3, fb.get("y"), 1e-12);
    }
}
