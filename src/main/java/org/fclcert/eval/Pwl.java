package org.fclcert.eval;

/**
 * Piece-wise linear membership functions given by points sorted by x (5.2.2): linear between
 * successive points, constant beyond the outer points. Where several points share one x the
 * function jumps; its value exactly there is the largest of their degrees, and its one-sided limits
 * are the degrees of the first and the last of them.
 */
final class Pwl {
    private Pwl() {
    }

    /** The degree at {@code u}. */
    static double degree(double[] x, double[] y, int n, double u) {
        if (u < x[0]) {
            return y[0];
        }
        if (u > x[n - 1]) {
            return y[n - 1];
        }
        int i = n <= 8 ? linearLowerBound(x, u) : lowerBound(x, n, u);
        if (x[i] == u) {
            double max = y[i];
            for (int j = i + 1; j < n && x[j] == u; j++) {
                max = Math.max(max, y[j]);
            }
            return max;
        }
        return interpolate(x[i - 1], y[i - 1], x[i], y[i], u);
    }

    /**
     * The value at {@code u} of the segment from (x0, y0) to (x1, y1), x0 &lt; u &lt; x1. The form
     * with one division is exact for the common 0/1 degrees; a flat segment returns its degree
     * unchanged so that plateaus compare equal. A segment wider than the largest double (from
     * -1.0E308 to 1.0E308, say) is computed on halved abscissas: halving such large numbers is exact,
     * and the width then no longer overflows to infinity (which would give degree 0 everywhere).
     */
    static double interpolate(double x0, double y0, double x1, double y1, double u) {
        if (y0 == y1) {
            return y0;
        }
        double width = x1 - x0;
        if (Double.isInfinite(width)) {
            double h0 = x0 / 2;
            double h1 = x1 / 2;
            double hu = u / 2;
            return ((h1 - hu) * y0 + (hu - h0) * y1) / (h1 - h0);
        }
        return ((x1 - u) * y0 + (u - x0) * y1) / width;
    }

    /** First index whose x is &gt;= u, for short point lists where a scan beats bisection. */
    static int linearLowerBound(double[] x, double u) {
        int i = 0;
        while (x[i] < u) {
            i++;
        }
        return i;
    }

    /** First index whose x is &gt;= u (n when none). */
    static int lowerBound(double[] x, int n, double u) {
        int lo = 0;
        int hi = n;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (x[mid] < u) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /** Stable insertion sort of the points by x: the order of points with equal x is kept. */
    static void sortStably(double[] x, double[] y, int n) {
        for (int i = 1; i < n; i++) {
            double xi = x[i];
            double yi = y[i];
            int j = i - 1;
            while (j >= 0 && x[j] > xi) {
                x[j + 1] = x[j];
                y[j + 1] = y[j];
                j--;
            }
            x[j + 1] = xi;
            y[j + 1] = yi;
        }
    }
}
