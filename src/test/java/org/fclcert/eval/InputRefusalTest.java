package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * Setting an input is refused the same way by the reference and by the exact path (one check, in {@link BlockPlan}):
 * a name the block does not declare, a variable that is not a VAR_INPUT, a value that is not a finite number.
 */
class InputRefusalTest {
    private static final String FB = "FUNCTION_BLOCK Fb\nVAR_INPUT Speed : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
            + "FUZZIFY Speed TERM t := (0, 1) (10, 0); END_FUZZIFY\n"
            + "DEFUZZIFY y TERM c := 4; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY\n"
            + "RULEBLOCK r ACCU : MAX; RULE 1 : IF Speed IS t THEN y IS c; END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";

    private static void refused(EvaluationCode code, String message, Executable set) {
        EvaluationException e = assertThrows(EvaluationException.class, set);
        assertEquals(code, e.diagnosticCode());
        assertEquals(message, e.getMessage());
    }

    @Test
    void bothInstancesRefuseTheSameInputsWithTheSameWords() throws EvaluationException {
        Program program = new StrictReader().read("fb.fcl", FB).program().orElseThrow();
        LoadedProgram loaded = Evaluator.load(program);
        FunctionBlockInstance reference = loaded.newInstance();
        ExactInstance exact = loaded.newExactInstance();

        refused(EvaluationCode.UNKNOWN_NAME, "function block 'Fb' has no variable 'speeds'",
                () -> reference.set("speeds", 1));
        refused(EvaluationCode.UNKNOWN_NAME, "function block 'Fb' has no variable 'speeds'",
                () -> exact.set("speeds", 1));
        refused(EvaluationCode.NOT_AN_INPUT, "'y' is not a VAR_INPUT and cannot be set", () -> reference.set("y", 1));
        refused(EvaluationCode.NOT_AN_INPUT, "'y' is not a VAR_INPUT and cannot be set", () -> exact.set("Y", 1));
        refused(EvaluationCode.NOT_FINITE, "input 'Speed' must be a finite number, not NaN",
                () -> reference.set("speed", Double.NaN));
        refused(EvaluationCode.NOT_FINITE, "input 'Speed' must be a finite number, not Infinity",
                () -> exact.set("SPEED", Double.POSITIVE_INFINITY));
        refused(EvaluationCode.NOT_FINITE, "input 'Speed' must be a finite number, not -Infinity",
                () -> reference.setInput(0, Double.NEGATIVE_INFINITY));
        refused(EvaluationCode.NOT_FINITE, "input 'Speed' must be a finite number, not NaN",
                () -> reference.setInputs(Double.NaN));

        // the name in any case reaches the input: degree of t at 2.5 is 0.75, so y is the singleton's 4
        reference.set("SPEED", 2.5);
        reference.evaluate();
        exact.set("speed", 2.5);
        exact.evaluate();
        assertEquals(4.0, reference.get("y"));
        assertEquals(4.0, exact.get("y"));
    }
}
