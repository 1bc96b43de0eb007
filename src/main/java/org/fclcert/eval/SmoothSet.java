package org.fclcert.eval;

import java.util.Arrays;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DefuzzificationMethod;

/**
 * Defuzzification of an accumulated set that is not piece-wise linear: an output with a smooth named
 * shape (Gaussian, bell, ...), accumulated by PROBOR (a + b − ab of two linear pieces is quadratic) or by
 * another of the dialects' s-norms, or activated by a t-norm outside Table 4 (Einstein product, ...).
 * docs/semantics.md, "Named shapes, hedges and other dialect accumulations", states the method:
 *
 * <ul>
 * <li>The interval is split at every known non-smooth place: term points, the shapes' special points,
 *     and the places where a MIN clip level (or a kink of another activation) meets a term (exact for points,
 *     closed form for the shapes that invert simply). Kinks not known in advance (envelope crossings under MAX, a sum
 *     reaching 1 under BSUM) are handled by the adaptivity.</li>
 * <li>Each piece is integrated by adaptive Gauss–Kronrod (7/15 points), area and first moment
 *     together, bisecting a panel until |K15 − G7| ≤ 1e-13 · (its share of the interval) · (the largest
 *     degree seen) for both; the K15 value is kept. For smooth integrands K15 is many orders more
 *     accurate than that estimate.</li>
 * <li>CoA solves ∫ μ = half inside the panel that reaches it (safeguarded Newton, each step a K15
 *     integral of a sub-panel), from the left and from the right, and takes the mean of the two.</li>
 * <li>LM / RM: the supremum S from samples (2048 uniform, plus every split point) refined by golden-section
 *     search around each sampled local maximum; then LM = inf{u : μ(u) ≥ S(1 − 1e-12)} by bisection,
 *     RM = sup of that set. A peak narrower than the sample spacing that is not at a shape's special
 *     point can be missed.</li>
 * <li>MoM: S and the threshold S(1 − 1e-12) as for LM / RM; the set where μ reaches the threshold is
 *     collected as intervals (runs of samples at or above it, and peaks found by the golden-section
 *     refinement between two samples below it), each end located by bisection. As for a piece-wise
 *     linear set (Defuzzifier#meanOfMaximum): when some intervals are plateaus, longer than
 *     {@value #PLATEAU} of the interval [lo, hi], the length-weighted mean of the plateaus' midpoints;
 *     otherwise (only isolated maxima, such as the peaks of Gaussians) the mean of the intervals'
 *     midpoints, each counted once.</li>
 * </ul>
 * NSUM divides by one constant, which cancels in every method, so it is computed as SUM here.
 * Not thread-safe; one per output per instance; scratch arrays grow and are reused.
 */
final class SmoothSet {
    static final int SAMPLES = 2048;
    static final double TOLERANCE = 1e-13;
    /** Shortest plateau for MoM, as a share of the defuzzification interval; shorter runs count as points. */
    static final double PLATEAU = 1e-4;
    private static final int MAX_DEPTH = 50;

    /** The contributions added since the last clear. */
    final Activations act = new Activations();

    private Shape[] shapes;
    private double[][] cx;
    private double[][] cy;
    private AccumulationMethod accu;
    /** The s-norm of the dialects' other accumulations (ESUM, ...), else null. */
    private org.fclcert.model.OrAlgorithm sNorm;

    private double[] split = new double[16];
    private int nSplit;
    /** Accepted panels: ends and area, in order. */
    private double[] panelA = new double[64];
    private double[] panelB = new double[64];
    private double[] panelArea = new double[64];
    private int nPanels;
    private double area;
    private double moment;
    private double centre;
    private double tolArea;

    /** The accumulated degree at u (NSUM as SUM, see the class comment). */
    double degree(double u) {
        double acc = 0;
        for (int j = 0; j < act.n; j++) {
            int t = act.shape[j];
            Shape s = shapes[t];
            double mu = s.kind != null ? s.kind.degree(s.params, u) : Pwl.degree(cx[t], cy[t], s.n, u);
            double c = act.activate(j, mu);
            acc = switch (accu) {
                case MAX -> Math.max(acc, c);
                case BSUM, NSUM, SUM -> acc + c;
                case PROBOR -> acc + c - acc * c;
                case ESUM, HSUM, DSUM, NMAX -> Norms.or(sNorm, acc, c);
            };
        }
        return accu == AccumulationMethod.BSUM ? Math.min(1.0, acc) : acc;
    }

