package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;

/** Reading fuzzylite's text output; the samples are what fuzzylite 6.0 printed on corpus cases. */
class FuzzyliteTextTest {
    private static final String PROGRAM = String.join("\n",
            "",
            "FUNCTION_BLOCK f",
            "VAR_INPUT x : REAL; END_VAR",
            "VAR_OUTPUT",
            "    y : REAL := 12.5;   (* initial *)",
            "END_VAR",
            "DEFUZZIFY y",
            "    METHOD: CoGS;",
            "    METHOD: CoGS;",
            "END_DEFUZZIFY");

    @Test
    void theLineIsTheNumberFuzzyliteGivesOrTheFirstLineReadingAsTheStatementItQuotes() {
        assertEquals(OptionalInt.of(24), FuzzyliteText.line(
                "[syntax error] unknown block definition <function_block>  in line 24: function_block Valve_Control", PROGRAM));
        // quoted without the semicolon: the first of two equal lines
        assertEquals(OptionalInt.of(8), FuzzyliteText.line(
                "[syntax error] unexpected token <METHOD:> in line: METHOD: CoGS", PROGRAM));
        // semicolons dropped and blanks collapsed, a comment kept
        assertEquals(OptionalInt.of(5), FuzzyliteText.line(
                "[syntax error] expected property of type (key : value) in line: y : REAL := 12.5 (* initial *)", PROGRAM));
        assertEquals(OptionalInt.of(3), FuzzyliteText.line(
                "[syntax error] expected <END_VAR> before <VAR_OUTPUT> in line: VAR_INPUT x : REAL END_VAR", PROGRAM));
        assertEquals(OptionalInt.empty(), FuzzyliteText.line(
                "[factory error] constructor of Defuzzifier <CoGS> not registered", PROGRAM));
        assertEquals(OptionalInt.empty(), FuzzyliteText.line("[syntax error] bad in line: nowhere to be found", PROGRAM));
    }

    @Test
    void theFirstMessageDropsFuzzylitesSourceLocation() {
        assertEquals("[syntax error] unexpected token <METHOD:> in line: METHOD: CoGS", FuzzyliteText.firstMessage(
                "\n[syntax error] unexpected token <METHOD:> in line: METHOD: CoGS\n{at ::processDefuzzify() [line:264]}\n\n"));
        assertEquals("", FuzzyliteText.firstMessage(" \n\n"));
    }

    @Test
    void versionEngineAndTablesAreRead() {
        assertEquals(Optional.of("6.0"), FuzzyliteText.version("====\nfuzzylite: a fuzzy logic control library\nversion: 6.0\n"));
        assertEquals(Optional.empty(), FuzzyliteText.version("usage: something else"));
        FuzzyliteText.Engine engine = FuzzyliteText.engine(String.join("\n", "Engine: Fuzzy_FB", "InputVariable: temp",
                "  enabled: true", "InputVariable: pressure", "OutputVariable: valve", "  default: 0.000",
                "RuleBlock: No1", "  rule: if temp is cold then valve is inlet"));
        assertEquals(new FuzzyliteText.Engine("Fuzzy_FB", List.of("temp", "pressure"), List.of("valve")), engine);

        FuzzyliteText.Table table = FuzzyliteText.table("a b\n1.50000000000000000 nan\n-inf -2\n");
        assertEquals(List.of("a", "b"), table.names());
        assertEquals(2, table.rows().size());
        assertEquals(1.5, table.rows().get(0)[0]);
        assertTrue(Double.isNaN(table.rows().get(0)[1]));
        assertEquals(Double.NEGATIVE_INFINITY, table.rows().get(1)[0]);
        assertTrue(Double.isNaN(FuzzyliteText.number("-nan")));
        IllegalArgumentException short1 = assertThrows(IllegalArgumentException.class, () -> FuzzyliteText.table("a b\n1\n"));
        assertEquals("row 1 has 1 values for 2 outputs: 1", short1.getMessage());
        assertThrows(IllegalArgumentException.class, () -> FuzzyliteText.table("a\nvalue\n"));
        assertThrows(IllegalArgumentException.class, () -> FuzzyliteText.table(""));
    }
}
