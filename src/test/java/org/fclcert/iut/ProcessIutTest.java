package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;

/** Drives the Python fakes in src/test/resources/iut, each misbehaving in one way. */
class ProcessIutTest {
    private static final Path FAKES = Path.of("src/test/resources/iut").toAbsolutePath();
    private static final IutOptions FAST = IutOptions.defaults().withTimeout(Duration.ofMillis(3000));
    private static final String PROGRAM = "FUNCTION_BLOCK first\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK second\nEND_FUNCTION_BLOCK\n";

    static String fake(String script, String... args) {
        // quoted so that the splitter has real work to do (and a path with blanks would still work)
        return "process:python3 '" + FAKES.resolve(script) + "' " + String.join(" ", args);
    }

    private static ImplementationUnderTest open(IutOptions options, String script, String... args) throws IutException {
        return Iuts.open(fake(script, args), options);
    }

    private static Map<String, Double> inputs(double x, double y) {
        return Map.of("x", x, "y", y);
    }

    @Test
    void aWellBehavedIutAnswersEveryRequest() throws IutException {
        try (ImplementationUnderTest iut = open(FAST, "well_behaved.py")) {
            IutInfo info = iut.hello();
            assertEquals("fake", info.name());
            assertEquals("1.0", info.version());
            assertEquals(List.of("B-FB"), info.claims());
            assertEquals(Map.of("max-points-per-input-term", 3L), info.declaredLimits());
            assertTrue(info.command().startsWith("process:python3"));
            assertEquals(new LoadOutcome.Loaded(List.of("first", "second")), iut.load(PROGRAM));
            // the fake answers sum = x + y = 1.5 + 2.25
            assertEquals(3.75, iut.eval(null, inputs(1.5, 2.25)).get("sum"));
            iut.reset();
            assertEquals(Optional.empty(), iut.export());
        }
    }

    @Test
    void aCrashIsReportedWithTheStderrTailAndTheNextRequestRestartsTheProcess() throws IutException {
        try (ImplementationUnderTest iut = open(FAST, "crash_on_fifth_eval.py")) {
            iut.load(PROGRAM);
            for (int i = 1; i <= 4; i++) {
                assertEquals((double) i, iut.eval(null, inputs(1, 2)).get("evals"));
            }
            IutException crash = assertThrows(IutException.class, () -> iut.eval(null, inputs(1, 2)));
            assertEquals(Kind.CRASH, crash.kind());
            assertTrue(crash.getMessage().contains("exit code 3"), crash.getMessage());
            assertTrue(crash.stderrTail().contains("fatal: fifth evaluation"), crash.stderrTail());
            // a fresh process: its eval counter starts again at 1 (and the program was replayed)
            assertEquals(1.0, iut.eval(null, inputs(1, 2)).get("evals"));
        }
    }

    @Test
    void crashesThatAreNotInARowCostOnlyTheirRequestAndNeverGiveUp() throws IutException {
        // each process of crash_every.py 3 answers two requests and dies of SIGSEGV on its third
        try (ImplementationUnderTest iut = open(FAST.withRestartBudget(1), "crash_every.py", "3")) {
            int answered = 0;
            int crashed = 0;
            for (int i = 1; i <= 30; i++) {
                try {
                    // the eval counter of the process: 1 and 2, never more, since every third request kills it
                    assertEquals((double) (answered % 2 + 1), iut.eval(null, inputs(1, 2)).get("evals"));
                    answered++;
                } catch (IutException e) {
                    assertEquals(Kind.CRASH, e.kind(), e.getMessage());
                    assertEquals(0, i % 3, "request " + i + " crashed");
                    assertTrue(e.getMessage().contains("exit code 139: killed by signal 11 (SIGSEGV"), e.getMessage());
                    assertTrue(e.stderrTail().contains("about to crash on request 3"), e.stderrTail());
                    crashed++;
                }
            }
            assertEquals(20, answered);
            assertEquals(10, crashed);
            // ten crashes; nine restarts so far (the tenth is made by the next request)
            assertEquals(new IutHealth(10, 9), iut.health());
            assertEquals(1.0, iut.eval(null, inputs(1, 2)).get("evals"));
            assertEquals(new IutHealth(10, 10), iut.health());
        }
    }