    /**
     * The defuzzified value over [lo, hi], NaN when the set is empty for the method (no area for CoG
     * and CoA, no positive degree for LM and RM). {@link #empty} tells which after the call.
     */
    double defuzzify(DefuzzificationMethod method, AccumulationMethod accumulation, double lo, double hi,
            Shape[] shapeTable, double[][] curX, double[][] curY) {
        this.shapes = shapeTable;
        this.cx = curX;
        this.cy = curY;
        this.accu = accumulation;
        this.sNorm = accumulation.otherNorm().orElse(null);
        lastEmpty = true;
        if (act.n == 0 || !(lo < hi)) {
            return Double.NaN;
        }
        splitPoints(lo, hi);
        return switch (method) {
            case LM -> extreme(lo, hi, true);
            case RM -> extreme(lo, hi, false);
            case COA -> {
                integrate(lo, hi);
                yield area > 0 ? centreOfArea() : Double.NaN;
            }
            case MOM -> meanOfMaximum(lo, hi);
            // BlockCompiler refuses COGSS on an output with point or shape terms, so none reaches a smooth set
            case COGSS -> throw new AssertionError("COGSS on a smooth set: BlockCompiler admits it only on singletons");
            default -> {
                integrate(lo, hi);
                yield area > 0 ? centre + moment / area : Double.NaN;
            }
        };
    }

    private boolean lastEmpty;

    /** Whether the last {@link #defuzzify} found the set empty for its method (point 6: DEFAULT). */
    boolean empty() {
        return lastEmpty;
    }

    double area() {
        return area;
    }

    // ---------------------------------------------------------------- split points

    private void splitPoints(double lo, double hi) {
        nSplit = 0;
        addSplit(lo, lo, hi);
        addSplit(hi, lo, hi);
        for (int j = 0; j < act.n; j++) {
            Shape s = shapes[act.shape[j]];
            if (s.kind != null) {
                for (double u : s.kind.specialPoints(s.params)) {
                    addSplit(u, lo, hi);
                }
                if (act.norm[j] != null) {
                    for (double k : act.kinkDegrees(j)) {
                        for (double u : s.kind.levelCrossings(s.params, k)) {
                            addSplit(u, lo, hi);
                        }
                    }
                } else if (!act.prod[j]) {
                    for (double u : s.kind.levelCrossings(s.params, act.level[j])) {
                        addSplit(u, lo, hi);
                    }
                }
            } else {
                double[] x = cx[act.shape[j]];
                double[] y = cy[act.shape[j]];
                for (int i = 0; i < s.n; i++) {
                    addSplit(x[i], lo, hi);
                }
                if (act.norm[j] != null) {
                    for (double k : act.kinkDegrees(j)) {
                        pointCrossings(x, y, s.n, k, lo, hi);
                    }
                } else if (!act.prod[j]) {
                    pointCrossings(x, y, s.n, act.level[j], lo, hi);
                }
            }
        }
        Arrays.sort(split, 0, nSplit);
        int m = 1;
        for (int i = 1; i < nSplit; i++) {
            if (split[i] != split[m - 1]) {
                split[m++] = split[i];
            }
        }
        nSplit = m;
    }

    /** Where a point term crosses a degree (a MIN clip level, a kink of another activation). */
    private void pointCrossings(double[] x, double[] y, int n, double level, double lo, double hi) {
        for (int i = 0; i + 1 < n; i++) {
            if ((y[i] - level) * (y[i + 1] - level) < 0 && x[i + 1] > x[i]) {
                addSplit(x[i] + (x[i + 1] - x[i]) * (level - y[i]) / (y[i + 1] - y[i]), lo, hi);
            }
        }
    }

    private void addSplit(double u, double lo, double hi) {
        if (!(u >= lo && u <= hi)) {
            return;
        }
        if (nSplit == split.length) {
            split = Arrays.copyOf(split, 2 * nSplit);
        }
        split[nSplit++] = u;
    }

    // ---------------------------------------------------------------- integration

