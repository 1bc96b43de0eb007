package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.Limits;
import org.junit.jupiter.api.Test;

/** Programs at the documented limits load and evaluate without deep recursion at run time. */
class LargeProgramTest {

    private static String program(String condition, String extraRules) {
        return """
                FUNCTION_BLOCK big
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM hi := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y
                    TERM zero := 0;
                    TERM ten := 10;
                    METHOD : CoGS;
                    DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : PROD;
                    ACCU : MAX;
                    RULE 1 : IF %s THEN y IS ten;
                    RULE 2 : IF x IS NOT hi THEN y IS zero;
                %s
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """.formatted(condition, extraRules);
    }

    /*
     * Parentheses nested to the limit around NOT: an even number of NOTs is the identity, so rule 1
     * has degree x = 0.25 and rule 2 0.75 -> CoGS = (10*0.25)/(0.25+0.75) = 2.5.
     */
    @Test
    void nestingAtTheLimit() throws EvaluationException {
        int depth = Limits.MAX_NESTING_DEPTH;
        StringBuilder c = new StringBuilder();
        for (int i = 0; i < depth; i++) {
            c.append("NOT (");
        }
        c.append("x IS hi");
        c.append(")".repeat(depth));
        String text = program(depth % 2 == 0 ? c.toString() : "NOT " + c, "");
        FunctionBlockInstance fb = Evaluator.load(FclTextSemanticsTest.checked("deep.fcl", text)).newInstance();
        fb.set("x", 0.25);
        fb.evaluate();
        assertEquals(2.5, fb.get("y"), 1e-12);
    }

    /*
     * An AND chain of 20 000 subconditions with PROD: x = 1 gives 1 (rule 2: 0) -> 10; x = 0.9999
     * gives 0.9999^20000 = e^(20000 ln 0.9999) = 0.1353...; with rule 2 at 0.0001:
     * CoGS = 10*p/(p + 0.0001). And 5 000 extra rules concluding zero with degree 1-x.
     */
    @Test
    void longChainsAndManyRules() throws EvaluationException {
        String chain = String.join(" AND ", java.util.Collections.nCopies(20_000, "x IS hi"));
        StringBuilder rules = new StringBuilder();
        for (int i = 3; i < 5_003; i++) {
            rules.append("    RULE ").append(i).append(" : IF x IS NOT hi THEN y IS zero;\n");
        }
        FunctionBlockInstance fb = Evaluator.load(FclTextSemanticsTest.checked("long.fcl",
                program(chain, rules.toString()))).newInstance();
        fb.set("x", 1);
        fb.evaluate();
        assertEquals(10.0, fb.get("y"), 0.0);
        fb.set("x", 0.9999);
        fb.evaluate();
        double p = Math.pow(0.9999, 20_000);
        assertEquals(10 * p / (p + 0.0001), fb.get("y"), 1e-9);
    }

    /*
     * An input term of 1 200 points (0 at even k, 1 at odd k): its degree code alone would exceed the class file's
     * 64 KiB per method, so the compiled kernel declines and the block stays interpreted. It used to fail at the
     * 65th evaluation ("the compiled kernel of block 'big' failed to load"). At x = k + 10.25 the degree is 0.25 for
     * even k + 10, 0.75 for odd; flat is 0.5, so y = 100 s / (s + 0.5): 100/3 or 60.
     */
    @Test
    void aTermTooLargeForTheKernelStaysInterpreted() throws EvaluationException {
        StringBuilder saw = new StringBuilder();
        for (int k = 0; k < 1200; k++) {
            saw.append(k == 0 ? "" : " ").append("(").append(k).append(", ").append(k % 2).append(")");
        }
        String text = """
                FUNCTION_BLOCK big
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM saw := %s; TERM flat := (0, 0.5) (1199, 0.5); END_FUZZIFY
                DEFUZZIFY y TERM lo := 0; TERM hi := 100; METHOD : CoGS; DEFAULT := -1; END_DEFUZZIFY
                RULEBLOCK r ACCU : MAX; RULE 1 : IF x IS saw THEN y IS hi; RULE 2 : IF x IS flat THEN y IS lo;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """.formatted(saw);
        LoadedProgram loaded = Evaluator.load(FclTextSemanticsTest.checked("big.fcl", text));
        FunctionBlockInstance fb = loaded.newInstance();
        for (int k = 0; k < 200; k++) {
            fb.setInputs(k + 10.25);
            fb.evaluate();
            double s = k % 2 == 0 ? 0.25 : 0.75;
            assertEquals(100 * s / (s + 0.5), fb.output(0), 1e-12, "step " + k);
        }
        assertEquals(0, fb.compiledEvaluations(), "no kernel");
        // from its first evaluation as well (the corpus's mutation test takes the kernel that way)
        FunctionBlockInstance compiled = loaded.newCompiledInstance("big");
        compiled.setInputs(10.25);
        compiled.evaluate();
        assertEquals(100 / 3.0, compiled.output(0), 1e-12);
    }
}