    @Test
    void anIutThatBreaksDownOnEveryRequestIsGivenUpAfterItsRestartsInARow() throws IutException {
        try (ImplementationUnderTest iut = open(FAST.withRestartBudget(2), "crash_every.py", "1")) {
            iut.hello();
            for (int i = 0; i < 3; i++) {
                assertEquals(Kind.CRASH, assertThrows(IutException.class, () -> iut.eval(null, inputs(0, 0))).kind());
            }
            // three in a row is the budget of two restarts in a row used up: no fourth process is started
            IutException given = assertThrows(IutException.class, () -> iut.eval(null, inputs(0, 0)));
            assertEquals(Kind.GAVE_UP, given.kind());
            assertTrue(given.getMessage().contains("each of the last 3 requests crashed, hung or broke the protocol"),
                    given.getMessage());
            assertEquals(new IutHealth(3, 2), iut.health());
            assertEquals(Kind.GAVE_UP, assertThrows(IutException.class, iut::hello).kind());
        }
    }

    @Test
    void anIutWhoseHelloFailsThreeTimesInARowCannotBeStarted() throws IutException {
        try (ImplementationUnderTest iut = Iuts.open("process:python3 -c 'import sys; sys.exit(4)'",
                FAST.withRestartBudget(100))) {
            for (int i = 0; i < RestartPolicy.FAILED_STARTS; i++) {
                IutException e = assertThrows(IutException.class, iut::hello);
                assertEquals(Kind.CRASH, e.kind(), e.getMessage());
                assertTrue(e.getMessage().contains("exit code 4"), e.getMessage());
            }
            IutException given = assertThrows(IutException.class, () -> iut.load(PROGRAM));
            assertEquals(Kind.GAVE_UP, given.kind());
            assertTrue(given.getMessage().contains("it could not be started: 3 starts in a row failed their hello"),
                    given.getMessage());
        }
    }

    @Test
    void aHangIsCutAtTheTimeoutAndTheProcessTreeIsKilled() throws IutException {
        // without the sandbox: the child names its pid, which only outside a PID namespace is the host's
        IutOptions halfSecond = IutOptions.defaults().withTimeout(Duration.ofMillis(500))
                .withSandbox(org.fclcert.sandbox.SandboxSettings.none());
        try (ImplementationUnderTest iut = open(halfSecond, "hang_on_load.py")) {
            iut.hello();
            long start = System.nanoTime();
            IutException hang = assertThrows(IutException.class, () -> iut.load(PROGRAM));
            long millis = (System.nanoTime() - start) / 1_000_000;
            assertEquals(Kind.TIMEOUT, hang.kind());
            assertTrue(millis >= 500 && millis < 5000, "cut after " + millis + " ms");
            Matcher pid = Pattern.compile("child pid (\\d+)").matcher(hang.stderrTail());
            assertTrue(pid.find(), hang.stderrTail());
            long childPid = Long.parseLong(pid.group(1));
            assertFalse(runningAfter(childPid, 2000), "the IUT's child process " + childPid + " was left running");
            // the next request restarts it
            assertEquals("fake", iut.hello().name());
        }
    }

