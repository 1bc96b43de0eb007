package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;

/**
 * The jfuzzylite adapter against the real jfuzzylite 6.0.1 (a test-scoped Maven dependency, so always present
 * here): found on the class path ({@code jfuzzylite}) and loaded from its jar ({@code jfuzzylite:JAR}); clean
 * rejections with their line, internal failures as crashes, a hang cut by the timeout. Expected values are
 * worked out by hand in {@link FuzzyliteIutTest} (jfuzzylite computes CoGS per rule as fuzzylite does).
 */
class JfuzzyliteIutTest {
    private static final double EXACT = 1e-9;

    /** One input x, one output y with a singleton; {@code term} replaces the input term's definition (line 9). */
    private static String small(String term) {
        return """
                FUNCTION_BLOCK small
                VAR_INPUT
                    x: REAL;
                END_VAR
                VAR_OUTPUT
                    y: REAL;
                END_VAR
                FUZZIFY x
                    TERM lo := %s;
                END_FUZZIFY
                DEFUZZIFY y
                    TERM one := 1;
                    ACCU : MAX;
                    METHOD : COGS;
                    DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    RULE 1 : if x is lo then y is one;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """.formatted(term);
    }

    private static ImplementationUnderTest open(String spec) throws IutException {
        return Iuts.open(spec, IutOptions.defaults().withTimeout(Duration.ofSeconds(20)));
    }

    /** The jar the test class path took jfuzzylite from (the local Maven repository's copy). */
    private static Path jar() throws ClassNotFoundException {
        return Path.of(ChildJvm.location(Class.forName("com.fuzzylite.Engine")).orElseThrow());
    }

    @Test
    void helloNamesJfuzzyliteWithTheVersionOfItsMavenArtifact() throws Exception {
        try (ImplementationUnderTest iut = open("jfuzzylite")) {
            IutInfo info = iut.hello();
            assertEquals("jfuzzylite", info.name());
            assertEquals("6.0.1", info.version(), "the jar's Maven version, not the library's constant 6.0");
            assertEquals("jfuzzylite", info.command());
        }
        try (ImplementationUnderTest iut = open("jfuzzylite:" + jar())) {
            assertEquals("6.0.1", iut.hello().version());
        }
    }