    /** Gauss–Kronrod 7/15 abscissae (QUADPACK qk15), the Kronrod weights, and the Gauss weights. */
    private static final double[] XGK = {
        0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
        0.207784955007898467600689403773245, 0.0};
    private static final double[] WGK = {
        0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
    private static final double[] WG = {
        0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
        0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

    private final double[] panel = new double[4];

    /** K15 of μ and (u − centre)·μ on [a, b] into panel[0], panel[1]; G7 into panel[2], panel[3]. */
    private void kronrod(double a, double b) {
        double c = (a + b) / 2;
        double h = (b - a) / 2;
        double fc = degree(c);
        double k0 = fc * WGK[7];
        double k1 = fc * (c - centre) * WGK[7];
        double g0 = fc * WG[3];
        double g1 = fc * (c - centre) * WG[3];
        for (int j = 0; j < 7; j++) {
            double d = h * XGK[j];
            double u1 = c - d;
            double u2 = c + d;
            double f1 = degree(u1);
            double f2 = degree(u2);
            double s0 = f1 + f2;
            double s1 = f1 * (u1 - centre) + f2 * (u2 - centre);
            k0 += WGK[j] * s0;
            k1 += WGK[j] * s1;
            if (j % 2 == 1) {
                g0 += WG[j / 2] * s0;
                g1 += WG[j / 2] * s1;
            }
        }
        panel[0] = k0 * h;
        panel[1] = k1 * h;
        panel[2] = g0 * h;
        panel[3] = g1 * h;
    }

    private void integrate(double lo, double hi) {
        centre = (lo + hi) / 2;
        double scale = 0;
        for (int i = 0; i < nSplit; i++) {
            scale = Math.max(scale, degree(split[i]));
        }
        for (int i = 0; i <= 64; i++) {
            scale = Math.max(scale, degree(lo + (hi - lo) * i / 64));
        }
        area = 0;
        moment = 0;
        nPanels = 0;
        tolArea = TOLERANCE * Math.max(scale, Double.MIN_NORMAL);
        double width = hi - lo;
        for (int i = 0; i + 1 < nSplit; i++) {
            adapt(split[i], split[i + 1], width, 0);
        }
        lastEmpty = !(area > 0);
    }

    private void adapt(double a, double b, double width, int depth) {
        kronrod(a, b);
        double k0 = panel[0];
        double k1 = panel[1];
        boolean ok = Math.abs(k0 - panel[2]) <= tolArea * (b - a)
                && Math.abs(k1 - panel[3]) <= tolArea * (b - a) * width / 2;
        double m = (a + b) / 2;
        if (ok || depth >= MAX_DEPTH || !(m > a && m < b)) {
            area += k0;
            moment += k1;
            if (nPanels == panelA.length) {
                panelA = Arrays.copyOf(panelA, 2 * nPanels);
                panelB = Arrays.copyOf(panelB, 2 * nPanels);
                panelArea = Arrays.copyOf(panelArea, 2 * nPanels);
            }
            panelA[nPanels] = a;
            panelB[nPanels] = b;
            panelArea[nPanels] = k0;
            nPanels++;
            return;
        }
        adapt(a, m, width, depth + 1);
        adapt(m, b, width, depth + 1);
    }

    // ---------------------------------------------------------------- CoA

    private double centreOfArea() {
        double half = area / 2;
        double tol = area * 1e-14;
        return (halfArea(half, tol, true) + halfArea(half, tol, false)) / 2;
    }

    /**
     * The place where the area accumulated from the left (fromLeft) or from the right reaches half: a
     * panel end when a panel ends within tol of it, else solved inside the panel that reaches it. Called
     * only with area &gt; 0 and half = area / 2, so some panel always reaches it: the panel areas are K15
     * sums of degrees with positive weights (never negative), and the last panel brings cum to the whole
     * area (from the left by the very additions that made {@code area}; from the right the same terms in
     * reverse order, within n·ulp of it), which exceeds half.
     */
    private double halfArea(double half, double tol, boolean fromLeft) {
        double cum = 0;
        for (int i = 0; i < nPanels; i++) {
            int p = fromLeft ? i : nPanels - 1 - i;
            if (Math.abs(cum + panelArea[p] - half) <= tol) {
                return fromLeft ? panelB[p] : panelA[p];
            }
            if (cum + panelArea[p] > half) {
                return solve(panelA[p], panelB[p], half - cum, fromLeft);
            }
            cum += panelArea[p];
        }
        throw new AssertionError("no panel reaches half the area " + half + " of " + area);
    }

    /**
     * The t in [a, b] with ∫_a^t μ = target (fromLeft) or ∫_t^b μ = target; Newton steps (the derivative
     * is ±μ(t)) kept inside a shrinking bracket, bisection when a step leaves it.
     */
    private double solve(double a, double b, double target, boolean fromLeft) {
        double lo = a;
        double hi = b;
        double t = (a + b) / 2;
        for (int i = 0; i < 200 && hi - lo > Math.ulp(Math.abs(t)) * 4; i++) {
            kronrod(fromLeft ? a : t, fromLeft ? t : b);
            double g = panel[0] - target;         // increasing in t from the left, decreasing from the right
            if ((g > 0) == fromLeft) {
                hi = t;                           // from the left: too much area, t too far right
            } else {
                lo = t;
            }
            if (Math.abs(g) <= Math.abs(target) * 1e-15) {
                return t;
            }
            double mu = degree(t);
            double next = mu > 0 ? t - (fromLeft ? g : -g) / mu : Double.NaN;
            t = next > lo && next < hi ? next : (lo + hi) / 2;
        }
        return t;
    }

    // ---------------------------------------------------------------- LM / RM

    private double[] su = new double[SAMPLES + 64];
    private double[] sv = new double[SAMPLES + 64];
    /** Per sample interval [su[i], su[i+1]] next to a sampled local maximum: its refined maximum and place. */
    private double[] gv = new double[SAMPLES + 64];
    private double[] ga = new double[SAMPLES + 64];

    private int nSamples;

    /** Samples [lo, hi] into su / sv, refines next to each sampled local maximum; returns the supremum. */
    private double sampledSupremum(double lo, double hi) {
        int n = samples(lo, hi);
        nSamples = n;
        double sup = 0;
        for (int i = 0; i < n; i++) {
            sv[i] = degree(su[i]);
            gv[i] = -1;
            sup = Math.max(sup, sv[i]);
        }
        // refine next to every sampled local maximum (a run of equal values counts once, at its ends)
        for (int i = 0; i < n; i++) {
            int j = i;
            while (j + 1 < n && sv[j + 1] == sv[i]) {
                j++;
            }
            boolean peak = sv[i] > 0 && (i == 0 || sv[i - 1] <= sv[i]) && (j == n - 1 || sv[j + 1] <= sv[i]);
            if (peak) {
                if (i > 0) {
                    sup = Math.max(sup, refine(i - 1));
                }
                // inside the run a maximum can hide between two equal samples (two equal spikes' centres, split points
                // both): an interval whose midpoint rises above the run is refined too; a plateau's midpoints do not
                for (int k = i; k < j; k++) {
                    if (degree(0.5 * (su[k] + su[k + 1])) > sv[i]) {
                        sup = Math.max(sup, refine(k));
                    }
                }
                if (j + 1 < n) {
                    sup = Math.max(sup, refine(j));
                }
            }
            i = j;
        }
        return sup;
    }

    private double extreme(double lo, double hi, boolean leftmost) {
        double sup = sampledSupremum(lo, hi);
        int n = nSamples;
        if (!(sup > 0)) {
            return Double.NaN;
        }
        lastEmpty = false;
        double threshold = sup * (1 - Defuzzifier.TIE);
        if (leftmost) {
            for (int i = 0; i < n; i++) {
                if (sv[i] >= threshold) {
                    return i == 0 ? su[0] : boundary(su[i - 1], su[i], threshold);
                }
                if (i + 1 < n && gv[i] >= threshold) {
                    return boundary(su[i], ga[i], threshold);
                }
            }
        } else {
            for (int i = n - 1; i >= 0; i--) {
                if (sv[i] >= threshold) {
                    return i == n - 1 ? su[n - 1] : boundary(su[i + 1], su[i], threshold);
                }
                if (i > 0 && gv[i - 1] >= threshold) {
                    return boundary(su[i], ga[i - 1], threshold);
                }
            }
        }
        return Double.NaN;
    }

    /**
     * Mean of maximum on [lo, hi] (class comment): the set where μ reaches S(1 − 1e-12) as intervals; the
     * length-weighted mean of the plateaus' midpoints, or, without plateaus, the mean of the midpoints.
     */
    private double meanOfMaximum(double lo, double hi) {
        double sup = sampledSupremum(lo, hi);
        int n = nSamples;
        if (!(sup > 0)) {
            return Double.NaN;
        }
        lastEmpty = false;
        double threshold = sup * (1 - Defuzzifier.TIE);
        double plateau = PLATEAU * (hi - lo);
        double plateauLength = 0;
        double plateauMoment = 0;
        double pointSum = 0;
        int points = 0;
        double start = Double.NaN;
        for (int i = 0; i < n; i++) {
            double a = Double.NaN;
            double b = Double.NaN;
            if (sv[i] >= threshold) {
                if (Double.isNaN(start)) {
                    start = i == 0 ? su[0] : boundary(su[i - 1], su[i], threshold);
                }
                if (i == n - 1) {
                    a = start;
                    b = su[n - 1];
                }
            } else {
                if (!Double.isNaN(start)) {
                    a = start;
                    b = boundary(su[i], su[i - 1], threshold);
                    start = Double.NaN;
                }
                if (i + 1 < n && sv[i + 1] < threshold && gv[i] >= threshold) {
                    // a peak between two samples below the threshold (the refinement found it)
                    double pa = boundary(su[i], ga[i], threshold);
                    double pb = boundary(su[i + 1], ga[i], threshold);
                    if (pb - pa > plateau) {
                        plateauLength += pb - pa;
                        plateauMoment += (pb - pa) * (pa + pb) / 2;
                    }
                    pointSum += (pa + pb) / 2;
                    points++;
                }
            }
            if (!Double.isNaN(a)) {
                if (b - a > plateau) {
                    plateauLength += b - a;
                    plateauMoment += (b - a) * (a + b) / 2;
                }
                pointSum += (a + b) / 2;
                points++;
            }
        }
        if (plateauLength > 0) {
            return plateauMoment / plateauLength;
        }
        return points > 0 ? pointSum / points : Double.NaN;
    }

    /** SAMPLES + 1 uniform points and every split point, sorted, into su; returns their number. */
    private int samples(double lo, double hi) {
        int need = SAMPLES + 1 + nSplit;
        if (su.length < need) {
            su = new double[need];
            sv = new double[need];
            gv = new double[need];
            ga = new double[need];
        }
        int n = 0;
        int si = 0;
        for (int i = 0; i <= SAMPLES; i++) {
            double u = i == SAMPLES ? hi : lo + (hi - lo) * i / SAMPLES;
            while (si < nSplit && split[si] < u) {
                su[n++] = split[si++];
            }
            while (si < nSplit && split[si] == u) {
                si++;
            }
            su[n++] = u;
        }
        return n;
    }

    /** Golden-section maximum on the sample interval i, stored in gv[i] / ga[i]. */
    private double refine(int i) {
        if (gv[i] < 0) {
            gv[i] = golden(su[i], su[i + 1]);
            ga[i] = lastArgMax;
        }
        return gv[i];
    }

    private double lastArgMax;

    /** Golden-section search for the largest degree in [a, b]; returns it, its place in lastArgMax. */
    private double golden(double a, double b) {
        double best = Math.max(degree(a), degree(b));
        lastArgMax = degree(a) >= degree(b) ? a : b;
        final double r = (Math.sqrt(5) - 1) / 2;
        double x1 = b - r * (b - a);
        double x2 = a + r * (b - a);
        double f1 = degree(x1);
        double f2 = degree(x2);
        for (int i = 0; i < 80 && b - a > 1e-15 * Math.max(1, Math.abs(a)); i++) {
            if (f1 >= f2) {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - r * (b - a);
                f1 = degree(x1);
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + r * (b - a);
                f2 = degree(x2);
            }
        }
        double m = f1 >= f2 ? x1 : x2;
        double fm = Math.max(f1, f2);
        if (fm > best) {
            best = fm;
            lastArgMax = m;
        }
        return best;
    }

    /**
     * Bisection between {@code outside} (μ below the threshold) and {@code inside} (μ at or above it)
     * for the boundary of the set where μ reaches the threshold. Every caller passes as {@code outside} a
     * sample whose degree sv[i] it has just found below the threshold (the same doubles: μ is a pure
     * function here), so the bisection starts without evaluating μ there again.
     */
    private double boundary(double outside, double inside, double threshold) {
        double o = outside;
        double in = inside;
        for (int i = 0; i < 200 && Math.abs(in - o) > Math.ulp(Math.abs(in)) * 2; i++) {
            double m = (o + in) / 2;
            if (m == o || m == in) {
                break;
            }
            if (degree(m) >= threshold) {
                in = m;
            } else {
                o = m;
            }
        }
        return in;
    }
}
