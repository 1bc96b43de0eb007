package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.Program;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Issue 18 item 9: a term whose points span more than the largest double (-1.0E308 to 1.0E308)
 * must not have its segment width overflow to infinity (which made every degree inside it 0).
 */
class HugeAbscissaTest {
    /* y = (d*1 + (1-d)*0) / (d + (1-d)) = d, the degree of x IS wide, on both evaluator paths. */
    private static final String PROGRAM = """
            FUNCTION_BLOCK huge
            VAR_INPUT x : LREAL; END_VAR
            VAR_OUTPUT y : LREAL; END_VAR
            FUZZIFY x
              TERM wide := (-1.0E308, 0) (1.0E308, 1);
            END_FUZZIFY
            DEFUZZIFY y
              TERM hi := 1;
              TERM lo := 0;
              METHOD : COGS;
              DEFAULT := -1;
            END_DEFUZZIFY
            RULEBLOCK r
              AND : MIN;
              ACCU : MAX;
              RULE 1 : IF x IS wide THEN y IS hi;
              RULE 2 : IF x IS NOT wide THEN y IS lo;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /* The line from (-1e308, 0) to (1e308, 1) is (x + 1e308) / 2e308: 0 -> 1/2, 5e307 -> 3/4, -5e307 -> 1/4. */
    @ParameterizedTest(name = "x = {0} -> degree {1}")
    @CsvSource({"0, 0.5", "5.0E307, 0.75", "-5.0E307, 0.25", "1.0E308, 1", "-1.0E308, 0"})
    void degreesInsideAnOverwideSegment(double x, double expected) throws EvaluationException {
        Program program = FclTextSemanticsTest.checked("huge.fcl", PROGRAM);
        FunctionBlockInstance reference = Evaluator.load(program).newInstance();
        reference.set("x", x);
        reference.evaluate();
        assertEquals(expected, reference.get("y"), 1e-15);

        FunctionBlockInstance byIndex = Evaluator.load(program).newInstance();
        byIndex.setInput(byIndex.inputIndex("x"), x);
        byIndex.evaluate();
        assertEquals(expected, byIndex.output(byIndex.outputIndex("y")), 1e-15);
    }
}