    @Test
    void theValveInFuzzylitesLayoutSumsEveryRuleSeparatelyUnderCogsAsFuzzyliteDoes() throws Exception {
        for (String spec : List.of("jfuzzylite", "jfuzzylite:" + jar())) {
            try (ImplementationUnderTest iut = open(spec)) {
                assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(FuzzyliteIutTest.VALVE_FUZZYLITE_LAYOUT));
                // 9500/137 per rule (FuzzyliteIutTest works it out); the standard gives 9500/127
                assertEquals(9500.0 / 137, iut.eval(null, Map.of("temp", 5.0, "pressure", 60.0)).get("valve"), EXACT, spec);
                // names in any letter case, as FCL's are
                assertEquals(-7000.0 / 143, iut.eval("FUZZY_FB", Map.of("TEMP", 20.0, "Pressure", 90.0)).get("valve"), EXACT);
            }
        }
    }

    @Test
    void theCorpusTextIsSentUnchangedAndRejectedCleanlyWithTheLineTheMessageQuotes() throws Exception {
        try (ImplementationUnderTest iut = open("jfuzzylite")) {
            // an initial value: jfuzzylite quotes the declaration, which is line 3
            String initial = FuzzyliteIutTest.VALVE_FUZZYLITE_LAYOUT.replace("temp: REAL;", "temp: REAL := 1.0;");
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, iut.load(initial));
            assertTrue(rejected.message().startsWith("jfuzzylite: [syntax error] expected property of type (key : value)"),
                    rejected.message());
            assertEquals(OptionalInt.of(3), rejected.line());
            // Table 1's spelling CoGS: "not registered", a message without a line
            String cogs = FuzzyliteIutTest.VALVE_FUZZYLITE_LAYOUT.replace("METHOD : COGS;", "METHOD : CoGS;");
            rejected = assertInstanceOf(LoadOutcome.Rejected.class, iut.load(cogs));
            assertTrue(rejected.message().contains("CoGS"), rejected.message());
            assertEquals(OptionalInt.empty(), rejected.line());
            // a number it cannot read is a rejection too (NumberFormatException), not a crash
            rejected = assertInstanceOf(LoadOutcome.Rejected.class, iut.load(small("(a, b)")));
            assertTrue(rejected.message().contains("cannot read a number"), rejected.message());
        }
    }

    @Test
    void aNullPointerExceptionInsideJfuzzyliteIsACrashNotARejectionAndTheSessionGoesOn() throws Exception {
        try (ImplementationUnderTest iut = open("jfuzzylite")) {
            // 'TERM lo := ;' makes jfuzzylite's own importer dereference a null term
            IutException crash = assertThrows(IutException.class, () -> iut.load(small("")));
            assertEquals(Kind.CRASH, crash.kind());
            assertTrue(crash.getMessage().contains("NullPointerException"), crash.getMessage());
            assertTrue(crash.getMessage().contains("failed internally"), crash.getMessage());
            // the next program loads and computes: lo(5) = 1/2 fires the singleton 1 alone
            assertInstanceOf(LoadOutcome.Loaded.class, iut.load(small("(0, 1) (10, 0)")));
            assertEquals(1.0, iut.eval(null, Map.of("x", 5.0)).get("y"), EXACT);
        }
    }

    @Test
    void aLoadThatHangsIsCutByTheTimeoutAndCountsAgainstTheRestartBudget() throws Exception {
        // 20,000 rules take jfuzzylite 55 ms to import once its code is hot, 300 ms cold (2026-12-05, an idle
        // machine): a 5 ms timeout cuts the load however warm the JVM is (100 ms did not, after the tests before it)
        StringBuilder rules = new StringBuilder();
        for (int k = 1; k <= 20_000; k++) {
            rules.append("    RULE ").append(k).append(" : if x is lo then y is one;\n");
        }
        String huge = small("(0, 1) (10, 0)").replace("    RULE 1 : if x is lo then y is one;\n", rules.toString());
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofMillis(5)).withRestartBudget(0);
        try (ImplementationUnderTest iut = Iuts.open("jfuzzylite", options)) {
            IutException timeout = assertThrows(IutException.class, () -> iut.load(huge));
            assertEquals(Kind.TIMEOUT, timeout.kind());
            IutException gaveUp = assertThrows(IutException.class, () -> iut.load(small("(0, 1) (10, 0)")));
            assertEquals(Kind.GAVE_UP, gaveUp.kind(), "a budget of 0 allows no abandoned call");
        }
    }

    @Test
    void onlyTheFirstFunctionBlockIsBuiltAndInputsStartAtZero() throws Exception {
        String two = small("(0, 1) (10, 0)") + small("(0, 1) (10, 0)").replace("FUNCTION_BLOCK small", "FUNCTION_BLOCK second");
        try (ImplementationUnderTest iut = open("jfuzzylite")) {
            assertEquals(new LoadOutcome.Loaded(List.of("small", "second")), iut.load(two));
            assertEquals(1.0, iut.eval("small", Map.of("x", 5.0)).get("y"), EXACT);
            IutException second = assertThrows(IutException.class, () -> iut.eval("second", Map.of("x", 5.0)));
            assertEquals(Kind.EVAL_ERROR, second.kind());
            assertTrue(second.getMessage().contains("builds only the first function block"), second.getMessage());
            // a fresh instance whose input was never set: jfuzzylite itself would leave x at NaN (nothing fires, y =
            // DEFAULT 0); the adapter starts it at 0, a REAL's initial value, where lo(0) = 1 fires the singleton 1
            iut.reset();
            assertEquals(1.0, iut.eval("small", Map.of()).get("y"), EXACT);
        }
    }

    @Test
    void itsOwnExportIsNotStrictFcl() throws Exception {
        try (ImplementationUnderTest iut = open("jfuzzylite")) {
            iut.load(small("(0, 1) (10, 0)"));
            String exported = iut.export().orElseThrow();
            assertTrue(exported.contains("FUNCTION_BLOCK small"), exported);
            assertTrue(exported.contains("RANGE := (nan .. nan)"), "jfuzzylite writes a RANGE of NaNs: " + exported);
            // the export check fails it, saying it is fuzzylite's dialect
            org.fclcert.harness.RunCase c = org.fclcert.harness.RunCases.from(org.fclcert.corpus.Corpus.load(
                    Path.of("src/test/resources/corpus-mini")).byId("B-DEFAULT-VALUE-001").orElseThrow());
            org.fclcert.harness.ExportCheck.Verdict v = new org.fclcert.harness.ReferenceExportCheck().check(exported, c);
            assertEquals(org.fclcert.harness.ExportStatus.FAILED, v.status());
            assertTrue(v.message().startsWith("the exported FCL does not read back: "), v.message());
            assertTrue(v.message().contains("written in the fuzzylite dialect, not standard FCL"), v.message());
        }
    }

    @Test
    void aJarThatIsNotThereIsAnInfraError() {
        IutException e = assertThrows(IutException.class, () -> Iuts.open("jfuzzylite:/no/such/jfuzzylite.jar",
                IutOptions.defaults()));
        assertEquals(Kind.INFRA, e.kind());
        assertTrue(e.getMessage().contains("does not exist"), e.getMessage());
    }
}
