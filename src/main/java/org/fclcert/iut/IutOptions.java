package org.fclcert.iut;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Objects;
import org.fclcert.sandbox.SandboxSettings;

/**
 * How fclcert drives an implementation under test.
 *
 * @param timeout        longest wait for one reply (process IUT) or one call (Java IUT)
 * @param restartBudget  how many times in a row a crashed or hung IUT is restarted: once this many + 1
 *                       requests in a row have broken it down, requests fail with {@link IutException.Kind#GAVE_UP}
 *                       (a process IUT, {@code RestartPolicy}; for a Java IUT the abandoned calls in all, for
 *                       fuzzylite the timed-out launches in all)
 * @param maxReplyBytes  longest reply line accepted from a process IUT; longer is a protocol fault
 * @param stderrTailBytes how much of the end of a process IUT's standard error is kept for reports
 * @param classpath      jars or class directories searched for a {@code java:CLASS} IUT (empty = the
 *                       classpath fclcert runs on)
 * @param sandbox        how implementation processes are launched (the sandbox is on by default)
 * @param inProcess      {@code --in-process}: a {@code java:CLASS} implementation is called inside fclcert's own JVM
 *                       (faster, unisolated) instead of in a child JVM in the sandbox
 */
public record IutOptions(Duration timeout, int restartBudget, int maxReplyBytes, int stderrTailBytes,
        List<Path> classpath, SandboxSettings sandbox, boolean inProcess) {

    /** The per-request timeout unless the user sets one (the front ends show it through orchestration.Defaults). */
    public static final int DEFAULT_TIMEOUT_SECONDS = 5;
    public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(DEFAULT_TIMEOUT_SECONDS);
    public static final int DEFAULT_RESTART_BUDGET = 5;
    public static final int DEFAULT_MAX_REPLY_BYTES = 16 * 1024 * 1024;
    public static final int DEFAULT_STDERR_TAIL_BYTES = 8 * 1024;

    public IutOptions {
        Objects.requireNonNull(timeout, "timeout");
        if (timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("timeout must be positive: " + timeout);
        }
        if (restartBudget < 0 || maxReplyBytes < 1 || stderrTailBytes < 0) {
            throw new IllegalArgumentException("restart budget, reply size and stderr tail size must not be negative");
        }
        classpath = List.copyOf(classpath);
        Objects.requireNonNull(sandbox, "sandbox");
    }

    /** Options with {@code java:} in a child JVM. */
    public IutOptions(Duration timeout, int restartBudget, int maxReplyBytes, int stderrTailBytes, List<Path> classpath,
            SandboxSettings sandbox) {
        this(timeout, restartBudget, maxReplyBytes, stderrTailBytes, classpath, sandbox, false);
    }

    /** Options with the default sandbox. */
    public IutOptions(Duration timeout, int restartBudget, int maxReplyBytes, int stderrTailBytes, List<Path> classpath) {
        this(timeout, restartBudget, maxReplyBytes, stderrTailBytes, classpath, SandboxSettings.defaults());
    }

    public static IutOptions defaults() {
        return new IutOptions(
                DEFAULT_TIMEOUT, DEFAULT_RESTART_BUDGET, DEFAULT_MAX_REPLY_BYTES, DEFAULT_STDERR_TAIL_BYTES, List.of());
    }

    public IutOptions withTimeout(Duration newTimeout) {
        return new IutOptions(newTimeout, restartBudget, maxReplyBytes, stderrTailBytes, classpath, sandbox, inProcess);
    }

    public IutOptions withRestartBudget(int budget) {
        return new IutOptions(timeout, budget, maxReplyBytes, stderrTailBytes, classpath, sandbox, inProcess);
    }

    public IutOptions withMaxReplyBytes(int bytes) {
        return new IutOptions(timeout, restartBudget, bytes, stderrTailBytes, classpath, sandbox, inProcess);
    }

    public IutOptions withStderrTailBytes(int bytes) {
        return new IutOptions(timeout, restartBudget, maxReplyBytes, bytes, classpath, sandbox, inProcess);
    }

    public IutOptions withClasspath(List<Path> entries) {
        return new IutOptions(timeout, restartBudget, maxReplyBytes, stderrTailBytes, entries, sandbox, inProcess);
    }

    public IutOptions withSandbox(SandboxSettings settings) {
        return new IutOptions(timeout, restartBudget, maxReplyBytes, stderrTailBytes, classpath, settings, inProcess);
    }

    /** {@code --in-process}: {@code java:CLASS} called inside fclcert's JVM (true) or in a child JVM (false). */
    public IutOptions withInProcess(boolean value) {
        return new IutOptions(timeout, restartBudget, maxReplyBytes, stderrTailBytes, classpath, sandbox, value);
    }
}
