package org.fclcert.iut;

import java.util.Map;

/** A process's exit status in words: the exit code, and for a process killed by a signal (code 128 + n) the signal. */
final class ExitStatus {
    private static final Map<Long, String> SIGNALS = Map.of(1L, "SIGHUP", 2L, "SIGINT", 4L, "SIGILL", 6L, "SIGABRT",
            7L, "SIGBUS", 8L, "SIGFPE", 9L, "SIGKILL", 11L, "SIGSEGV, a segmentation fault", 13L, "SIGPIPE",
            15L, "SIGTERM");

    private ExitStatus() {}

    /** {@code exit code 139: killed by signal 11 (SIGSEGV, a segmentation fault)}, or {@code exit code 3}. */
    static String describe(long code) {
        if (code > 128 && code < 128 + 65) {
            long signal = code - 128;
            String name = SIGNALS.get(signal);
            return "exit code " + code + ": killed by signal " + signal + (name == null ? "" : " (" + name + ")");
        }
        return "exit code " + code;
    }
}
