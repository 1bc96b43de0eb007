package org.fclcert.model;

import java.math.BigDecimal;
import java.math.BigInteger;

/**
 * A numeric literal (IEC 61131-3 B.1.2): its value, and whether it was written as an integer
 * literal ({@code 5}, {@code -1_000}, {@code 16#FF}) or a real literal ({@code 5.0}, {@code 2.5E-3}).
 * The spelling is not kept: {@code 1_000} and {@code 1000} are the same literal.
 *
 * @param wideInteger the exact value of an integer literal that a double cannot hold (beyond 2^53,
 *                    e.g. {@code 9223372036854775807}, whose double is 2^63), so that range checks
 *                    and writers see what was written; null when {@code value} is exact
 */
public record Literal(double value, boolean integral, SourceLocation location, BigInteger wideInteger)
        implements Operand {
    public Literal(double value, boolean integral, SourceLocation location) {
        this(value, integral, location, null);
    }

    public static Literal of(double value) {
        return new Literal(value, value == Math.rint(value) && Math.abs(value) < 1e15, SourceLocation.UNKNOWN);
    }

    /** The value exactly as written for integer literals, else the double's exact decimal; value must be finite. */
    public BigDecimal exactValue() {
        return wideInteger != null ? new BigDecimal(wideInteger) : new BigDecimal(value);
    }
}
