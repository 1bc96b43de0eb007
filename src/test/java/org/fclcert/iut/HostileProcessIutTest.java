package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Map;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;

/** {@link ProcessIut} against {@code hostile.py}: faults that must not cost a restart, and what is kept of its text. */
class HostileProcessIutTest {
    private static final IutOptions NO_RESTARTS = IutOptions.defaults().withTimeout(Duration.ofMillis(3000))
            .withRestartBudget(0);
    private static final String PROGRAM = "FUNCTION_BLOCK f\nEND_FUNCTION_BLOCK\n";

    @Test
    void anExportReplyWithoutFclIsAFaultOfThatReplyNotOfTheProcess() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open(ProcessIutTest.fake("hostile.py", "no-fcl-export"), NO_RESTARTS)) {
            iut.load(PROGRAM);
            for (int i = 0; i < 3; i++) {
                IutException e = assertThrows(IutException.class, iut::export);
                assertEquals(Kind.PROTOCOL, e.kind(), e.getMessage());
                assertEquals("the reply to 'export' has no text field 'fcl'", e.getMessage());
            }
            // still the first process: with a restart budget of 0 a restart would have given up
            assertEquals(Map.of("sum", 3.0, "evals", 1.0), iut.eval(null, Map.of("a", 1.0, "b", 2.0)));
        }
    }

    @Test
    void aChildThatOutlivesTheIutAndKeepsItsStdoutIsKilledToo(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path pids = dir.resolve("pids");
        // without the sandbox: the test reads the host pids the children write (the sandbox's PID namespace ends
        // them all anyway, SandboxedRunTest)
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofMillis(1000)).withRestartBudget(1)
                .withSandbox(org.fclcert.sandbox.SandboxSettings.none());
        try (ImplementationUnderTest iut = Iuts.open(ProcessIutTest.fake("hostile.py", "orphan", pids.toString()),
                options)) {
            iut.load(PROGRAM);
            // the IUT exits, its child holds stdout open: no end of stream, so a timeout; then a restart (a second
            // child) and the same again
            for (int i = 0; i < 2; i++) {
                IutException e = assertThrows(IutException.class, () -> iut.eval(null, Map.of("a", 1.0)));
                assertEquals(Kind.TIMEOUT, e.kind(), e.getMessage());
            }
        }
        java.util.List<Long> children = java.nio.file.Files.readAllLines(pids).stream().map(Long::valueOf).toList();
        assertEquals(2, children.size(), "one child per start");
        for (long pid : children) {
            java.util.Optional<ProcessHandle> p = ProcessHandle.of(pid);
            if (p.isPresent()) {
                p.get().onExit().get(2, java.util.concurrent.TimeUnit.SECONDS);
            }
            assertTrue(ProcessHandle.of(pid).map(h -> !h.isAlive()).orElse(true), "child " + pid + " survives");
        }
    }

    @Test
    void keptTextRepairsSurrogatesAndCapsAtACharacterBoundary() {
        assertEquals("a\uFFFDb\uFFFD", IutText.kept("a\udc00b\ud800"));
        assertEquals("\uD83D\uDE00", IutText.kept("\uD83D\uDE00"), "a proper pair is kept");
        String euro = "€".repeat(2000);   // 3 bytes each: 6000 bytes
        String kept = IutText.kept(euro);
        assertEquals("€".repeat(1365) + "… (truncated, 6000 bytes)", kept, "4096 / 3 = 1365 whole characters");
        assertEquals("x".repeat(4096), IutText.kept("x".repeat(4096)), "exactly at the cap: kept whole");
    }
}
