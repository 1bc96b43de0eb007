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

    private Limits() {
    }
}
