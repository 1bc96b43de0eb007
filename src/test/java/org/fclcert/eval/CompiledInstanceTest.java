package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/**
 * {@link LoadedProgram#newCompiledInstance}: the compiled kernel from the first evaluation (the corpus's second
 * judgement relies on it), with the interpreter's results; a block the kernel does not cover stays interpreted.
 */
class CompiledInstanceTest {
    private static final String COVERED = """
            FUNCTION_BLOCK fb
            VAR_INPUT a : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY a
                TERM lo := (0, 1) (10, 0);
                TERM hi := (0, 0) (10, 1);
            END_FUZZIFY
            DEFUZZIFY y
                TERM down := 0;
                TERM up := 100;
                METHOD : CoGS;
                DEFAULT := -1;
            END_DEFUZZIFY
            RULEBLOCK rules
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF a IS hi THEN y IS up;
                RULE 2 : IF a IS lo THEN y IS down;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private static LoadedProgram load(String text) {
        Program program = new StrictReader().read("t.fcl", text).program().orElseThrow();
        return Evaluator.load(program);
    }

    @Test
    void takesTheKernelAtTheFirstEvaluation() throws EvaluationException {
        FunctionBlockInstance compiled = load(COVERED).newCompiledInstance(null);
        FunctionBlockInstance interpreted = load(COVERED).newInstance();
        for (double a : new double[] {3, 7.5, 10}) {
            compiled.setInput(0, a);
            interpreted.setInput(0, a);
            compiled.evaluate();
            interpreted.evaluate();
            // hi = a/10, lo = 1 - a/10: y = 100 * a/10 = 10 a
            assertEquals(10 * a, compiled.output(0), 1e-12);
            assertEquals(interpreted.output(0), compiled.output(0));
        }
        assertEquals(3, compiled.compiledEvaluations());
        assertEquals(0, interpreted.compiledEvaluations());
    }

    @Test
    void aBlockTheKernelDoesNotCoverStaysInterpreted() throws EvaluationException {
        // a bare conclusion (a local variable given the rule's degree) gets no kernel
        String bare = COVERED.replace("VAR_OUTPUT y : REAL; END_VAR", "VAR_OUTPUT y : REAL; END_VAR\nVAR w : REAL; END_VAR")
                .replace("RULE 2 : IF a IS lo THEN y IS down;", "RULE 2 : IF a IS lo THEN y IS down;\n    RULE 3 : IF a IS lo THEN w;");
        FunctionBlockInstance instance = load(bare).newCompiledInstance(null);
        instance.setInput(0, 3);
        instance.evaluate();
        assertEquals(30, instance.output(0), 1e-12);
        assertEquals(0, instance.compiledEvaluations());
    }
}
