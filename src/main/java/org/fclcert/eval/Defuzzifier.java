package org.fclcert.eval;

/**
 * Defuzzification (Tables 1 and 2) of a piece-wise linear set given by its vertices, in closed form:
 * every piece between two vertices is linear, so areas and moments are exact trapezoid formulas and
 * the halving point of CoA is the root of a quadratic. A piece of zero width is a jump.
 * All methods return NaN when the set has no area (CoG, CoA) or no positive degree (LM, RM).
 */
final class Defuzzifier {
    private Defuzzifier() {
    }

    static double area(double[] px, double[] py, int np) {
        double area = 0;
        for (int j = 0; j + 1 < np; j++) {
            area += pieceArea(px[j], py[j], px[j + 1], py[j + 1]);
        }
        return area;
    }

    /** Centre of gravity: ∫u·μ / ∫μ. */
    static double centreOfGravity(double[] px, double[] py, int np) {
        return centreOfGravity(px, py, np, null);
    }

    /**
     * {@link #centreOfGravity(double[], double[], int)}, and its ∫μ into {@code areaOut[0]} (when not null): the
     * same double as {@link #area}, summed by the same operations in the same order.
     */
    static double centreOfGravity(double[] px, double[] py, int np, double[] areaOut) {
        double area = 0;
        double moment = 0;
        for (int j = 0; j + 1 < np; j++) {
            area += pieceArea(px[j], py[j], px[j + 1], py[j + 1]);
            moment += pieceSixMoments(px[j], py[j], px[j + 1], py[j + 1]);
        }
        if (areaOut != null) {
            areaOut[0] = area;
        }
        return centreOfGravity(area, moment);
    }

    /**
     * CoG from ∫μ and six times ∫u·μ summed piece by piece as {@link #centreOfGravity(double[], double[], int, double[])}
     * sums them (the pieces' moments are six times theirs: one division for all of them).
     */
    static double centreOfGravity(double area, double sixMoments) {
        return area > 0 ? sixMoments / 6.0 / area : Double.NaN;
    }

    /** The area of the linear piece from (u0, y0) to (u1, y1): a trapezoid. */
    static double pieceArea(double u0, double y0, double u1, double y1) {
        return (u1 - u0) * (y0 + y1) * 0.5;
    }

    /** Six times the first moment ∫u·μ of the linear piece from (u0, y0) to (u1, y1). */
    static double pieceSixMoments(double u0, double y0, double u1, double y1) {
        return (u1 - u0) * (u0 * (2 * y0 + y1) + u1 * (y0 + 2 * y1));
    }

    /**
     * Centre of area: the u' with equal area on both sides. When a whole interval of u' halves the
     * area (a gap of zero degree at the halfway point), its midpoint. The halfway point is searched
     * once from the left and once from the right; both agree unless there is such a gap.
     */
    static double centreOfArea(double[] px, double[] py, int np) {
        double total = area(px, py, np);
        if (!(total > 0)) {
            return Double.NaN;
        }
        double half = total * 0.5;
        double tol = total * 1e-12;
        return (fromLeft(px, py, np, half, tol) + fromRight(px, py, np, half, tol)) * 0.5;
    }

    private static double fromLeft(double[] px, double[] py, int np, double half, double tol) {
        double cum = 0;
        for (int j = 0; j + 1 < np; j++) {
            double a = pieceArea(px[j], py[j], px[j + 1], py[j + 1]);
            if (Math.abs(cum + a - half) <= tol) {
                return px[j + 1];
            }
            if (cum + a > half) {
                return px[j] + solve(py[j], py[j + 1], px[j + 1] - px[j], half - cum);
            }
            cum += a;
        }
        return px[np - 1];
    }

    private static double fromRight(double[] px, double[] py, int np, double half, double tol) {
        double cum = 0;
        for (int j = np - 2; j >= 0; j--) {
            double a = pieceArea(px[j], py[j], px[j + 1], py[j + 1]);
            if (Math.abs(cum + a - half) <= tol) {
                return px[j];
            }
            if (cum + a > half) {
                return px[j + 1] - solve(py[j + 1], py[j], px[j + 1] - px[j], half - cum);
            }
            cum += a;
        }
        return px[0];
    }

    /**
     * The distance t into a linear piece of width h, starting at degree y0 and ending at y1, whose
     * area up to t is target: y0·t + (y1−y0)/h·t²/2 = target, in the form without cancellation.
     */
    static double solve(double y0, double y1, double h, double target) {
        if (target <= 0) {
            return 0;
        }
        double s = (y1 - y0) / h;
        double disc = Math.max(0, y0 * y0 + 2 * s * target);
        double den = y0 + Math.sqrt(disc);
        double t = den > 0 ? 2 * target / den : h;
        return Math.min(h, Math.max(0, t));
    }

    /**
     * For the numerically integrated sets of {@link SmoothSet} only: degrees within this relative distance of the
     * supremum count as reaching it. On a piece-wise linear set a degree reaches the supremum when it equals it;
     * a vertex near it without equalling it is a decision the filter hands to the exact path
     * (FunctionBlockInstance.decideSet).
     */
    static final double TIE = 1e-12;

    /** Leftmost maximum: the smallest u whose degree is the supremum. */
    static double leftmostMaximum(double[] px, double[] py, int np) {
        double sup = supremum(py, np);
        if (!(sup > 0)) {
            return Double.NaN;
        }
        for (int j = 0; j < np; j++) {
            if (py[j] == sup) {
                return px[j];
            }
        }
        return Double.NaN;
    }

    /** Rightmost maximum: the largest u whose degree is the supremum. */
    static double rightmostMaximum(double[] px, double[] py, int np) {
        double sup = supremum(py, np);
        if (!(sup > 0)) {
            return Double.NaN;
        }
        for (int j = np - 1; j >= 0; j--) {
            if (py[j] == sup) {
                return px[j];
            }
        }
        return Double.NaN;
    }

    /**
     * Mean of maximum (Open Level, O-MOM; docs/semantics.md "Open Level (dialect) semantics"): the set of
     * points where the degree is the supremum is a union of plateaus (pieces whose both vertices reach
     * it) and isolated points. When the plateaus have a positive total length, the length-weighted mean
     * of their midpoints, i.e. the centre of the argmax set; otherwise the mean of the distinct
     * maximising vertices. NaN when no degree is positive.
     */
    static double meanOfMaximum(double[] px, double[] py, int np) {
        double sup = supremum(py, np);
        if (!(sup > 0)) {
            return Double.NaN;
        }
        double level = sup;
        double length = 0;
        double moment = 0;
        for (int j = 0; j + 1 < np; j++) {
            double h = px[j + 1] - px[j];
            if (h > 0 && py[j] >= level && py[j + 1] >= level) {
                length += h;
                moment += h * (px[j] + px[j + 1]) * 0.5;
            }
        }
        if (length > 0) {
            return moment / length;
        }
        double sum = 0;
        int count = 0;
        for (int j = 0; j < np; j++) {
            if (py[j] >= level && (count == 0 || px[j] != px[j - 1] || py[j - 1] < level)) {
                sum += px[j];
                count++;
            }
        }
        return sum / count;
    }

    static double supremum(double[] py, int np) {
        double sup = 0;
        for (int j = 0; j < np; j++) {
            sup = Math.max(sup, py[j]);
        }
        return sup;
    }
}
