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
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The real FFLL 2.2.1 through fclcert's bridge ({@code --iut ffll}): what it loads, what it rejects, a crash in the
 * middle of a session that the session survives, and a hang cut by the timeout.
 *
 * <p>{@code lamp.fcl} (src/test/resources/iut/ffll, our own program in FFLL's layout): one input dusk on 0..10 with
 * triangles bright (-10, 0, 10) and dark (0, 10, 20), singletons off = 0 and full = 100; bright gives off, dark full.
 * By hand: at dusk = d, bright = 1 - d/10 and dark = d/10, so CoG of the singletons = 100 · (d/10) / 1 = 10·d: 0 at 0,
 * 50 at 5, 100 at 10, 25 at 2.5 (FFLL quantises the input on a grid, so 2.5 lands within a grid step of it).
 */
class FfllIutTest {
    private static final Path PROGRAMS = Path.of("src/test/resources/iut/ffll");
    private static final IutOptions OPTIONS = IutOptions.defaults().withTimeout(Duration.ofSeconds(3));
    private static String lamp;

    @BeforeAll
    static void program() throws Exception {
        Ffll.assumeLibrary();
        lamp = Files.readString(PROGRAMS.resolve("lamp.fcl"));
    }

    private static Map<String, Double> dusk(double d) {
        return Map.of("dusk", d);
    }

    @Test
    void loadsItsOwnLayoutAndEvaluatesByHand() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open("ffll", OPTIONS)) {
            IutInfo info = iut.hello();
            assertEquals("FFLL", info.name());
            assertTrue(info.version().startsWith("2.2.1"), info.version());
            assertEquals(new LoadOutcome.Loaded(List.of("lamp")), iut.load(lamp));
            assertEquals(50.0, iut.eval(null, dusk(5)).get("power"), 1e-9);
            assertEquals(0.0, iut.eval(null, dusk(0)).get("power"), 1e-9);
            assertEquals(100.0, iut.eval(null, dusk(10)).get("power"), 1e-9);
            double quarter = iut.eval("LAMP", Map.of("DUSK", 2.5)).get("power");
            assertEquals(25.0, quarter, 1.0, "within the quantisation of the input grid");
            IutException unknown = assertThrows(IutException.class, () -> iut.eval(null, Map.of("dawn", 1.0)));
            assertEquals(Kind.EVAL_ERROR, unknown.kind());
            // FFLL's own writer, read back by the bridge: its header and the parenthesised rules of its layout
            String exported = iut.export().orElseThrow();
            assertTrue(exported.startsWith("(* FCL File Created From FFLL Model"), exported);
            assertTrue(exported.contains("THEN (power IS full);"), exported);
        }
    }

    @Test
    void noDefaultWhenNoRuleFiredGivesTheSmallestPositiveFloat() throws Exception {
        String onlyDark = lamp.replace("\tRULE 0: IF (dusk IS bright) THEN (power IS off);\n", "");
        try (ImplementationUnderTest iut = Iuts.open("ffll", OPTIONS)) {
            iut.load(onlyDark);
            // at dusk 0 dark has degree 0: no rule fired, and FFLL answers FLT_MIN = 2^-126
            assertEquals(Math.pow(2, -126), iut.eval(null, dusk(0)).get("power"));
            assertEquals(100.0, iut.eval(null, dusk(10)).get("power"), 1e-9);
        }
    }

    @Test
    void aTermOfTwoPointsIsRejected() throws Exception {
        String twoPoints = lamp.replace("(0, 0) (10, 1) (20, 0)", "(0, 0) (10, 1)");
        try (ImplementationUnderTest iut = Iuts.open("ffll", OPTIONS)) {
            LoadOutcome outcome = iut.load(twoPoints);
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, outcome);
            assertTrue(rejected.message().contains("FFLL did not load the program"), rejected.message());
        }
    }

    @Test
    void aCrashInTheMiddleOfASessionCostsOnlyItsRequest() throws Exception {
        // blanks after the RULEBLOCK name: FFLL takes the rest of that line as the operator line and crashes
        String crashing = lamp.replace("RULEBLOCK lighting\n", "RULEBLOCK lighting   \n");
        try (ImplementationUnderTest iut = Iuts.open("ffll", OPTIONS)) {
            iut.load(lamp);
            assertEquals(50.0, iut.eval(null, dusk(5)).get("power"), 1e-9);
            IutException crash = assertThrows(IutException.class, () -> iut.load(crashing));
            assertEquals(Kind.CRASH, crash.kind());
            assertTrue(crash.getMessage().contains("killed by signal 11 (SIGSEGV"), crash.getMessage());
            assertEquals(new IutHealth(1, 0), iut.health());
            // the next request starts FFLL afresh
            iut.load(lamp);
            assertEquals(100.0, iut.eval(null, dusk(10)).get("power"), 1e-9);
            assertEquals(new IutHealth(1, 1), iut.health());
        }
    }

    @Test
    void aHangIsCutByTheTimeoutAndTheSessionGoesOn() throws Exception {
        // an operator line of 50 characters or more: FFLL reads it into a 50-byte buffer, its stream fails, and its
        // loop waiting for a non-empty line never ends
        String hanging = lamp.replace("\tAND:MIN;\n", "\tAND:MIN; (* this line is longer than fifty characters *)\n");
        try (ImplementationUnderTest iut = Iuts.open("ffll", IutOptions.defaults().withTimeout(Duration.ofSeconds(1)))) {
            iut.hello();
            IutException hang = assertThrows(IutException.class, () -> iut.load(hanging));
            assertEquals(Kind.TIMEOUT, hang.kind(), hang.getMessage());
            assertEquals(new LoadOutcome.Loaded(List.of("lamp")), iut.load(lamp));
            assertEquals(50.0, iut.eval(null, dusk(5)).get("power"), 1e-9);
            assertEquals(new IutHealth(1, 1), iut.health());
        }
    }

    @Test
    void aLibraryThatIsNotThereIsAClearError() {
        IutException e = assertThrows(IutException.class, () -> Iuts.open("ffll:/nonexistent/libffll.so", OPTIONS));
        assertEquals(Kind.INFRA, e.kind());
        assertTrue(e.getMessage().contains("no FFLL library at /nonexistent/libffll.so"), e.getMessage());
    }
}
