package org.fclcert.eval;

import java.util.Arrays;

/**
 * CoG in closed form over the fewest breakpoints for the usual Mamdani output (ACCU MAX): its terms are
 * unimodal 0/1 shapes ({@link TermDegrees.Edges}: triangles, trapezoids, shoulders) that form a
 * <b>chain</b> — ordered by their rising edge, only neighbours overlap, and where they do, the earlier
 * one only falls and the later one only rises. Each activated term is then a trapezoid w · min(L, μ)
 * (ACT MIN) or w · L · μ (ACT PROD) with at most four vertices, and the accumulated set is those
 * trapezoids one after the other, joined inside each overlap at the single place where the falling side
 * meets the rising side. This gives the vertices of the exact accumulated set that {@link SetBuilder}
 * builds by the general sweep (every breakpoint against every contribution, then the envelope), in
 * time linear in the number of activated terms.
 *
 * <p>The chain is decided once, when the block is compiled: the terms' points are constants.
 */
final class ClippedChain {
    /** The output's terms in chain order: index into the output's term list. */
    private final int[] order;
    private final double[] a;
    private final double[] b;
    private final double[] c;
    private final double[] d;
    private final double lo;
    private final double hi;

    // per activated term, in chain order: its vertices (x, y), at most four
    private final double[] vx;
    private final double[] vy;
    private final int[] vn;
    private int active;

    // the piece-wise linear set as it is walked from left to right: the last vertex, and the sums
    private double lastX;
    private double lastY;
    private boolean started;
    /** 2 ∫μ and 6 ∫u·μ over the set built by the last {@link #centreOfGravity}. */
    private double area2;
    private double moment6;

    private ClippedChain(int[] order, double[] a, double[] b, double[] c, double[] d, double lo, double hi) {
        this.order = order;
        this.a = a;
        this.b = b;
        this.c = c;
        this.d = d;
        this.lo = lo;
        this.hi = hi;
        int n = order.length;
        vx = new double[4 * n];
        vy = new double[4 * n];
        vn = new int[n];
    }

    /**
     * The chain over these shapes (the output's terms, in its term order) on [lo, hi], or null when they
     * are not all unimodal 0/1 shapes forming a chain.
     */
    static ClippedChain of(Shape[] shapes, double lo, double hi) {
        int n = shapes.length;
        if (!(lo < hi) || !Double.isFinite(lo) || !Double.isFinite(hi)) {
            return null;
        }
        TermDegrees.Edges[] e = new TermDegrees.Edges[n];
        Integer[] idx = new Integer[n];
        for (int t = 0; t < n; t++) {
            Shape s = shapes[t];
            e[t] = s.singleton || !s.constant || s.kind != null ? null : TermDegrees.Edges.of(s.sortedX, s.sortedY, s.n);
            if (e[t] == null) {
                return null;
            }
            idx[t] = t;
        }
        Arrays.sort(idx, (p, q) -> Double.compare(e[p].b(), e[q].b()));
        int[] order = new int[n];
        double[] a = new double[n];
        double[] b = new double[n];
        double[] c = new double[n];
        double[] d = new double[n];
        for (int k = 0; k < n; k++) {
            TermDegrees.Edges x = e[idx[k]];
            order[k] = idx[k];
            a[k] = x.a();
            b[k] = x.b();
            c[k] = x.c();
            d[k] = x.d();
        }
        for (int k = 0; k + 1 < n; k++) {
            // neighbours: the earlier only falls over the overlap [a(k+1), d(k)], the later only rises there
            if (!(a[k + 1] >= c[k] && d[k] <= b[k + 1])) {
                return null;
            }
            if (k + 2 < n && !(a[k + 2] >= d[k])) {
                return null;    // a term overlapping the one after its neighbour
            }
        }
        for (int k = 0; k < n; k++) {
            if (k > 0 && a[k] == Double.NEGATIVE_INFINITY || k < n - 1 && d[k] == Double.POSITIVE_INFINITY
                    || a[k] == Double.NEGATIVE_INFINITY && d[k] == Double.POSITIVE_INFINITY) {
                return null;    // only the first term may start at degree 1, only the last end at it, none both
            }
        }
        return new ClippedChain(order, a, b, c, d, lo, hi);
    }

    /**
     * The CoG of the accumulated set over [lo, hi]: ∫u·μ / ∫μ summed piece by piece (trapezoids and their
     * first moments, as {@link Defuzzifier#centreOfGravity}, with the constant factors taken out of the sums
     * and one division at the end); NaN when the set has no area. {@code level[base + t]},
     * {@code weight[base + t]} and {@code prod[base + t]} are term t's merged activation level, its rule weight
     * and whether it is activated by PROD; terms with w · L = 0 contribute nothing.
     */
    double centreOfGravity(double[] level, double[] weight, boolean[] prod, int base) {
        build(level, weight, prod, base);
        return area2 > 0 ? moment6 / (3 * area2) : Double.NaN;
    }

