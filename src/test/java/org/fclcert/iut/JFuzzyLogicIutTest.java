package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;

/**
 * The jFuzzyLogic adapter against the real, unmodified jFuzzyLogic build (skipped when it is not there, failing
 * in CI), in its child JVM: the standard's own valve example, printed parse errors as rejections, a
 * NullPointerException and a stack overflow inside the library as crashes that do not end the session, a hang
 * cut by the timeout and followed by a fresh JVM.
 */
class JFuzzyLogicIutTest {
    private static final double EXACT = 1e-9;

    private static String valve() throws Exception {
        return Files.readString(Path.of("examples/valve.fcl"));
    }

    private static ImplementationUnderTest open() throws IutException {
        return Iuts.open(JFuzzyLogic.spec(), IutOptions.defaults().withTimeout(Duration.ofSeconds(20)));
    }

    private static double valve(ImplementationUnderTest iut, double temp, double pressure) throws IutException {
        return iut.eval(null, Map.of("temp", temp, "pressure", pressure)).get("valve");
    }

    @Test
    void theStandardsValveExampleLoadsAsWrittenAndGivesTheStandardsNumbers() throws Exception {
        try (ImplementationUnderTest iut = open()) {
            IutInfo info = iut.hello();
            assertEquals("jFuzzyLogic", info.name());
            assertEquals("3.3", info.version());
            assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(valve()));
            // clause 5.3 at temp 5, pressure 60: CoGS over MAX-accumulated singletons = 9500/127
            assertEquals(9500.0 / 127, valve(iut, 5, 60), EXACT);
            // temp 3, pressure 55: only rule 1 fires, inlet's 100
            assertEquals(100.0, valve(iut, 3, 55), EXACT);
            String exported = iut.export().orElseThrow();
            assertTrue(exported.contains("FUNCTION_BLOCK Fuzzy_FB"), exported);
        }
    }

    @Test
    void declaringOrAfterAndChangesTheAndAlgorithmToItsDeMorganPair() throws Exception {
        try (ImplementationUnderTest iut = open()) {
            iut.load(valve().replace("AND: MIN;", "AND: MIN;\n    OR: ASUM;"));
            // AND now PROD: R1 7/8·11/12 = 77/96, R2 11/12·1/8·0.8 = 11/120, R3 1/12·7/8 = 7/96, R4 1/96;
            // closed = max(11/120, 7/96) = 11/120; (100·77/96 − 100·1/96) / (77/96 + 11/120 + 1/96)
            //   = (7600/96) / (434/480) = 38000/434 ≈ 87.558 (the standard's MIN gives 9500/127 ≈ 74.803)
            assertEquals(38000.0 / 434, valve(iut, 5, 60), EXACT);
        }
    }

    @Test
    void aPrintedParseErrorIsARejectionAtItsLineThoughJFuzzyLogicStillReturnsASystem() throws Exception {
        try (ImplementationUnderTest iut = open()) {
            // the ';' after DEFAULT (line 23) missing: ANTLR reports it at the next token, line 24
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class,
                    iut.load(valve().replace("DEFAULT     := 0;", "DEFAULT     := 0")));
            assertTrue(rejected.message().contains("printed a parse error and still returned a system"), rejected.message());
            assertTrue(rejected.message().contains("missing SEMICOLON"), rejected.message());
            assertEquals(OptionalInt.of(24), rejected.line());
            assertThrows(IutException.class, () -> iut.eval(null, Map.of("temp", 5.0)), "nothing is loaded after a rejection");
        }
    }

    @Test
    void aNullPointerExceptionInsideJFuzzyLogicIsACrashAndTheSameJvmGoesOn() throws Exception {
        try (ImplementationUnderTest iut = open()) {
            // a bare input variable as a condition (Table 9's E-COND-VARIABLE) makes its tree walker dereference null
            String bare = valve().replace("IF temp IS cold AND pressure IS low", "IF temp");
            IutException crash = assertThrows(IutException.class, () -> iut.load(bare));
            assertEquals(Kind.CRASH, crash.kind());
            assertTrue(crash.getMessage().contains("NullPointerException"), crash.getMessage());
            assertTrue(crash.getMessage().contains("failed internally"), crash.getMessage());
            iut.load(valve());
            assertEquals(9500.0 / 127, valve(iut, 5, 60), EXACT);
        }
    }

    @Test
    void aStackOverflowOnDeepNestingIsACrashNotTheEndOfTheRun() throws Exception {
        String deep = "(".repeat(3000) + "temp IS cold" + ")".repeat(3000);
        try (ImplementationUnderTest iut = open()) {
            IutException crash = assertThrows(IutException.class,
                    () -> iut.load(valve().replace("IF temp IS cold AND pressure IS low", "IF " + deep)));
            assertEquals(Kind.CRASH, crash.kind());
            assertTrue(crash.getMessage().contains("StackOverflowError"), crash.getMessage());
            iut.load(valve());
            assertEquals(9500.0 / 127, valve(iut, 5, 60), EXACT);
        }
    }

    @Test
    void aHangIsKilledByTheTimeoutAndTheNextRequestGetsAFreshJvm() throws Exception {
        StringBuilder rules = new StringBuilder();
        for (int k = 1; k <= 200_000; k++) {
            rules.append("    RULE ").append(k).append(": IF temp IS cold THEN valve IS inlet;\n");
        }
        String huge = valve().replace("    RULE 1: IF temp IS cold AND pressure IS low THEN valve IS inlet;\n", rules.toString());
        // the first reply of a JVM gets 10 s whatever the timeout; loading 200,000 rules takes far longer than 1 s (40,000 did not, on a quiet machine),
        // while a fresh JVM's first small load (its classes loaded in the sandbox) needs more than 300 ms here
        try (ImplementationUnderTest iut = Iuts.open(JFuzzyLogic.spec(),
                IutOptions.defaults().withTimeout(Duration.ofMillis(1000)))) {
            iut.hello();
            IutException timeout = assertThrows(IutException.class, () -> iut.load(huge));
            assertEquals(Kind.TIMEOUT, timeout.kind());
            assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(valve()));
        }
    }

    @Test
    void namesAreMatchedInAnyLetterCaseAndInputsStartAtZero() throws Exception {
        try (ImplementationUnderTest iut = open()) {
            iut.load(valve());
            assertEquals(9500.0 / 127, iut.eval("FUZZY_FB", Map.of("TEMP", 5.0, "Pressure", 60.0)).get("valve"), EXACT);
            IutException unknown = assertThrows(IutException.class, () -> iut.eval(null, Map.of("humidity", 1.0)));
            assertEquals(Kind.EVAL_ERROR, unknown.kind());
            // after reset the inputs are at 0 again (jFuzzyLogic itself starts them at NaN; the adapter sets a REAL's
            // initial value): temp 0 and pressure 0 lie before the first points, cold = low = 1, hot = high = 0, so
            // only rule 1 fires and the valve is inlet's 100
            iut.reset();
            assertEquals(100.0, iut.eval(null, Map.of()).get("valve"), EXACT);
            // and an input set once keeps its value: temp 5 with pressure still 0 (low 1): R1 11/12 -> 100,
            // R3 min(1/12, 1) = 1/12 -> 0: (100·11/12) / (11/12 + 1/12) = 91.667
            assertEquals(1100.0 / 12, iut.eval(null, Map.of("temp", 5.0)).get("valve"), EXACT);
        }
    }

    @Test
    void aJarThatIsNotJFuzzyLogicIsAnInfraError() throws Exception {
        Path jar = Path.of(ChildJvm.location(org.fclcert.model.Names.class).orElseThrow());
        IutException e = assertThrows(IutException.class, () -> Iuts.open("jfuzzylogic:" + jar, IutOptions.defaults()));
        assertEquals(Kind.INFRA, e.kind());
        IutException missing = assertThrows(IutException.class, () -> Iuts.open("jfuzzylogic", IutOptions.defaults()));
        assertEquals(Kind.INFRA, missing.kind());
        assertTrue(missing.getMessage().contains("jfuzzylogic:PATH-TO-JAR"), missing.getMessage());
    }
}
