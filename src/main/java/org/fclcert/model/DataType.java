package org.fclcert.model;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.Locale;
import java.util.Optional;

/**
 * The IEC 61131-3 elementary numeric types an FCL function block may use for its variables.
 * Integer types carry their value range so that an evaluator can reject a result that does not fit.
 */
public enum DataType {
    REAL(false, -Float.MAX_VALUE, Float.MAX_VALUE),
    LREAL(false, -Double.MAX_VALUE, Double.MAX_VALUE),
    SINT(true, -128, 127),
    INT(true, -32_768, 32_767),
    DINT(true, Integer.MIN_VALUE, Integer.MAX_VALUE),
    LINT(true, Long.MIN_VALUE, Long.MAX_VALUE),
    USINT(true, 0, 255),
    UINT(true, 0, 65_535),
    UDINT(true, 0, 4_294_967_295.0),
    ULINT(true, 0, 18_446_744_073_709_551_615.0);

    private final boolean integer;
    private final double min;
    private final double max;

    DataType(boolean integer, double min, double max) {
        this.integer = integer;
        this.min = min;
        this.max = max;
    }

    public boolean isInteger() {
        return integer;
    }

    /** Smallest representable value (for REAL, the most negative finite single-precision value). */
    public double min() {
        return min;
    }

    /** Largest representable value. */
    public double max() {
        return max;
    }

    /**
     * The exact smallest value: the doubles {@link #min()} and {@link #max()} round LINT's and ULINT's
     * bounds to 2^63 and 2^64, which a range check must not accept.
     */
    public BigDecimal exactMin() {
        return this == LINT ? BigDecimal.valueOf(Long.MIN_VALUE) : new BigDecimal(min);
    }

    /** The exact largest value (see {@link #exactMin()}). */
    public BigDecimal exactMax() {
        return switch (this) {
            case LINT -> BigDecimal.valueOf(Long.MAX_VALUE);
            case ULINT -> new BigDecimal(BigInteger.ONE.shiftLeft(64).subtract(BigInteger.ONE));
            default -> new BigDecimal(max);
        };
    }

    /** The type named by a keyword in any case, e.g. {@code real} or {@code UDInt}. */
    public static Optional<DataType> byKeyword(String keyword) {
        try {
            return Optional.of(valueOf(keyword.toUpperCase(Locale.ROOT)));
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
    }
}
