package org.fclcert.model;

/**
 * Documented implementation limits of fclcert, shared by the reader and the checks so that both
 * agree. The standard sets no limit; these exist so that no input can exhaust the stack.
 */
public final class Limits {
    /**
     * Deepest nesting of parentheses fclcert reads. The strict reader rejects deeper nesting with
     * FCL-S008 before parsing (so the recursive parser never sees it); check FCL-C026 uses the same
     * number for programs built by other readers.
     */
    public static final int MAX_NESTING_DEPTH = 1_000;

    private Limits() {
    }
}
