package org.fclcert.eval;

/**
 * Fuzzification (5.2.2) of a block's input terms with constant points, compiled for {@link CompiledEvaluator}.
 * Terms are grouped by shape so that each group runs in a loop without data-dependent branches:
 *
 * <ul>
 *   <li><b>unimodal</b> (in three runs: ramps up, ramps down, both edges): points with strictly ascending x whose degrees are 0, then 1, then 0 (either run of
 *       zeros may be missing) — triangles, trapezoids, shoulders, the usual fuzzy partitions. The degree is
 *       max(0, min(1, (u − a)/(b − a), (d − u)/(d − c))) for the rising edge (a, 0)–(b, 1) and the falling
 *       edge (c, 1)–(d, 0); a missing edge is an infinite a or d, which makes its quotient +∞. Inside an
 *       edge these are the very operations {@link Pwl#interpolate} performs (the other degree's product is
 *       an exact 0), so the degrees are bit for bit the reference's;</li>
 *   <li><b>singletons</b>: 1 at their value, else 0;</li>
 *   <li><b>other points</b>: {@link Pwl#degree}'s walk over the points.</li>
 * </ul>
 */
final class TermDegrees {
    /** Number of terms; degrees are written to {@code deg[0..count)} by term index. */
    final int count;

    private final int[] uniTerm;
    private final int[] uniSlot;
    private final double[] uniA;
    private final double[] uniRise;
    private final double[] uniD;
    private final double[] uniFall;
    /** Per unimodal term: where its rising edge reaches 1 (b). */
    private final double[] uniTop;
    /** Per unimodal term: its rising edge ends where its falling edge starts (b = c, a triangle). */
    private final boolean[] peak;
    /** uni[0, risingEnd) only rise, uni[risingEnd, fallingEnd) only fall, the rest have both edges. */
    private int risingEnd;
    private int fallingEnd;

    private final int[] singleTerm;
    private final int[] singleSlot;
    private final double[] singleX;

    private final int[] otherTerm;
    private final int[] otherSlot;
    private final double[][] otherX;
    private final double[][] otherY;

    TermDegrees(BlockPlan plan) {
        count = plan.termShape.length;
        int uni = 0;
        int single = 0;
        for (int t = 0; t < count; t++) {
            Shape s = plan.shapes[plan.termShape[t]];
            if (s.singleton) {
                single++;
            } else if (Edges.of(s.sortedX, s.sortedY, s.n) != null) {
                uni++;
            }
        }
        uniTerm = new int[uni];
        uniSlot = new int[uni];
        uniA = new double[uni];
        uniRise = new double[uni];
        uniD = new double[uni];
        uniFall = new double[uni];
        uniTop = new double[uni];
        peak = new boolean[uni];
        singleTerm = new int[single];
        singleSlot = new int[single];
        singleX = new double[single];
        int other = count - uni - single;
        otherTerm = new int[other];
        otherSlot = new int[other];
        otherX = new double[other][];
        otherY = new double[other][];
        int u = 0;
        int g = 0;
        int o = 0;
        // unimodal terms in three runs: rising only (ramps up), falling only (ramps down), both
        for (int kind = 0; kind < 3; kind++) {
            for (int t = 0; t < count; t++) {
                Shape s = plan.shapes[plan.termShape[t]];
                Edges e = s.singleton ? null : Edges.of(s.sortedX, s.sortedY, s.n);
                if (e != null && e.kind() == kind) {
                    uniTerm[u] = t;
                    uniSlot[u] = plan.termVariableSlot[t];
                    uniA[u] = e.a;
                    uniRise[u] = e.rise;
                    uniD[u] = e.d;
                    uniTop[u] = e.b;
                    peak[u] = e.b == e.c;
                    uniFall[u++] = e.fall;
                }
            }
            if (kind == 0) {
                risingEnd = u;
            } else if (kind == 1) {
                fallingEnd = u;
            }
        }
        for (int t = 0; t < count; t++) {
            Shape s = plan.shapes[plan.termShape[t]];
            int slot = plan.termVariableSlot[t];
            Edges e = s.singleton ? null : Edges.of(s.sortedX, s.sortedY, s.n);
            if (s.singleton) {
                singleTerm[g] = t;
                singleSlot[g] = slot;
                singleX[g++] = s.sortedX[0];
            } else if (e != null) {
                continue;
            } else {
                otherTerm[o] = t;
                otherSlot[o] = slot;
                otherX[o] = s.sortedX;
                otherY[o++] = s.sortedY;
            }
        }
    }

    /** Writes the degree of every term at the current variable values. */
    void fuzzify(double[] values, double[] deg) {
        final int[] term = uniTerm;
        final int[] slot = uniSlot;
        final double[] a = uniA;
        final double[] rise = uniRise;
        final double[] d = uniD;
        final double[] fall = uniFall;
        for (int k = 0; k < risingEnd; k++) {
            deg[term[k]] = Math.max(0.0, Math.min(1.0, (values[slot[k]] - a[k]) / rise[k]));
        }
        for (int k = risingEnd; k < fallingEnd; k++) {
            deg[term[k]] = Math.max(0.0, Math.min(1.0, (d[k] - values[slot[k]]) / fall[k]));
        }
        for (int k = fallingEnd; k < term.length; k++) {
            double u = values[slot[k]];
            double m = Math.min((u - a[k]) / rise[k], (d[k] - u) / fall[k]);
            deg[term[k]] = Math.max(0.0, Math.min(1.0, m));
        }
        fuzzifyOthers(values, deg);
    }

