package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 27: a SIGTERM in the first moments of a run, before the command has registered its own shutdown hook, used
 * to end the JVM silently with exit code 143 and nothing written. Now it ends the way SIGINT does, with a message
 * that says nothing was written, and no output directory appears. {@link HeldStart} holds that early window open
 * (it installs what {@link Main#main} installs first, then waits), so the signal lands in it every time.
 */
class EarlySignalTest {
    @TempDir
    Path dir;

    /** {@code main} of a fclcert that stops right after {@link Main#main}'s first step, before any command runs. */
    public static final class HeldStart {
        public static void main(String[] args) throws Exception {
            EarlySignals.install(System.err);
            Files.createFile(Path.of(args[0]));
            Thread.sleep(120_000);
            Main.main(java.util.Arrays.copyOfRange(args, 1, args.length));
        }
    }

    private void signalledEarly(String signal, int exitCode) throws Exception {
        Path ready = dir.resolve("ready-" + signal);
        Path out = dir.resolve("out-" + signal);
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), HeldStart.class.getName(), ready.toString(), "certify",
                "--out", out.toString()).redirectError(dir.resolve("err-" + signal).toFile())
                .redirectOutput(dir.resolve("stdout-" + signal).toFile()).start();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!Files.exists(ready) && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertTrue(Files.exists(ready), "the JVM came up");
        Process kill = new ProcessBuilder("kill", "-" + signal, String.valueOf(p.pid())).start();
        assertEquals(0, kill.waitFor());
        assertTrue(p.waitFor(30, TimeUnit.SECONDS), "ended");
        assertEquals(exitCode, p.exitValue());
        List<String> err = Files.readAllLines(dir.resolve("err-" + signal));
        assertEquals(List.of("", "fclcert: interrupted (SIGINT, SIGTERM or SIGHUP) before the run started; nothing was"
                + " written"), err);
        assertFalse(Files.exists(out), "no output directory");
    }

    @Test
    void sigtermBeforeTheRunsOwnHookEndsItWithAMessage() throws Exception {
        signalledEarly("TERM", 143);
    }

    @Test
    void sigintThereEndsItTheSameWay() throws Exception {
        signalledEarly("INT", 130);
    }
}
