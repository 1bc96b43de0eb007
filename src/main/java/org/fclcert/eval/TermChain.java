package org.fclcert.eval;

import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.model.AccumulationMethod;

/**
 * The terms of an output that form a chain (the usual layout of a fuzzy partition): constant points, degrees in
 * [0, 1], each term rising then falling (unimodal), ordered so that a term's support meets only its neighbours'
 * and two neighbours overlap only where the left one falls and the right one rises; only the first term may stay
 * positive to the left (a shoulder) and only the last to the right. Under MAX accumulation of MIN- or PROD-
 * activated contributions, at most two activated sets are positive at any u and where two are, the left one
 * does not rise and the right one does not fall, so they cross at most once: {@link SetBuilder#buildChain}
 * builds the upper envelope from each contribution's own vertices and one crossing per overlap, instead of
 * evaluating every contribution at every breakpoint.
 */
final class TermChain {
    /**
     * Per shape index s of the plan, at s − base (the arrays span the output's shapes only, not the plan's): its place
     * in the chain (−1 when it is not one of the output's terms), the first and last point of its support (the points
     * around its positive run).
     */
    private final int base;
    private final int[] rank;
    private final int[] first;
    private final int[] last;

    private TermChain(int base, int[] rank, int[] first, int[] last) {
        this.base = base;
        this.rank = rank;
        this.first = first;
        this.last = last;
    }

    /** Shape s's place in the chain, −1 when it is not one of the output's terms. */
    int rank(int s) {
        int i = s - base;
        return i >= 0 && i < rank.length ? rank[i] : -1;
    }

    /** The first point of shape s's support (s one of the chain's terms). */
    int first(int s) {
        return first[s - base];
    }

    /** The last point of shape s's support (s one of the chain's terms). */
    int last(int s) {
        return last[s - base];
    }

    /** The chain of o's terms, or null when they do not form one (or o is not a MAX accumulation of point terms). */
    static TermChain of(OutputPlan o, Shape[] shapes) {
        if (o.singletons() || o.accumulation() != AccumulationMethod.MAX) {
            return null;
        }
        int[] ts = o.termShapes();
        int m = ts.length;
        double[] start = new double[m];
        double[] end = new double[m];
        int[] rise = new int[m];
        int[] fall = new int[m];
        int lowest = Integer.MAX_VALUE;
        int highest = -1;
        for (int s : ts) {
            lowest = Math.min(lowest, s);
            highest = Math.max(highest, s);
        }
        if (m == 0 || highest - lowest >= 4 * m) {
            return null;            // the output's shapes far apart in the plan: not worth arrays over the span
        }
        int base = lowest;
        int[] rank = new int[highest - lowest + 1];
        int[] first = new int[rank.length];
        int[] last = new int[rank.length];
        java.util.Arrays.fill(rank, -1);
        Integer[] order = new Integer[m];
        for (int t = 0; t < m; t++) {
            Shape s = shapes[ts[t]];
            // (each term has a shape of its own, BlockCompiler: no shape twice in one output)
            if (s.singleton || !s.constant || s.kind != null || s.computed != null || s.n < 2) {
                return null;
            }
            double[] x = s.sortedX;
            double[] y = s.sortedY;
            int n = s.n;
            int f = -1;
            int l = -1;
            for (int i = 0; i < n; i++) {
                if (!(y[i] >= 0 && y[i] <= 1) || i > 0 && !(x[i] > x[i - 1])) {
                    return null;        // a degree out of [0, 1], a jump or a repeated point
                }
                if (y[i] > 0) {
                    f = f < 0 ? i : f;
                    l = i;
                }
            }
            int r = 0;
            while (r + 1 < n && y[r + 1] >= y[r]) {
                r++;
            }
            int d = n - 1;
            while (d > 0 && y[d - 1] >= y[d]) {
                d--;
            }
            if (f < 0 || d > r) {
                return null;            // never positive, or not unimodal
            }
            first[ts[t] - base] = Math.max(0, f - 1);
            last[ts[t] - base] = Math.min(n - 1, l + 1);
            start[t] = y[0] > 0 ? Double.NEGATIVE_INFINITY : x[first[ts[t] - base]];
            end[t] = y[n - 1] > 0 ? Double.POSITIVE_INFINITY : x[last[ts[t] - base]];
            rise[t] = r;
            fall[t] = d;
            order[t] = t;
        }
        java.util.Arrays.sort(order, (a, b) -> Double.compare(start[a], start[b]));
        for (int k = 0; k < m; k++) {
            int t = order[k];
            rank[ts[t] - base] = k;
            // (a shoulder inside the chain is refused below: its neighbour's overlap reaches past that one's slope)
            if (k + 2 < m && end[t] > start[order[k + 2]]) {
                return null;            // meets a term beyond its neighbour
            }
            if (k + 1 < m) {
                int b = order[k + 1];
                double[] xa = shapes[ts[t]].sortedX;
                double[] xb = shapes[ts[b]].sortedX;
                // the overlap (start b, end t) lies where t falls and b rises
                if (start[b] < end[t] && !(start[b] >= xa[fall[t]] && end[t] <= xb[rise[b]])) {
                    return null;
                }
            }
        }
        return new TermChain(base, rank, first, last);
    }
}
