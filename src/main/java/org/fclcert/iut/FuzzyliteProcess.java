package org.fclcert.iut;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalLong;
import java.util.concurrent.TimeUnit;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.sandbox.Sandbox;
import org.fclcert.sandbox.SandboxSettings;

/**
 * One launch of the fuzzylite command line: its standard output and error (both drained on their own
 * threads, only their ends kept), its exit code, and — where GNU time is installed at {@code /usr/bin/time}
 * — its peak resident set size. A launch that overruns the timeout is killed with every process it
 * started. Standard input is closed at once, so the tool can never wait for a console user.
 */
final class FuzzyliteProcess {
    private static final String GNU_TIME = "/usr/bin/time";
    private static final long DRAIN_WAIT_MILLIS = 2000;

    /** What one launch left behind. */
    record Run(int exitCode, String stdout, String stderr, OptionalLong peakRssBytes) {
    }

    private FuzzyliteProcess() {}

    /**
     * Runs {@code command} to its end.
     *
     * @param rssFile where GNU time writes the peak RSS, or null not to measure
     * @throws IutException {@link Kind#INFRA} when the command cannot be started, {@link Kind#TIMEOUT} when it
     *     does not end in time (it is killed first)
     */
    static Run run(List<String> command, Path rssFile, Duration timeout, int tailBytes) throws IutException {
        return run(command, rssFile, timeout, tailBytes, Sandbox.of(SandboxSettings.none()), List.of());
    }

    /**
     * Runs {@code command} to its end through {@code sandbox}, with the {@code writable} directories (where the
     * launch reads its program and writes its answer) bound read-write.
     */
    static Run run(List<String> command, Path rssFile, Duration timeout, int tailBytes, Sandbox sandbox,
            List<Path> writable) throws IutException {
        List<String> full = new ArrayList<>();
        if (rssFile != null) {
            full.addAll(List.of(GNU_TIME, "-f", "%M", "-o", rssFile.toString()));
        }
        full.addAll(command);
        Process process;
        try {
            process = sandbox.oneRequest(full, writable).start();
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "could not start " + command.get(0) + " (" + e.getMessage()
                    + "); install fuzzylite (Debian/Ubuntu: apt-get install fuzzylite) or give its path as fuzzylite:PATH");
        }
        try {
            process.getOutputStream().close();
        } catch (IOException e) {
            // it exited already: what it wrote is read below
        }
        String name = "fclcert-fuzzylite-" + process.pid();
        int capacity = Math.max(tailBytes, 4096);
        StderrTail stdout = new StderrTail(process.getInputStream(), capacity, name + "-stdout");
        StderrTail stderr = new StderrTail(process.getErrorStream(), capacity, name + "-stderr");
        boolean ended;
        try {
            ended = process.waitFor(timeout.toNanos(), TimeUnit.NANOSECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            ProcessSession.killTree(process);
            throw new IutException(Kind.INFRA, "interrupted while waiting for fuzzylite");
        }
        if (!ended) {
            ProcessSession.killTree(process);
            stderr.awaitEnd(DRAIN_WAIT_MILLIS);
            throw new IutException(Kind.TIMEOUT, "fuzzylite did not finish within " + timeout.toMillis() + " ms",
                    stdout.text() + stderr.text());
        }
        stdout.awaitEnd(DRAIN_WAIT_MILLIS);
        stderr.awaitEnd(DRAIN_WAIT_MILLIS);
        return new Run(process.exitValue(), stdout.text(), stderr.text(), peakRss(rssFile));
    }

    /** Whether {@code /usr/bin/time} is GNU time (which has {@code -f %M -o FILE}); asked once per session. */
    static boolean gnuTimeAvailable(Duration timeout) {
        if (!Files.isExecutable(Path.of(GNU_TIME))) {
            return false;
        }
        try {
            Run run = run(List.of(GNU_TIME, "--version"), null, timeout, 4096);
            return (run.stdout() + run.stderr()).contains("GNU");
        } catch (IutException e) {
            return false;
        }
    }

    /** The last line of GNU time's output file is the peak RSS in KiB (a line before it may name a signal). */
    private static OptionalLong peakRss(Path rssFile) {
        if (rssFile == null) {
            return OptionalLong.empty();
        }
        try {
            List<String> lines = Files.readAllLines(rssFile);
            Files.deleteIfExists(rssFile);
            for (int k = lines.size() - 1; k >= 0; k--) {
                String line = lines.get(k).strip();
                if (line.matches("\\d+")) {
                    return OptionalLong.of(Long.parseLong(line) * 1024);
                }
            }
        } catch (IOException | RuntimeException e) {
            // not written (the launch failed early): no measurement
        }
        return OptionalLong.empty();
    }
}
