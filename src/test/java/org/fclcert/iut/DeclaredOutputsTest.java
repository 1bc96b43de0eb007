package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class DeclaredOutputsTest {
    private static final String PROGRAM = String.join("\n",
            "(* VAR_OUTPUT ghost : REAL; END_VAR in a comment does not count *)",
            "function_block Tank",
            "var_input level : real; end_var",
            "VAR_OUTPUT",
            "  valve, Pump : REAL;   (* two at once *)",
            "  alarm : INT := 0;",
            "END_VAR",
            "VAR_OUTPUT RETAIN heater : REAL; END_VAR",
            "END_FUNCTION_BLOCK",
            "FUNCTION_BLOCK second",
            "VAR_OUTPUT out2 : REAL; END_VAR",
            "END_FUNCTION_BLOCK");

    @Test
    void theFirstBlocksOutputsInDeclarationOrderAsWritten() {
        assertEquals(List.of("valve", "Pump", "alarm", "heater"), DeclaredOutputs.of(PROGRAM, null));
    }

    @Test
    void aNamedBlockIsFoundInAnyLetterCase() {
        assertEquals(List.of("out2"), DeclaredOutputs.of(PROGRAM, "SECOND"));
        assertEquals(List.of("valve", "Pump", "alarm", "heater"), DeclaredOutputs.of(PROGRAM, "tank"));
    }

    @Test
    void anUnknownBlockOrUnreadableTextHasNoOutputs() {
        assertEquals(List.of(), DeclaredOutputs.of(PROGRAM, "missing"));
        assertEquals(List.of(), DeclaredOutputs.of("(* never closed FUNCTION_BLOCK x VAR_OUTPUT y", null));
    }
}
