package org.fclcert.write;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import org.fclcert.model.Literal;

/**
 * Spells numeric literals in IEC 61131-3 (B.1.2) syntax. Integer literals are written as plain
 * integers; real literals as the fewest significant digits that read back to the same double,
 * always with a '.', in plain notation for magnitudes in [1e-3, 1e7) and as {@code d.dddE±n}
 * otherwise (the layout convention of Java's {@code Double.toString}).
 */
public final class LiteralText {
    private static final RoundingMode[] CANDIDATES = {RoundingMode.HALF_EVEN, RoundingMode.FLOOR, RoundingMode.CEILING};

    private LiteralText() {
    }

    /** The literal as FCL text; throws IllegalArgumentException for NaN or infinity (no FCL spelling). */
    public static String of(Literal literal) {
        double v = literal.value();
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("the value " + v + " has no FCL literal spelling");
        }
        if (literal.wideInteger() != null) {
            return literal.wideInteger().toString();   // exactly as written, not the rounded double
        }
        return literal.integral() && v == Math.rint(v) ? integer(v) : real(v);
    }

    static String integer(double v) {
        String digits = new BigDecimal(v).toBigInteger().toString();
        return isNegativeZero(v) ? "-0" : digits;
    }

    static String real(double v) {
        String sign = v < 0 || isNegativeZero(v) ? "-" : "";
        double magnitude = Math.abs(v);
        if (magnitude == 0) {
            return sign + "0.0";
        }
        BigDecimal d = shortest(magnitude);
        String digits = d.unscaledValue().toString();
        int exponent = digits.length() - 1 - d.scale();
        boolean plain = magnitude >= 1e-3 && magnitude < 1e7;
        return sign + (plain ? plain(digits, d.scale()) : scientific(digits, exponent));
    }

    /**
     * The decimal with the fewest significant digits that parses back to {@code v} (v > 0), the
     * closest one when several have that many. Starts from Java's round-tripping (but on Java 17
     * sometimes one digit too long) spelling and shortens it while some candidate still round-trips:
     * if any p-digit decimal lies in v's rounding interval, the p-digit floor or ceiling of that
     * spelling does too, since the interval is convex and contains both.
     */
    static BigDecimal shortest(double v) {
        BigDecimal best = new BigDecimal(Double.toString(v)).stripTrailingZeros();
        for (int precision = best.precision() - 1; precision >= 1; precision--) {
            BigDecimal shorter = roundTripping(best, precision, v);
            if (shorter == null) {
                break;
            }
            best = shorter;
        }
        return best;
    }

    private static BigDecimal roundTripping(BigDecimal d, int precision, double v) {
        for (RoundingMode mode : CANDIDATES) {
            BigDecimal c = d.round(new MathContext(precision, mode));
            if (Double.parseDouble(c.toString()) == v) {
                return c.stripTrailingZeros();
            }
        }
        return null;
    }

    private static String plain(String digits, int scale) {
        if (scale <= 0) {
            return digits + "0".repeat(-scale) + ".0";
        }
        if (scale >= digits.length()) {
            return "0." + "0".repeat(scale - digits.length()) + digits;
        }
        int point = digits.length() - scale;
        return digits.substring(0, point) + "." + digits.substring(point);
    }

    private static String scientific(String digits, int exponent) {
        String fraction = digits.length() > 1 ? digits.substring(1) : "0";
        return digits.charAt(0) + "." + fraction + "E" + exponent;
    }

    private static boolean isNegativeZero(double v) {
        return Double.doubleToRawLongBits(v) == Double.doubleToRawLongBits(-0.0);
    }
}
