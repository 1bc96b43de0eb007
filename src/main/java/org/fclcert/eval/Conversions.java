package org.fclcert.eval;

/** Numeric conversions to IEC 61131-3 integer types. */
final class Conversions {
    private Conversions() {
    }

    /**
     * Rounds half away from zero (2.5 → 3, -2.5 → -3). Computed from the fractional part, which is
     * exact, rather than {@code floor(v + 0.5)}, which misrounds 0.49999999999999994.
     */
    static double roundHalfAwayFromZero(double v) {
        double a = Math.abs(v);
        double f = Math.floor(a);
        if (a - f >= 0.5) {
            f += 1.0;
        }
        return Math.copySign(f, v);
    }
}
