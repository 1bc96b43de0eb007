package org.fclcert.model;

/**
 * Documented implementation limits of fclcert. Table 11 lets each system state its own limits (for
 * example the nesting depth of parentheses); these are fclcert's, chosen far above anything a
 * controller needs and well below what would exhaust memory or the stack.
 */
public final class Limits {
    /**
     * Deepest nesting of parentheses in one rule condition that fclcert accepts: {@code (a)} has
     * depth 1, {@code ((a))} depth 2. A condition nested deeper is rejected (FCL-C026).
     */
    public static final int MAX_NESTING_DEPTH = 1000;

    private Limits() {
    }
}
