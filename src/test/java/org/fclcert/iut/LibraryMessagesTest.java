package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.OptionalInt;
import org.junit.jupiter.api.Test;

/** The line heuristics, on messages as fuzzylite, jfuzzylite and jFuzzyLogic print them. */
class LibraryMessagesTest {
    private static final String PROGRAM = "FUNCTION_BLOCK f\nVAR_INPUT\n    x : REAL := 1.0;\nEND_VAR\nVAR\n";

    @Test
    void fuzzyliteNumbersQuotesAndJfuzzylitesAngleBrackets() {
        assertEquals(OptionalInt.of(24), LibraryMessages.fuzzyliteLine(
                "[syntax error] unknown block definition <function_block>  in line 24: function_block v", PROGRAM));
        assertEquals(OptionalInt.of(5), LibraryMessages.fuzzyliteLine(
                "[syntax error] unknown block definition <VAR> in line <5>: VAR", PROGRAM));
        // the quoted statement, semicolons dropped, is found in the program
        assertEquals(OptionalInt.of(3), LibraryMessages.fuzzyliteLine(
                "[syntax error] expected property of type (key : value) in line: x : REAL := 1.0", PROGRAM));
        assertEquals(OptionalInt.empty(), LibraryMessages.fuzzyliteLine(
                "[factory error] constructor of Defuzzifier <CoGS> not registered", PROGRAM));
    }

    @Test
    void antlrPositions() {
        assertEquals(OptionalInt.of(24), LibraryMessages.antlrLine("line 24:0 missing SEMICOLON at 'END_DEFUZZIFY'"));
        assertEquals(OptionalInt.empty(), LibraryMessages.antlrLine("Cannot find variable: 'h'"));
    }
}
