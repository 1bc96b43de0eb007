package org.fclcert.eval;

import java.util.Arrays;
import org.fclcert.model.AccumulationMethod;

/**
 * Builds the accumulated set of one output with point terms as an exact piece-wise linear function
 * (Table 5 accumulation of A.15-weighted activations), held as a list of vertices; a jump is two or
 * three vertices with the same u. Breakpoints are the term points, the interval ends and the places
 * where a MIN clip level crosses a term segment; between two breakpoints every activated set is
 * linear, so MAX only adds the crossings of the upper envelope and BSUM the crossing of 1.
 * Scratch arrays grow on demand and are reused, so the steady state allocates nothing.
 */
final class SetBuilder {
    /** The contributions added since the last clear. */
    final Activations act = new Activations();

    private double[] bx = new double[16];
    private int nb;
    /** MIN clip crossings: their u, and per contribution the range of its crossings in crossU. */
    private double[] crossU = new double[16];
    private int nc;
    private int[] crossStart = new int[4];
    private int[] crossEnd = new int[4];
    private double[] cl = new double[64];
    private double[] cv = new double[64];
    private double[] cr = new double[64];
    /** Per breakpoint: whether some contribution jumps there (its left limit, value and right limit differ). */
    private boolean[] jump = new boolean[16];
    private double[] aL = new double[16];
    private double[] aV = new double[16];
    private double[] aR = new double[16];

    /**
     * Vertices of the accumulated set, valid after {@link #build}. The two degrees after the last vertex (as far
     * as the arrays reach) are then 0: the arrays are reused, and a read one or two places past the set must see
     * no degree, never a vertex of an earlier evaluation (conformance/EQUIVALENT-MUTANTS.md, "stale scratch").
     */
    double[] px = new double[32];
    double[] py = new double[32];
    int np;

    /** Builds the vertices over [lo, hi]; leaves none when nothing was added or the interval is empty. */
    void build(AccumulationMethod accu, double lo, double hi, double[][] cx, double[][] cy, Shape[] shapes) {
        np = 0;
        buildVertices(accu, lo, hi, cx, cy, shapes);
        Arrays.fill(py, np, Math.min(py.length, np + 2), 0.0);
    }

    private void buildVertices(AccumulationMethod accu, double lo, double hi, double[][] cx, double[][] cy,
            Shape[] shapes) {
        if (act.n == 0 || !(lo < hi)) {
            return;
        }
        breakpoints(lo, hi, cx, cy, shapes);
        activatedValues(cx, cy, shapes);
        accumulateAtBreakpoints(accu);
        for (int i = 0; i < nb; i++) {
            // a degree equal to the one just emitted at the same u adds no vertex (emitRaw's first test): not emitted
            if (i > 0) {
                emit(bx[i], aL[i], accu);
            }
            if (i == 0 || aV[i] != aL[i]) {
                emit(bx[i], aV[i], accu);
            }
            if (i < nb - 1) {
                if (aR[i] != aV[i]) {
                    emit(bx[i], aR[i], accu);
                }
                interior(i, accu);
            }
        }
        if (accu == AccumulationMethod.NSUM) {
            normalize();
        }
    }

    private void breakpoints(double lo, double hi, double[][] cx, double[][] cy, Shape[] shapes) {
        nb = 0;
        nc = 0;
        if (crossStart.length < act.n) {
            crossStart = new int[2 * act.n];
            crossEnd = new int[2 * act.n];
        }
        addBreakpoint(lo);
        addBreakpoint(hi);
        for (int j = 0; j < act.n; j++) {
            double[] x = cx[act.shape[j]];
            double[] y = cy[act.shape[j]];
            int n = shapes[act.shape[j]].n;
            for (int i = 0; i < n; i++) {
                if (x[i] > lo && x[i] < hi) {
                    addBreakpoint(x[i]);
                }
            }
            if (!act.prod[j]) {
                clipCrossings(j, x, y, n, act.level[j], lo, hi);
            } else {
                crossStart[j] = crossEnd[j] = nc;
            }
        }
        sort(bx, nb);
        int m = 1;
        for (int i = 1; i < nb; i++) {
            if (bx[i] != bx[m - 1]) {
                bx[m++] = bx[i];
            }
        }
        nb = m;
    }

