package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/** Issue 18 item 9: two blocks whose names differ only in case; asking for that name picks neither. */
class AmbiguousBlockNameTest {
    private static String block(String name, int value) {
        return "FUNCTION_BLOCK " + name + "\nVAR_INPUT x : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
                + "FUZZIFY x TERM t := (0, 1) (1, 1); END_FUZZIFY\n"
                + "DEFUZZIFY y TERM c := " + value + "; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY\n"
                + "RULEBLOCK r ACCU : MAX; RULE 1 : IF x IS t THEN y IS c; END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
    }

    @Test
    void aNameMatchingTwoBlocksIsRefusedOnEveryPath() throws EvaluationException {
        Program program = new StrictReader().read("two.fcl", block("Fuzzy_FB", 1) + block("FUZZY_FB", 2))
                .program().orElseThrow();
        LoadedProgram loaded = Evaluator.load(program);
        String expected = "the function block name 'fuzzy_fb' is ambiguous: the program has both 'Fuzzy_FB' and"
                + " 'FUZZY_FB' (names are not case-sensitive)";
        assertEquals(expected, assertThrows(EvaluationException.class, () -> loaded.newInstance("fuzzy_fb")).getMessage());
        assertThrows(EvaluationException.class, () -> loaded.newDoubleInstance("FUZZY_FB"));
        assertThrows(EvaluationException.class, () -> loaded.newExactInstance("Fuzzy_FB", NumberReading.DECIMAL));

        Program distinct = new StrictReader().read("two.fcl", block("Fuzzy_FB", 1) + block("Other", 2))
                .program().orElseThrow();
        FunctionBlockInstance other = Evaluator.load(distinct).newInstance("OTHER");
        other.set("x", 0.5);
        other.evaluate();
        assertEquals(2.0, other.get("y"));
    }
}