    /** Whether the set built by the last {@link #centreOfGravity} has no area. */
    boolean empty() {
        return area2 == 0;
    }

    private void build(double[] level, double[] weight, boolean[] prod, int base) {
        active = 0;
        int n = order.length;
        for (int k = 0; k < n; k++) {
            int t = base + order[k];
            double l = level[t];
            double h = l * weight[t];
            if (!(h > 0)) {
                continue;
            }
            int at = 4 * active;
            int m = 0;
            boolean byProd = prod[t];
            if (a[k] != Double.NEGATIVE_INFINITY) {
                vx[at] = a[k];
                vy[at] = 0.0;
                // ACT MIN: the clip level meets the rising edge at a + (b − a)·L (the reference's crossing)
                vx[at + 1] = byProd || l >= 1.0 ? b[k] : a[k] + (b[k] - a[k]) * l;
                vy[at + 1] = h;
                m = 2;
            }
            if (d[k] != Double.POSITIVE_INFINITY) {
                double x = byProd || l >= 1.0 ? c[k] : c[k] + (d[k] - c[k]) * ((l - 1.0) / -1.0);
                if (m == 0 || x > vx[at + m - 1]) {
                    vx[at + m] = x;
                    vy[at + m++] = h;
                }
                vx[at + m] = d[k];
                vy[at + m++] = 0.0;
            }
            vn[active++] = m;
        }
        started = false;
        area2 = 0;
        moment6 = 0;
        double from = lo;
        for (int j = 0; j < active; j++) {
            double to = hi;
            if (j + 1 < active) {
                to = Math.min(hi, meeting(j, j + 1));
            }
            emit(j, from, to);
            from = Math.max(from, to);
        }
    }

    /** Where term j's falling side meets term j + 1's rising side (the left end of the overlap when none). */
    private double meeting(int j, int k) {
        int pj = 4 * j;
        int pk = 4 * k;
        double left = vx[pk];                       // where k starts rising (finite: k is not first)
        double right = vx[pj + vn[j] - 1];          // where j has fallen to 0 (finite: j is not last)
        if (!(left < right)) {
            return right;                           // no overlap: they meet at zero
        }
        // g = f_j − f_k decreases from g(left) ≥ 0 to g(right) ≤ 0; walk the breakpoints inside the overlap
        double x0 = left;
        double g0 = value(j, left);
        if (g0 <= 0) {
            return left;
        }
        double p = vx[pj + vn[j] - 2];              // where j starts falling
        double q = vx[pk + 1];                      // where k stops rising
        for (int i = 0; i < 3; i++) {
            double x1 = i == 0 ? Math.min(p, q) : i == 1 ? Math.max(p, q) : right;
            if (!(x1 > x0) || x1 > right) {
                continue;
            }
            double g1 = value(j, x1) - value(k, x1);
            if (g1 <= 0) {
                return g1 == 0 ? x1 : x0 + (x1 - x0) * (g0 / (g0 - g1));
            }
            x0 = x1;
            g0 = g1;
        }
        return right;
    }

    /** The activated set of term j at u (linear between its vertices, 0 beyond a present edge). */
    private double value(int j, double u) {
        int p = 4 * j;
        int m = vn[j];
        if (u <= vx[p]) {
            return vy[p];
        }
        for (int i = p + 1; i < p + m; i++) {
            if (u <= vx[i]) {
                return Pwl.interpolate(vx[i - 1], vy[i - 1], vx[i], vy[i], u);
            }
        }
        return vy[p + m - 1];
    }

    /**
     * Appends term j's vertices within [from, to], with its values at both ends. Vertices on the ends count
     * too: where a clip level is so small that a + (b − a)·L rounds to a, the set rises vertically at a = from,
     * and only the vertex (from, h) says so (a vertical piece adds no area, so a repeated x costs nothing).
     */
    private void emit(int j, double from, double to) {
        if (!(from < to)) {
            return;
        }
        int p = 4 * j;
        int m = vn[j];
        add(from, value(j, from));
        for (int i = p; i < p + m; i++) {
            if (vx[i] >= from && vx[i] <= to) {
                add(vx[i], vy[i]);
            }
        }
        add(to, value(j, to));
    }

    /** The next vertex: adds the trapezoid from the last one (2·area and 6·moment, so exact factors stay out). */
    private void add(double x, double y) {
        if (started) {
            double h = x - lastX;
            double s = lastY + y;
            area2 += h * s;
            moment6 += h * (lastX * (lastY + s) + x * (s + y));
        }
        started = true;
        lastX = x;
        lastY = y;
    }
}