    /** Insertion sort for the usual handful of breakpoints; Arrays.sort beyond that. */
    private static void sort(double[] a, int n) {
        if (n > 32) {
            Arrays.sort(a, 0, n);
            return;
        }
        for (int i = 1; i < n; i++) {
            double v = a[i];
            int j = i - 1;
            while (j >= 0 && a[j] > v) {
                a[j + 1] = a[j];
                j--;
            }
            a[j + 1] = v;
        }
    }

    /**
     * The places where a MIN clip level crosses a segment strictly, recorded per contribution (ascending, as
     * the points are sorted) so that {@link #activatedValues} can use the level itself as the degree there: the
     * interpolated degree at a rounded crossing may miss the level by more than the tie band (issue 12). A
     * crossing that rounds onto a segment's end is kept one ulp inside, so the piece beyond stays a plateau.
     */
    private void clipCrossings(int j, double[] x, double[] y, int n, double level, double lo, double hi) {
        crossStart[j] = nc;
        for (int i = 0; i + 1 < n; i++) {
            double y0 = y[i];
            double y1 = y[i + 1];
            if ((y0 - level) * (y1 - level) < 0 && x[i + 1] > x[i]) {
                double u = x[i] + (x[i + 1] - x[i]) * (level - y0) / (y1 - y0);
                if (!(u < x[i + 1])) {
                    u = Math.nextDown(x[i + 1]);
                }
                if (!(u > x[i])) {
                    u = Math.nextUp(x[i]);
                }
                if (u > lo && u < hi && u > x[i] && u < x[i + 1]) {
                    addBreakpoint(u);
                    if (nc == crossU.length) {
                        crossU = Arrays.copyOf(crossU, 2 * nc);
                    }
                    crossU[nc++] = u;
                }
            }
        }
        crossEnd[j] = nc;
    }

    private void addBreakpoint(double u) {
        if (nb == bx.length) {
            bx = Arrays.copyOf(bx, 2 * nb);
        }
        bx[nb++] = u;
    }

    /**
     * For each contribution j and breakpoint i: left limit, value and right limit at bx[i]. The
     * breakpoints are sorted, so one forward walk over each term's points serves them all.
     */
    private void activatedValues(double[][] cx, double[][] cy, Shape[] shapes) {
        int size = act.n * nb;
        if (cl.length < size) {
            cl = new double[2 * size];
            cv = new double[2 * size];
            cr = new double[2 * size];
        }
        if (jump.length < nb) {
            jump = new boolean[2 * nb];
        }
        Arrays.fill(jump, 0, nb, false);
        for (int j = 0; j < act.n; j++) {
            double[] x = cx[act.shape[j]];
            double[] y = cy[act.shape[j]];
            int n = shapes[act.shape[j]].n;
            int base = j * nb;
            int p = 0;
            int c = crossStart[j];
            for (int i = 0; i < nb; i++) {
                double u = bx[i];
                while (p < n && x[p] < u) {
                    p++;
                }
                while (c < crossEnd[j] && crossU[c] < u) {
                    c++;
                }
                double v;
                if (c < crossEnd[j] && crossU[c] == u) {
                    v = act.level[j]; // a clip crossing: the term's degree is the level, exactly
                } else if (p < n && x[p] == u) {
                    if (p + 1 < n && x[p + 1] == u) {
                        // a jump: left limit, value and right limit differ
                        int q = p;
                        v = y[p];
                        while (q + 1 < n && x[q + 1] == u) {
                            v = Math.max(v, y[++q]);
                        }
                        cv[base + i] = act.activate(j, v);
                        cl[base + i] = act.activate(j, y[p]);
                        cr[base + i] = act.activate(j, y[q]);
                        jump[i] = true;
                        continue;
                    }
                    v = y[p];
                } else if (p == 0 || p == n) {
                    v = y[p == 0 ? 0 : n - 1];
                } else {
                    v = Pwl.interpolate(x[p - 1], y[p - 1], x[p], y[p], u);
                }
                // left limit, value and right limit are the one degree: activated once
                double a = act.activate(j, v);
                cv[base + i] = a;
                cl[base + i] = a;
                cr[base + i] = a;
            }
        }
    }