    /** The degrees of the singletons and the other point terms only (the unimodal ones are generated code's). */
    void fuzzifyOthers(double[] values, double[] deg) {
        for (int k = 0; k < singleTerm.length; k++) {
            deg[singleTerm[k]] = values[singleSlot[k]] == singleX[k] ? 1.0 : 0.0;
        }
        for (int k = 0; k < otherTerm.length; k++) {
            double[] x = otherX[k];
            deg[otherTerm[k]] = Pwl.degree(x, otherY[k], x.length, values[otherSlot[k]]);
        }
    }

    /**
     * Emits, for {@link MinMaxKernel}, the <em>unclamped</em> degree q of every unimodal term into the double
     * local {@code local[term]}: (u − a)/(b − a), (d − u)/(d − c), or the lesser of the two, the very
     * quotients {@link #fuzzify} computes before clamping; its degree is max(0, min(1, q)). {@code tmp} and
     * {@code tmp + 2} are scratch locals. Values are in {@code aload_1}.
     */
    void emitUnimodal(ClassFile.Code c, int[] local, int tmp) {
        for (int k = 0; k < uniTerm.length; k++) {
            boolean rises = k < risingEnd || k >= fallingEnd;
            boolean falls = k >= risingEnd;
            int to = local[uniTerm[k]];
            if (rises && falls) {
                // one division instead of two and their minimum: up to b the rising quotient is at most 1 and the
                // falling one at least 1 (rounding is monotonic and rise = b − a, fall = d − c as computed here),
                // beyond b the other way round or, on a plateau, both above 1, which the rule's clamp makes 1
                loadValue(c, uniSlot[k]);
                c.local(ClassFile.DSTORE, tmp);
                c.edgeQuotient(tmp, uniTop[k], uniA[k], uniRise[k], uniD[k], uniFall[k]);
                c.local(ClassFile.DSTORE, to);
            } else if (rises) {
                loadValue(c, uniSlot[k]);
                c.doubleConst(uniA[k]);
                c.op(ClassFile.DSUB);
                c.doubleConst(uniRise[k]);
                c.op(ClassFile.DDIV);
                c.local(ClassFile.DSTORE, to);
            } else {
                c.doubleConst(uniD[k]);
                loadValue(c, uniSlot[k]);
                c.op(ClassFile.DSUB);
                c.doubleConst(uniFall[k]);
                c.op(ClassFile.DDIV);
                c.local(ClassFile.DSTORE, to);
            }
        }
    }

    /**
     * Whether term t's unclamped quotient from {@link #emitUnimodal} never exceeds 1: a rising and a falling
     * edge meeting at one peak (a triangle), or a term whose degree is read clamped.
     */
    boolean[] atMostOne() {
        boolean[] m = new boolean[count];
        java.util.Arrays.fill(m, true);
        for (int k = 0; k < uniTerm.length; k++) {
            m[uniTerm[k]] = k >= fallingEnd && peak[k];
        }
        return m;
    }

    /** Whether some term is a singleton or other points (whose degrees {@link #fuzzifyOthers} computes). */
    boolean hasOthers() {
        return singleTerm.length + otherTerm.length > 0;
    }

    /** Whether term t's degree is computed by {@link #emitUnimodal} (else it is read from the degree array). */
    boolean[] unimodal() {
        boolean[] u = new boolean[count];
        for (int t : uniTerm) {
            u[t] = true;
        }
        return u;
    }

    private static void loadValue(ClassFile.Code c, int slot) {
        c.op(ClassFile.ALOAD_1);
        c.intConst(slot);
        c.op(ClassFile.DALOAD);
    }

    /**
     * The two edges of a unimodal 0/1 shape: rising from (a, 0) over a width {@code rise} to degree 1, falling
     * from degree 1 over a width {@code fall} to (d, 0); a = −∞ (d = +∞) where the shape starts (ends) at 1,
     * with width 1 so that the quotient is +∞. Null for any other shape, and for widths that overflow.
     */
    record Edges(double a, double rise, double d, double fall, double b, double c) {
        /** 0: rises only (ends at degree 1), 1: falls only (starts at degree 1), 2: both. */
        int kind() {
            return d == Double.POSITIVE_INFINITY ? 0 : a == Double.NEGATIVE_INFINITY ? 1 : 2;
        }

        static Edges of(double[] x, double[] y, int n) {
            for (int i = 0; i < n; i++) {
                if (!(y[i] == 0.0 || y[i] == 1.0) || !Double.isFinite(x[i]) || i > 0 && !(x[i] > x[i - 1])) {
                    return null;
                }
            }
            int first = 0;
            while (first < n && y[first] == 0.0) {
                first++;
            }
            int last = n - 1;
            while (last >= 0 && y[last] == 0.0) {
                last--;
            }
            if (first > last) {
                return null;            // all zero
            }
            for (int i = first; i <= last; i++) {
                if (y[i] != 1.0) {
                    return null;        // a dip inside: not unimodal
                }
            }
            double a = first == 0 ? Double.NEGATIVE_INFINITY : x[first - 1];
            double rise = first == 0 ? 1.0 : x[first] - x[first - 1];
            double d = last == n - 1 ? Double.POSITIVE_INFINITY : x[last + 1];
            double fall = last == n - 1 ? 1.0 : x[last + 1] - x[last];
            if (!Double.isFinite(rise) || !Double.isFinite(fall)) {
                return null;            // a segment wider than the largest double: Pwl halves it
            }
            return new Edges(a, rise, d, fall, x[first], x[last]);
        }
    }
}
