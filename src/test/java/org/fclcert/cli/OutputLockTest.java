package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fclcert.orchestration.OutputDirectory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 27: {@code probe --out} and {@code fuzz --out} hold their output directory as {@code certify} does; a second
 * run into the same directory refuses at once, naming the first run and its pid, and the directory is free again
 * once the first has ended. The first run is a real fclcert in a JVM of its own, slowed down by
 * {@code src/test/resources/iut/slow.py}.
 */
class OutputLockTest {
    @TempDir
    Path dir;

    private Process first(String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "org.fclcert.cli.Main"));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectOutput(dir.resolve("first.out").toFile())
                .redirectError(dir.resolve("first.err").toFile()).start();
    }

    private String slow() {
        return "process:python3 src/test/resources/iut/slow.py 0.25 " + dir.resolve("pids");
    }

    /** Waits until the lock file beside {@code out} names {@code pid}. */
    private static void awaitHolder(Path out, long pid) throws Exception {
        Path lock = out.resolveSibling("." + out.getFileName() + ".lock");
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            if (Files.exists(lock) && Files.readString(lock).startsWith("pid " + pid + ",")) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("the first run never locked " + out);
    }

    private void refusedWhileTheFirstRuns(Process first, Path out, String command, String... second) throws Exception {
        try {
            awaitHolder(out, first.pid());
            StringWriter err = new StringWriter();
            long start = System.nanoTime();
            int exit = Main.run(new PrintWriter(new StringWriter()), new PrintWriter(err), second);
            long seconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - start);
            assertEquals(2, exit, err.toString());
            assertTrue(err.toString().startsWith("fclcert " + command + ": the output directory "
                    + out.toAbsolutePath().normalize() + " is in use by another fclcert run (pid " + first.pid()
                    + ", started "), err.toString());
            assertTrue(seconds < 10, "refused at once, not after " + seconds + " s");
            assertTrue(first.isAlive(), "the first run goes on");
        } finally {
            first.destroy();
            assertTrue(first.waitFor(60, TimeUnit.SECONDS));
        }
        // the kernel released the first run's lock with its process
        try (OutputDirectory.Lock free = OutputDirectory.lock(out)) {
            assertTrue(Files.readString(out.resolveSibling("." + out.getFileName() + ".lock"))
                    .startsWith("pid " + ProcessHandle.current().pid() + ","));
        }
    }

    @Test
    void aSecondProbeIntoTheSameOutRefusesNamingTheFirst() throws Exception {
        Path out = dir.resolve("probe");
        Process first = first("probe", "--iut", slow(), "--no-sandbox", "--cap", "64", "--out", out.toString());
        refusedWhileTheFirstRuns(first, out, "probe", "probe", "--iut", "reference", "--cap", "4", "--out",
                out.toString());
    }

    @Test
    void aSecondFuzzRunIntoTheSameOutRefusesNamingTheFirst() throws Exception {
        Path out = dir.resolve("fuzz");
        Process first = first("fuzz", "--iut", slow(), "--no-sandbox", "--budget", "2m", "--out", out.toString());
        refusedWhileTheFirstRuns(first, out, "fuzz", "fuzz", "--iut", "reference", "--budget", "1s", "--out",
                out.toString());
    }
}
