package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;

class ReferenceIutTest {
    private static final String VALVE = BasicIutExampleTest.VALVE;

    private static ImplementationUnderTest open() throws IutException {
        return Iuts.open("reference", IutOptions.defaults());
    }

    @Test
    void itClaimsEveryCatalogueFeature() throws IutException {
        try (ImplementationUnderTest iut = open()) {
            IutInfo info = iut.hello();
            assertEquals("reference", info.command());
            assertTrue(info.claims().containsAll(List.of("B-COGS", "E-OR-BSUM", "O-MANY-POINTS")), info.claims().toString());
        }
    }

    @Test
    void theValveExampleOfClause53() throws IutException {
        try (ImplementationUnderTest iut = open()) {
            assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(VALVE));
            // hand calculation in BasicIutExampleTest: 9500/127
            assertEquals(9500.0 / 127.0, iut.eval(null, Map.of("temp", 5.0, "pressure", 60.0)).get("valve"), 1e-12);
            // only rule 4 fires at (27, 95): drainage
            assertEquals(-100.0, iut.eval("fuzzy_fb", Map.of("TEMP", 27.0, "Pressure", 95.0)).get("valve"), 1e-12);
        }
    }

    /*
     * Issue 24, the two disagreements, through certify's reference implementation (they were 10 or 5.55e-16, and
     * -62). NOT (x IS one OR x IS up), OR : ASUM, one = 1 everywhere, x = 13: 1 + 0.13 - 0.13 = 1 exactly, NOT
     * gives 0, nothing fires: DEFAULT 35. y : INT with the single singleton -62.5 fired at degree 0.55: CoGS =
     * -62.5 exactly, half away from zero: -63.
     */
    @Test
    void theIssue24CasesGiveTheExactAnswer() throws IutException {
        String asum = "FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
                + "FUZZIFY x TERM one := (0, 1) (100, 1); TERM up := (0, 0) (100, 1); END_FUZZIFY\n"
                + "DEFUZZIFY y TERM s := 10; METHOD : CoGS; DEFAULT := 35; END_DEFUZZIFY\n"
                + "RULEBLOCK r OR : ASUM; ACCU : MAX; RULE 1 : IF NOT (x IS one OR x IS up) THEN y IS s; END_RULEBLOCK\n"
                + "END_FUNCTION_BLOCK\n";
        String half = "FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\nVAR_OUTPUT y : INT; END_VAR\n"
                + "FUZZIFY x TERM up := (0, 0) (1, 1); END_FUZZIFY\n"
                + "DEFUZZIFY y TERM s := -62.5; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY\n"
                + "RULEBLOCK r AND : MIN; ACCU : MAX; RULE 1 : IF x IS up THEN y IS s; END_RULEBLOCK\n"
                + "END_FUNCTION_BLOCK\n";
        try (ImplementationUnderTest iut = open()) {
            iut.load(asum);
            assertEquals(35.0, iut.eval(null, Map.of("x", 13.0)).get("y"));
            iut.load(asum.replace("METHOD : CoGS", "METHOD : LM"));
            assertEquals(35.0, iut.eval(null, Map.of("x", 13.0)).get("y"));
            iut.load(half);
            assertEquals(-63.0, iut.eval(null, Map.of("x", 0.55)).get("y"));
        }
    }

    @Test
    void anErrorIsARejectionWithItsCodeAndLine() throws IutException {
        try (ImplementationUnderTest iut = open()) {
            // line 30 is rule 4, which now names a term temp does not have
            LoadOutcome outcome = iut.load(VALVE.replace("temp IS hot AND pressure IS high", "temp IS warm AND pressure IS high"));
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, outcome);
            assertEquals(OptionalInt.of(30), rejected.line());
            assertTrue(rejected.message().startsWith("FCL-C002"), rejected.message());
            // a syntax error: the missing ';' is reported on the DEFAULT line (22) that lacks it
            LoadOutcome syntax = iut.load(VALVE.replace("DEFAULT     := 0;", "DEFAULT     := 0"));
            assertEquals(OptionalInt.of(22), assertInstanceOf(LoadOutcome.Rejected.class, syntax).line());
        }
    }

    private static final String NC = String.join("\n",
            "FUNCTION_BLOCK keep",
            "VAR_INPUT x : REAL; END_VAR",
            "VAR_OUTPUT y : REAL; END_VAR",
            "FUZZIFY x TERM low := (0, 1) (10, 0); END_FUZZIFY",
            "DEFUZZIFY y TERM a := 42; METHOD : CoGS; DEFAULT := NC; END_DEFUZZIFY",
            "RULEBLOCK r ACCU : MAX; RULE 1 : IF x IS low THEN y IS a; END_RULEBLOCK",
            "END_FUNCTION_BLOCK");

    @Test
    void statePersistsUntilReset() throws IutException {
        try (ImplementationUnderTest iut = open()) {
            iut.load(NC);
            // x = 5: low = 1/2, the only fired singleton is a -> 42
            assertEquals(42.0, iut.eval(null, Map.of("x", 5.0)).get("y"), 1e-12);
            // x = 20: low = 0, nothing fires -> NC keeps 42
            assertEquals(42.0, iut.eval(null, Map.of("x", 20.0)).get("y"), 1e-12);
            iut.reset();
            // a fresh instance: y still at its initial value 0
            assertEquals(0.0, iut.eval(null, Map.of("x", 20.0)).get("y"), 1e-12);
        }
    }

    @Test
    void theExportedTextLoadsAndEvaluatesAlike() throws IutException {
        try (ImplementationUnderTest iut = open()) {
            iut.load(VALVE);
            String exported = iut.export().orElseThrow();
            assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(exported));
            assertEquals(9500.0 / 127.0, iut.eval(null, Map.of("temp", 5.0, "pressure", 60.0)).get("valve"), 1e-12);
        }
    }

    @Test
    void evaluationProblemsAreEvalErrors() throws IutException {
        try (ImplementationUnderTest iut = open()) {
            assertEquals(Kind.EVAL_ERROR, assertThrows(IutException.class, () -> iut.eval(null, Map.of())).kind());
            iut.load(VALVE);
            IutException unknown = assertThrows(IutException.class, () -> iut.eval(null, Map.of("humidity", 1.0)));
            assertEquals(Kind.EVAL_ERROR, unknown.kind());
            assertTrue(unknown.getMessage().startsWith("FCL-V"), unknown.getMessage());
            assertEquals(Kind.EVAL_ERROR, assertThrows(IutException.class, () -> iut.eval("nope", Map.of())).kind());
        }
    }
}
