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

    /**
     * Builds the vertices over [lo, hi] as {@link #build} does, for a MAX accumulation whose contributions lie on a
     * chain of terms ({@link TermChain}): each contribution's own vertices (its term's points and clip crossings
     * in the range, and the range's ends where they cut it) and, where two neighbours overlap, the one place where
     * the right one overtakes the left one. The same function as {@link #build}'s, with fewer vertices (a vertex
     * of a term where another one is higher is not one of the envelope's). Returns false, having built nothing,
     * when this step's contributions do not fit the chain (two on one term, an activation outside Table 4, a level
     * or weight not above 0): the caller then builds with {@link #build}.
     */
    boolean buildChain(TermChain chain, double lo, double hi, double[][] cx, double[][] cy) {
        return buildChain(chain, lo, hi, cx, cy, false, null);
    }

    /**
     * {@link #buildChain(TermChain, double, double, double[][], double[][])}; {@code inOrder} when the caller added
     * the contributions in the chain's order, at most one per term, each MIN or PROD with level and weight above 0
     * (the static filter's chain outputs, whose terms have one rule each): then they are not sorted nor checked.
     * {@code staging}, when not null, stages each contribution's vertices in place of {@link #contributionVertices}.
     */
    boolean buildChain(TermChain chain, double lo, double hi, double[][] cx, double[][] cy, boolean inOrder,
            Staging staging) {
        np = 0;
        boolean built = chainVertices(chain, lo, hi, cx, cy, inOrder, staging);
        if (!built) {
            np = 0;
        }
        for (int j = np; j < np + 2 && j < py.length; j++) {
            py[j] = 0.0;
        }
        return built;
    }

    /** Per contribution in chain order ({@code order}): its vertices in qx/qy from qFrom[k] to qFrom[k + 1]. */
    private int[] order = new int[4];
    private int[] qFrom = new int[5];
    private double[] qx = new double[32];
    private double[] qy = new double[32];
    private int nq;

    /**
     * {@link #contributionVertices} written out for the terms of one plan's chains, the terms' points, the support's
     * ends and the range's as constants (the static filter's generated code, {@code StaticFilter.stage}).
     */
    interface Staging {
        /**
         * The vertices of the contribution of shape s activated at (level, w, MIN or PROD) over the plan's interval for
         * that output, into vx and vy from q on (room made by the caller); the new q, or −1 for a shape it does not know.
         */
        int stage(int s, double level, double w, boolean prod, double[] vx, double[] vy, int q);
    }

    private boolean chainVertices(TermChain chain, double lo, double hi, double[][] cx, double[][] cy,
            boolean inOrder, Staging staging) {
        int n = act.n;
        if (n == 0 || !(lo < hi)) {
            return true;
        }
        if (order.length < n) {
            order = new int[2 * n];
            qFrom = new int[2 * n + 1];
        }
        for (int j = 0; j < n && !inOrder; j++) {
            int r = chain.rank(act.shape[j]);
            if (r < 0 || act.norm[j] != null || !(act.level[j] > 0) || !(act.weight[j] > 0)) {
                return false;
            }
            int k = j;
            while (k > 0 && chain.rank(act.shape[order[k - 1]]) > r) {
                order[k] = order[k - 1];
                k--;
            }
            if (k > 0 && chain.rank(act.shape[order[k - 1]]) == r) {
                return false;
            }
            order[k] = j;
        }
        nq = 0;
        rangeLo = lo;
        rangeHi = hi;
        for (int k = 0; k < n; k++) {
            qFrom[k] = nq;
            int j = inOrder ? k : order[k];
            int s = act.shape[j];
            int f = chain.first(s);
            int l = chain.last(s);
            room(l - f);
            if (staging == null) {
                contributionVertices(j, cx[s], cy[s], f, l);
            } else if ((nq = staging.stage(s, act.level[j], act.weight[j], act.prod[j], qx, qy, nq)) < 0) {
                return false;
            }
        }
        qFrom[n] = nq;
        if (px.length < nq + n + 2) {        // every staged vertex, a crossing per overlap, the two ends
            px = Arrays.copyOf(px, 2 * (nq + n + 2));
            py = Arrays.copyOf(py, px.length);
        }
        if (nq == 0 || qx[0] > lo) {
            put(lo, 0.0);
        }
        int cur = -1;
        int next = 0;       // the current contribution's first vertex not yet emitted
        for (int k = 0; k < n; k++) {
            int b0 = qFrom[k];
            int b1 = qFrom[k + 1];
            if (b0 == b1) {
                continue;   // outside the range
            }
            if (cur < 0 || !(qx[b0] < qx[qFrom[cur + 1] - 1])) {
                // no overlap with the current one: all of it, then this one from its start
                emitVertices(next, cur < 0 ? 0 : qFrom[cur + 1], Double.POSITIVE_INFINITY);
                cur = k;
                next = b0;
                continue;
            }
            double us = overtake(qFrom[cur], qFrom[cur + 1], b0, b1);
            boolean overtaken = us == us;
            if (!overtaken && overtakeDegree != overtakeDegree) {
                return false;
            }
            if (!overtaken) {
                us = Double.POSITIVE_INFINITY;  // the left one stays above to the end of the range
            }
            emitVertices(next, qFrom[cur + 1], us);
            if (overtaken) {
                put(us, overtakeDegree);
            }
            next = b0;
            while (next < b1 && !(qx[next] > us)) {
                next++;
            }
            cur = k;
        }
        emitVertices(next, cur < 0 ? 0 : qFrom[cur + 1], Double.POSITIVE_INFINITY);
        if (np == 0 || px[np - 1] < hi) {
            put(hi, 0.0);
        }
        return true;
    }

    private void emitVertices(int from, int to, double before) {
        for (int i = from; i < to && qx[i] < before; i++) {
            put(qx[i], qy[i]);
        }
    }

    /**
     * Appends a vertex of the chain's set (at most one per staged vertex, the crossings and the two ends: the arrays
     * were sized for them); a vertex equal to the last adds nothing.
     */
    private void put(double u, double y) {
        int m = np;
        if (m > 0 && px[m - 1] == u && py[m - 1] == y) {
            return;
        }
        px[m] = u;
        py[m] = y;
        np = m + 1;
    }

    /**
     * Contribution j's vertices over the part of [lo, hi] where its term (points x, y; support from point f to
     * point l, or the range's end on a shoulder) may be positive: the ends of that part, the term's points and
     * its clip crossings inside it, each with its activated degree.
     */
    private void contributionVertices(int j, double[] x, double[] y, int f, int l) {
        double a = supportStart(x, y, f, rangeLo);
        double b = supportEnd(x, y, l, rangeHi);
        if (!(a < b)) {
            return;
        }
        int q = nq;
        double[] vx = qx;
        double[] vy = qy;
        // the activation of a chain's contribution is Table 4's MIN or PROD (buildChain declines any other)
        double level = act.level[j];
        double w = act.weight[j];
        boolean prod = act.prod[j];
        // the ends: at the support's end point its degree, where the range cuts the term Pwl.degree's interpolation
        vx[q] = a;
        vy[q++] = Activations.activate(w, level, prod, degreeAt(x, y, f, a));
        double x0 = x[f];
        double y0 = y[f];
        // a point above a MIN level lies on the clipped plateau, which its neighbours bound: not a vertex
        if (x0 > a && x0 < b && (prod || !(y0 > level))) {
            vx[q] = x0;
            vy[q++] = Activations.activate(w, level, prod, y0);
        }
        for (int i = f + 1; i <= l; i++) {
            double x1 = x[i];
            double y1 = y[i];
            if (!prod) {
                double c = crossing(x0, y0, x1, y1, level);
                if (c > a && c < b) {
                    // a clip crossing: the term's degree there is the level, exactly
                    vx[q] = c;
                    vy[q++] = Activations.activate(w, level, false, level);
                }
            }
            if (x1 > a && x1 < b && (prod || !(y1 > level))) {
                vx[q] = x1;
                vy[q++] = Activations.activate(w, level, prod, y1);
            }
            x0 = x1;
            y0 = y1;
        }
        vx[q] = b;
        vy[q++] = Activations.activate(w, level, prod, degreeAt(x, y, l, b));
        nq = q;
    }

    /** Room in qx, qy for one more contribution of that many pieces (point f to l): its points, crossings and ends. */
    private void room(int pieces) {
        if (qx.length < nq + 2 * pieces + 4) {
            qx = Arrays.copyOf(qx, 2 * (nq + 2 * pieces + 4));
            qy = Arrays.copyOf(qy, qx.length);
        }
    }

    /**
     * Where a contribution's vertices start over [lo, ...]: the range's start on a left shoulder (a term positive at
     * its first point), else the later of it and the support's first point f.
     */
    static double supportStart(double[] x, double[] y, int f, double lo) {
        return y[0] > 0 ? lo : Math.max(lo, x[f]);
    }

    /** Where they end: the range's end on a right shoulder, else the earlier of it and the support's last point l. */
    static double supportEnd(double[] x, double[] y, int l, double hi) {
        return y[y.length - 1] > 0 ? hi : Math.min(hi, x[l]);
    }

    /** The term's degree at u, an end of its support's part: point i's own at that point, else Pwl.degree's. */
    static double degreeAt(double[] x, double[] y, int i, double u) {
        return u == x[i] ? y[i] : Pwl.degree(x, y, x.length, u);
    }

    /** The range of the set {@link #buildChain} is building. */
    private double rangeLo;
    private double rangeHi;

    /** The degree at the place {@link #overtake} returned. */
    private double overtakeDegree;

    /**
     * Where contribution b (vertices b0 to b1, starting inside contribution a's vertices a0 to a1) overtakes a:
     * the first u where a is no longer above b, found piece by piece over both one's vertices (a falls and b rises
     * there, so they cross once), its degree into {@link #overtakeDegree}; the crossing inside a piece by
     * {@link #envelope}'s formula. NaN when a stays above b to its last vertex (and NaN as the degree too when b
     * does not start inside a's vertices, which the chain's order rules out: the caller declines). A degree at a vertex of a
     * contribution is that vertex's; between two of its vertices, where it is linear, their interpolation.
     */
    private double overtake(int a0, int a1, int b0, int b1) {
        overtakeDegree = 0;
        double u0 = qx[b0];
        int ia = a0;
        while (ia < a1 && qx[ia] < u0) {
            ia++;
        }
        if (ia == a1 || ia == a0 && qx[ia] != u0) {
            overtakeDegree = Double.NaN;    // b does not start inside a (the chain's order rules it out): declined
            return Double.NaN;
        }
        double f0 = qx[ia] == u0 ? qy[ia++] : between(ia, u0);
        double g0 = qy[b0];
        if (!(f0 > g0)) {
            overtakeDegree = g0;
            return u0;
        }
        int ib = b0 + 1;
        while (ia < a1 && ib < b1) {
            double u1 = Math.min(qx[ia], qx[ib]);
            double f1 = qx[ia] == u1 ? qy[ia] : between(ia, u1);
            double g1 = qx[ib] == u1 ? qy[ib] : between(ib, u1);
            if (!(f1 > g1)) {
                if (f1 == g1) {
                    overtakeDegree = f1;
                    return u1;
                }
                double d0 = f0 - g0;
                double t = d0 / (d0 - (f1 - g1));
                double u = Math.min(u1, Math.max(u0, u0 + (u1 - u0) * t));
                overtakeDegree = f0 + (f1 - f0) * t;
                return u;
            }
            if (qx[ia] == u1) {
                ia++;
            }
            if (qx[ib] == u1) {
                ib++;
            }
            u0 = u1;
            f0 = f1;
            g0 = g1;
        }
        return Double.NaN;
    }

    /** The degree at u of the staged polyline between its vertices i − 1 and i (u strictly between them). */
    private double between(int i, double u) {
        return Pwl.interpolate(qx[i - 1], qy[i - 1], qx[i], qy[i], u);
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
            double u = crossing(x[i], y[i], x[i + 1], y[i + 1], level);
            if (u > lo && u < hi) {
                addBreakpoint(u);
                if (nc == crossU.length) {
                    crossU = Arrays.copyOf(crossU, 2 * nc);
                }
                crossU[nc++] = u;
            }
        }
        crossEnd[j] = nc;
    }

    /**
     * Where a MIN clip level crosses the segment from (x0, y0) to (x1, y1) strictly inside it, or NaN: a crossing
     * that rounds onto an end is kept one ulp inside, so the piece beyond stays a plateau (NaN when there is no
     * double inside).
     */
    static double crossing(double x0, double y0, double x1, double y1, double level) {
        if (!((y0 - level) * (y1 - level) < 0 && x1 > x0)) {
            return Double.NaN;
        }
        double dy = y1 - y0;
        double p = (x1 - x0) * (level - y0);
        // on a piece from degree 0 to 1 or back (the usual) the quotient by ±1 is p or −p exactly: no division
        double u = x0 + (dy == 1 ? p : dy == -1 ? -p : p / dy);
        if (!(u < x1)) {
            u = Math.nextDown(x1);
        }
        if (!(u > x0)) {
            u = Math.nextUp(x0);
        }
        return u > x0 && u < x1 ? u : Double.NaN;
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