    /** Whether the process still runs after at most that wait (a killed process may take a moment to go). */
    static boolean runningAfter(long pid, long millis) {
        long until = System.nanoTime() + millis * 1_000_000;
        while (System.nanoTime() < until) {
            Optional<ProcessHandle> p = ProcessHandle.of(pid);
            if (p.isEmpty() || !p.get().isAlive()) {
                return false;
            }
            sleep(20);
        }
        return true;
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Test
    void nonJsonWrongIdsAndWrongShapesAreProtocolFaults() throws IutException {
        for (String mode : List.of("text", "wrong-id", "no-ok", "array", "trailing", "bad-shape")) {
            try (ImplementationUnderTest iut = open(FAST, "garbage.py", mode)) {
                assertEquals("fake", iut.hello().name());
                IutException e = assertThrows(IutException.class, () -> iut.eval(null, inputs(1, 1)), mode);
                assertEquals(Kind.PROTOCOL, e.kind(), mode + ": " + e.getMessage());
            }
        }
    }

    @Test
    void aReplyLongerThanTheCapIsAProtocolFaultDetectedWithoutReadingItAll() throws IutException {
        IutOptions smallCap = FAST.withMaxReplyBytes(64 * 1024);
        try (ImplementationUnderTest iut = open(smallCap, "huge_reply.py", "20000000")) {
            iut.load(PROGRAM);
            IutException e = assertThrows(IutException.class, () -> iut.eval(null, inputs(1, 1)));
            assertEquals(Kind.PROTOCOL, e.kind());
            assertTrue(e.getMessage().contains("longer than 65536 bytes"), e.getMessage());
        }
    }

    @Test
    void aReplyJustUnderTheCapIsAccepted() throws IutException {
        try (ImplementationUnderTest iut = open(FAST.withMaxReplyBytes(1024 * 1024), "huge_reply.py", "900000")) {
            assertEquals(4.0, iut.eval(null, inputs(1, 3)).get("sum"));
        }
    }

    @Test
    void stderrNoiseIsDrainedAndOnlyItsTailKept() throws IutException {
        IutOptions tail = FAST.withStderrTailBytes(100);
        try (ProcessIut iut = (ProcessIut) open(tail, "stderr_flood.py", "2000000")) {
            iut.load(PROGRAM);
            for (int i = 0; i < 3; i++) {
                assertEquals(5.0, iut.eval(null, inputs(2, 3)).get("sum"));
            }
            // the drainer runs on its own thread: give it a moment to reach the last line
            String kept = iut.stderrTail();
            for (int i = 0; i < 100 && !kept.endsWith("eval\n"); i++) {
                sleep(20);
                kept = iut.stderrTail();
            }
            assertTrue(kept.length() <= 100, "kept " + kept.length());
            assertTrue(kept.endsWith("last words before eval\n"), kept);
        }
    }

    @Test
    void anIutReportsItsPeakMemory() throws IutException {
        try (ImplementationUnderTest iut = open(FAST, "well_behaved.py")) {
            iut.hello();
            long bytes = iut.peakMemoryBytes().orElseThrow();
            // a Python interpreter needs a few MiB and certainly less than 1 GiB
            assertTrue(bytes > 1_000_000 && bytes < 1L << 30, bytes + " bytes");
        }
    }

    @Test
    void anIutThatStopsReadingCannotBlockALargeRequestPastTheTimeout() throws IutException {
        IutOptions halfSecond = FAST.withTimeout(Duration.ofMillis(500));
        try (ImplementationUnderTest iut = open(halfSecond, "deaf.py")) {
            assertEquals("deaf", iut.hello().name());
            // 4 MB is far more than a pipe buffers: writing it blocks until the process is killed
            String huge = "(*" + "x".repeat(4_000_000) + "*)\n" + PROGRAM;
            long start = System.nanoTime();
            assertEquals(Kind.TIMEOUT, assertThrows(IutException.class, () -> iut.load(huge)).kind());
            assertTrue((System.nanoTime() - start) / 1_000_000 < 5000);
        }
    }

    @Test
    void aSlowStartIsNotCutAtTheRequestTimeout() throws IutException {
        // the per-request timeout is 300 ms, the fake needs 1 s before it reads anything
        try (ImplementationUnderTest iut = open(FAST.withTimeout(Duration.ofMillis(300)), "slow_start.py")) {
            assertEquals("fake", iut.hello().name());
            assertEquals(new LoadOutcome.Loaded(List.of("first", "second")), iut.load(PROGRAM));
        }
    }

    @Test
    void aCommandThatCannotStartIsAnInfraError() {
        IutException e = assertThrows(IutException.class,
                () -> Iuts.open("process:/no/such/iut --flag", FAST).hello());
        assertEquals(Kind.INFRA, e.kind());
        assertTrue(e.getMessage().contains("/no/such/iut"), e.getMessage());
    }

    @Test
    void closeSaysByeAndEndsTheProcess() throws IutException {
        ImplementationUnderTest iut = open(FAST, "well_behaved.py");
        iut.hello();
        long start = System.nanoTime();
        iut.close();
        // a well-behaved IUT exits on bye at once; close must not wait out its full grace period
        assertTrue((System.nanoTime() - start) / 1_000_000 < 1000);
        iut.close();
    }
}
