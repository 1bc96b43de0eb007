package org.fclcert.model;

/**
 * A numeric literal (IEC 61131-3 B.1.2): its value, and whether it was written as an integer
 * literal ({@code 5}, {@code -1_000}, {@code 16#FF}) or a real literal ({@code 5.0}, {@code 2.5E-3}).
 * The spelling is not kept: {@code 1_000} and {@code 1000} are the same literal.
 */
public record Literal(double value, boolean integral, SourceLocation location) implements Operand {
    public static Literal of(double value) {
        return new Literal(value, value == Math.rint(value) && Math.abs(value) < 1e15, SourceLocation.UNKNOWN);
    }
}
