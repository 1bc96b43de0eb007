package org.fclcert.sandbox;

import java.time.Duration;
import java.util.Objects;

/**
 * What a sandboxed implementation may use. Memory, processes and file size are kernel resource limits
 * (RLIMIT_DATA, RLIMIT_NPROC, RLIMIT_FSIZE) set inside the sandbox; CPU time is counted per request over
 * the whole process tree by the adapter that drives it ({@link Sandbox#cpuTime}).
 *
 * @param memoryBytes   writable private memory of each process (heap, anonymous mappings, thread stacks)
 * @param processes     processes and threads alive at once in the sandbox
 * @param fileSizeBytes largest file a process may write (the private /tmp and working directory are also
 *                      capped at this size each)
 * @param cpuPerRequest CPU time the process tree may spend on one request (all its processes and threads)
 */
public record Limits(long memoryBytes, int processes, long fileSizeBytes, Duration cpuPerRequest) {
    public static final long DEFAULT_MEMORY_BYTES = 2L << 30;
    public static final int DEFAULT_PROCESSES = 256;
    public static final long DEFAULT_FILE_SIZE_BYTES = 256L << 20;
    public static final Duration DEFAULT_CPU_PER_REQUEST = Duration.ofSeconds(30);

    public Limits {
        Objects.requireNonNull(cpuPerRequest, "cpuPerRequest");
        if (memoryBytes < 1 || processes < 1 || fileSizeBytes < 1 || cpuPerRequest.isNegative()
                || cpuPerRequest.isZero()) {
            throw new IllegalArgumentException("sandbox limits must be positive");
        }
    }

    public static Limits defaults() {
        return new Limits(DEFAULT_MEMORY_BYTES, DEFAULT_PROCESSES, DEFAULT_FILE_SIZE_BYTES, DEFAULT_CPU_PER_REQUEST);
    }

    public Limits withMemoryBytes(long bytes) {
        return new Limits(bytes, processes, fileSizeBytes, cpuPerRequest);
    }

    public Limits withProcesses(int count) {
        return new Limits(memoryBytes, count, fileSizeBytes, cpuPerRequest);
    }

    public Limits withFileSizeBytes(long bytes) {
        return new Limits(memoryBytes, processes, bytes, cpuPerRequest);
    }

    public Limits withCpuPerRequest(Duration cpu) {
        return new Limits(memoryBytes, processes, fileSizeBytes, cpu);
    }

    /** The limits in words, for reports: "memory 2 GiB, 256 processes, files 256 MiB, CPU 30 s per request". */
    public String describe() {
        return "memory " + bytes(memoryBytes) + ", " + processes + " processes, files " + bytes(fileSizeBytes)
                + ", CPU " + seconds(cpuPerRequest) + " per request";
    }

    static String bytes(long n) {
        if (n % (1L << 30) == 0) {
            return (n >> 30) + " GiB";
        }
        if (n % (1L << 20) == 0) {
            return (n >> 20) + " MiB";
        }
        if (n % (1L << 10) == 0) {
            return (n >> 10) + " KiB";
        }
        return n + " bytes";
    }

    private static String seconds(Duration d) {
        return d.toMillis() % 1000 == 0 ? d.toSeconds() + " s" : d.toMillis() + " ms";
    }
}
