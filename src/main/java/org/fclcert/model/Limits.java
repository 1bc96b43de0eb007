package org.fclcert.model;

/**
 * Documented implementation limits of fclcert, shared by the reader and the checks so that both
 * agree. Table 11 lets each system state its own limits; the standard sets none. These are
 * fclcert's, far above anything a controller needs and well below what would exhaust the stack.
 */
public final class Limits {
    /**
     * Deepest nesting of parentheses in one rule condition: {@code (a)} has depth 1, {@code ((a))}
     * depth 2. The strict reader rejects deeper nesting with FCL-S008 before parsing (so the
     * recursive parser never sees it); check FCL-C026 uses the same number for programs built by
     * other readers.
     */
    public static final int MAX_NESTING_DEPTH = 1_000;

    /**
     * Largest program, CSV or results file the command line reads, in bytes (128 MiB). Only regular
     * files are read (not devices, FIFOs or directories), so {@code /dev/zero} or a pipe that never
     * ends gets a plain error instead of exhausting memory or hanging.
     */
    public static final long MAX_SOURCE_BYTES = 128L * 1024 * 1024;

    private Limits() {
    }
}
