package org.fclcert.eval;

/**
 * Tsukamoto's inverse of a monotonic output term (Open Level, O-TSUKAMOTO; docs/semantics.md point 9): the point
 * where the term reaches a degree w &gt; 0 — for a rising term the least u with μ(u) ≥ w, for a falling one the
 * greatest. A term that never reaches w (a sigmoid never reaches 1, nothing reaches a summed degree above 1) gives
 * the RANGE's end beyond its rise (the max for a rising term, the min for a falling one); a term that reaches w on
 * a whole half-line gives the RANGE's other end. Without a RANGE these are infinite (an overflow, FCL-V005).
 */
final class Tsukamoto {
    private Tsukamoto() {
    }

    static double point(Shape s, double[] x, double[] y, double w, boolean hasRange, double lo, double hi) {
        double z = s.kind != null ? s.kind.inverse(s.params, w) : points(x, y, s.n, w);
        if (z == Double.POSITIVE_INFINITY && hasRange) {
            return hi;
        }
        if (z == Double.NEGATIVE_INFINITY && hasRange) {
            return lo;
        }
        return z;
    }

    /** The inverse of points rising (or falling) throughout, linear between them (a ramp's compiled points). */
    static double points(double[] x, double[] y, int n, double w) {
        if (y[n - 1] >= y[0]) {
            if (y[0] >= w) {
                return Double.NEGATIVE_INFINITY;
            }
            for (int i = 0; i + 1 < n; i++) {
                if (y[i + 1] >= w) {
                    return x[i] + (w - y[i]) * (x[i + 1] - x[i]) / (y[i + 1] - y[i]);
                }
            }
            return Double.POSITIVE_INFINITY;
        }
        if (y[n - 1] >= w) {
            return Double.POSITIVE_INFINITY;
        }
        for (int i = n - 1; i > 0; i--) {
            if (y[i - 1] >= w) {
                return x[i - 1] + (y[i - 1] - w) * (x[i] - x[i - 1]) / (y[i - 1] - y[i]);
            }
        }
        return Double.NEGATIVE_INFINITY;
    }
}
