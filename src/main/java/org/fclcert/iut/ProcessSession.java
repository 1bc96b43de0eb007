package org.fclcert.iut;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.OptionalLong;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.TimeUnit;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.fclcert.sandbox.Sandbox;

/**
 * One run of an IUT process: its pipes, the threads that drain them, and killing it (with the
 * processes it started). Requests are written on a separate thread so that an IUT that stops
 * reading its input cannot block fclcert past the timeout.
 */
final class ProcessSession {
    private final Process process;
    private final OutputStream stdin;
    private final ReplyReader replies;
    private final StderrTail stderr;
    private final ExecutorService writer;

    private ProcessSession(Process process, IutOptions options, int number) {
        this.process = process;
        this.stdin = process.getOutputStream();
        String name = "fclcert-iut-" + process.pid() + "-" + number;
        this.replies = new ReplyReader(process.getInputStream(), options.maxReplyBytes(), name + "-stdout");
        this.stderr = new StderrTail(process.getErrorStream(), options.stderrTailBytes(), name + "-stderr");
        this.writer = Executors.newSingleThreadExecutor(r -> daemon(r, name + "-stdin"));
    }

    /** Starts {@code command} through the sandbox (which leaves it unwrapped when it is off or unavailable). */
    static ProcessSession start(List<String> command, Sandbox sandbox, IutOptions options, int number)
            throws IOException {
        Process process = sandbox.processBuilder(command).start();
        return new ProcessSession(process, options, number);
    }

    /** CPU time of the process and what it started, so far (the per-request CPU limit is counted on it). */
    java.time.Duration cpuTime() {
        return Sandbox.cpuTime(process.toHandle());
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    boolean isAlive() {
        return process.isAlive();
    }

    /**
     * Every process the IUT has been seen to start. A child that outlives its parent is re-parented away
     * from the IUT's tree (and may keep its stdout open), so {@code descendants()} at kill time would miss
     * it; the tree is therefore noted at every request and reply and all of it is killed.
     */
    private final java.util.Set<ProcessHandle> seen = java.util.concurrent.ConcurrentHashMap.newKeySet();

    private void noteDescendants() {
        process.descendants().forEach(seen::add);
    }

    /** Sends one line (without its newline) in the background; a failure shows up as a reply event. */
    void send(String line) {
        noteDescendants();
        byte[] bytes = (line + "\n").getBytes(StandardCharsets.UTF_8);
        writer.execute(() -> {
            try {
                stdin.write(bytes);
                stdin.flush();
            } catch (IOException e) {
                replies.writeFailed(e.getMessage());
            }
        });
    }

    ReplyReader.Event next(long nanos) throws InterruptedException {
        ReplyReader.Event event = replies.next(nanos);
        noteDescendants();
        return event;
    }

    /** The exit code, waiting at most {@code millis} for the process to end; empty if it still runs. */
    OptionalLong exitCode(long millis) {
        try {
            process.waitFor(millis, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return process.isAlive() ? OptionalLong.empty() : OptionalLong.of(process.exitValue());
    }

    /** The end of stderr so far, after waiting briefly for a dead process's last words. */
    String stderrTail(long waitMillis) {
        if (!process.isAlive()) {
            stderr.awaitEnd(waitMillis);
        }
        return stderr.text();
    }

    /** Kills the process and every process it started (collected first, so none is orphaned unseen). */
    void kill() {
        noteDescendants();
        killTree(process, seen);
        writer.shutdownNow();
        replies.stop();
    }

    /**
     * Kills a process and every process it started (collected first, so none is orphaned unseen), and
     * waits briefly for them to end.
     */
    static void killTree(Process process) {
        killTree(process, java.util.Set.of());
    }

    /** {@link #killTree(Process)}, also killing the processes seen earlier and whatever they started since. */
    static void killTree(Process process, java.util.Set<ProcessHandle> seenBefore) {
        java.util.Set<ProcessHandle> all = new java.util.LinkedHashSet<>(process.descendants().toList());
        for (ProcessHandle p : seenBefore) {
            if (p.isAlive()) {
                all.add(p);
                p.descendants().forEach(all::add);
            }
        }
        List<ProcessHandle> tree = List.copyOf(all);
        process.destroyForcibly();
        tree.forEach(ProcessHandle::destroyForcibly);
        try {
            process.waitFor(1000, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        tree.forEach(ProcessSession::awaitExit);
    }

    private static void awaitExit(ProcessHandle p) {
        try {
            p.onExit().get(500, TimeUnit.MILLISECONDS);
        } catch (ExecutionException | TimeoutException e) {
            // killed but not yet reaped: the kill signal is all fclcert can do
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Closes stdin so that an IUT reading to end of input can finish on its own. */
    void closeInput() {
        writer.shutdown();
        try {
            stdin.close();
        } catch (IOException e) {
            // already gone: killing follows anyway
        }
    }

    /**
     * Peak resident set size of the process and its descendants (VmHWM from {@code /proc}, Linux only),
     * in bytes; empty where it cannot be read.
     */
    OptionalLong peakRss() {
        long[] peaks = Stream.concat(Stream.of(process.toHandle()), process.descendants())
                .map(p -> vmHwm(p.pid()))
                .filter(OptionalLong::isPresent)
                .mapToLong(OptionalLong::getAsLong)
                .toArray();
        return peaks.length == 0 ? OptionalLong.empty() : OptionalLong.of(LongStream.of(peaks).sum());
    }

    private static OptionalLong vmHwm(long pid) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc", Long.toString(pid), "status"))) {
                if (line.startsWith("VmHWM:")) {
                    String kb = line.substring("VmHWM:".length()).replace("kB", "").strip();
                    return OptionalLong.of(Long.parseLong(kb) * 1024);
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux, or the process just ended: no measurement
        }
        return OptionalLong.empty();
    }
}