    /** MAX keeps the maximum; BSUM and NSUM keep the plain sum here (bounded or normalised later). */
    private void accumulateAtBreakpoints(AccumulationMethod accu) {
        if (aL.length < nb) {
            aL = new double[2 * nb];
            aV = new double[2 * nb];
            aR = new double[2 * nb];
        }
        boolean max = accu == AccumulationMethod.MAX;
        for (int i = 0; i < nb; i++) {
            if (!jump[i]) {
                // every contribution's three degrees here are one double: so are their accumulations
                double v = 0;
                for (int j = 0; j < act.n; j++) {
                    int at = j * nb + i;
                    v = max ? Math.max(v, cv[at]) : v + cv[at];
                }
                aL[i] = v;
                aV[i] = v;
                aR[i] = v;
                continue;
            }
            double l = 0;
            double v = 0;
            double r = 0;
            for (int j = 0; j < act.n; j++) {
                int at = j * nb + i;
                l = max ? Math.max(l, cl[at]) : l + cl[at];
                v = max ? Math.max(v, cv[at]) : v + cv[at];
                r = max ? Math.max(r, cr[at]) : r + cr[at];
            }
            aL[i] = l;
            aV[i] = v;
            aR[i] = r;
        }
    }

    private void interior(int i, AccumulationMethod accu) {
        if (accu == AccumulationMethod.MAX && act.n > 1) {
            envelope(i);        // one contribution is its own envelope: no crossing
        } else if (accu == AccumulationMethod.BSUM) {
            double s0 = aR[i];
            double s1 = aL[i + 1];
            if ((s0 - 1) * (s1 - 1) < 0) {
                emitRaw(bx[i] + (bx[i + 1] - bx[i]) * (1 - s0) / (s1 - s0), 1.0);
            }
        }
    }

    /**
     * The corners of the upper envelope of the activated sets, all linear on (bx[i], bx[i+1]):
     * walk from the left, always switching to the line that overtakes the current one first.
     */
    private void envelope(int i) {
        double a = bx[i];
        double w = bx[i + 1] - a;
        int cur = 0;
        for (int j = 1; j < act.n; j++) {
            int at = j * nb;
            int best = cur * nb;
            if (cr[at + i] > cr[best + i] || cr[at + i] == cr[best + i] && cl[at + i + 1] > cl[best + i + 1]) {
                cur = j;
            }
        }
        double t0 = 0;
        for (int steps = 0; steps < act.n; steps++) {
            double fa = cr[cur * nb + i];
            double fb = cl[cur * nb + i + 1];
            double f0 = fa + (fb - fa) * t0;
            double bestT = 1;
            int next = -1;
            for (int j = 0; j < act.n; j++) {
                double ga = cr[j * nb + i];
                double gb = cl[j * nb + i + 1];
                double d1 = fb - gb;
                if (j == cur || d1 >= 0) {
                    continue;
                }
                double d0 = Math.max(0, f0 - (ga + (gb - ga) * t0));
                double t = t0 + (1 - t0) * d0 / (d0 - d1);
                if (t < bestT || t == bestT && next >= 0 && gb > cl[next * nb + i + 1]) {
                    bestT = t;
                    next = j;
                }
            }
            if (next < 0 || bestT >= 1) {
                return;
            }
            if (bestT > t0) {
                emitRaw(a + w * bestT, fa + (fb - fa) * bestT);
            }
            t0 = bestT;
            cur = next;
        }
    }

    private void emit(double u, double raw, AccumulationMethod accu) {
        emitRaw(u, accu == AccumulationMethod.BSUM ? Math.min(1.0, raw) : raw);
    }

    private void emitRaw(double u, double y) {
        if (np > 0 && px[np - 1] == u && py[np - 1] == y) {
            return;
        }
        if (np > 1 && py[np - 1] == y && py[np - 2] == y) {
            px[np - 1] = u; // a flat run needs only its two ends
            return;
        }
        if (np == px.length) {
            px = Arrays.copyOf(px, 2 * np);
            py = Arrays.copyOf(py, 2 * np);
        }
        px[np] = u;
        py[np] = y;
        np++;
    }

    /** NSUM (Table 5): divide by max(1, the largest sum), which sits at a vertex. */
    private void normalize() {
        double max = 1.0;
        for (int j = 0; j < np; j++) {
            max = Math.max(max, py[j]);
        }
        for (int j = 0; j < np; j++) {
            py[j] /= max;
        }
    }
}
