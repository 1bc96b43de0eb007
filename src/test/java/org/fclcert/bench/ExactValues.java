package org.fclcert.bench;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

/**
 * The exact outputs of the {@link PeerPrograms}, computed independently of fclcert's evaluator: straight
 * from the definitions (degrees by linear interpolation, MIN/MAX, CoGS as Σ v·μ / Σ μ, CoG as ∫u·μ / ∫μ)
 * in 60-digit decimal arithmetic. The accumulated CoG set max_k min(l_k, μ_k(u)) is integrated piece by
 * piece between a superset of its breakpoints: every term point and every crossing of any two of the
 * lines it is made of (term segments, their constant continuations and clip levels), on each of which it
 * is linear, so the trapezoid formulas are exact there. The error of the result is about 1e-55.
 */
final class ExactValues {
    private static final MathContext MC = new MathContext(60);
    private static final BigDecimal TWO = BigDecimal.valueOf(2);
    private static final BigDecimal SIX = BigDecimal.valueOf(6);

    private ExactValues() {
    }

    static BigDecimal d(double v) {
        return new BigDecimal(v);
    }

    /** Piece-wise linear membership: linear between points, constant beyond the outer points. */
    static BigDecimal pwl(double[] x, double[] y, BigDecimal u) {
        int n = x.length;
        if (u.compareTo(d(x[0])) <= 0) {
            return d(y[0]);
        }
        if (u.compareTo(d(x[n - 1])) >= 0) {
            return d(y[n - 1]);
        }
        for (int i = 1; i < n; i++) {
            if (u.compareTo(d(x[i])) <= 0) {
                BigDecimal t = u.subtract(d(x[i - 1])).divide(d(x[i]).subtract(d(x[i - 1])), MC);
                return d(y[i - 1]).add(t.multiply(d(y[i]).subtract(d(y[i - 1])), MC), MC);
            }
        }
        throw new AssertionError();
    }

    private static BigDecimal min(BigDecimal a, BigDecimal b) {
        return a.compareTo(b) <= 0 ? a : b;
    }

    private static BigDecimal max(BigDecimal a, BigDecimal b) {
        return a.compareTo(b) >= 0 ? a : b;
    }

    /** The 5.3 valve: singletons −100, 0, 100, AND MIN, ACCU MAX, rule 2 WITH 0.8, CoGS; DEFAULT 0. */
    static double valve(double temp, double pressure) {
        BigDecimal t = d(temp);
        BigDecimal p = d(pressure);
        BigDecimal cold = pwl(new double[] {3, 27}, new double[] {1, 0}, t);
        BigDecimal hot = pwl(new double[] {3, 27}, new double[] {0, 1}, t);
        BigDecimal low = pwl(new double[] {55, 95}, new double[] {1, 0}, p);
        BigDecimal high = pwl(new double[] {55, 95}, new double[] {0, 1}, p);
        BigDecimal inlet = min(cold, low);
        BigDecimal closed = max(new BigDecimal("0.8").multiply(min(cold, high)), min(hot, low));
        BigDecimal drainage = min(hot, high);
        BigDecimal den = inlet.add(closed).add(drainage);
        if (den.signum() == 0) {
            return 0;
        }
        BigDecimal num = BigDecimal.valueOf(100).multiply(inlet).subtract(BigDecimal.valueOf(100).multiply(drainage));
        return num.divide(den, MC).doubleValue();
    }

    /** The three-rule system: each input term's degree clips its output triangle. */
    static double cog3(double x) {
        BigDecimal u = d(x);
        double[][] in = {{0, 2, 5}, {2, 5, 8}, {5, 8, 10}};
        double[][] out = {{0, 20, 40}, {30, 50, 70}, {60, 80, 100}};
        List<Clipped> sets = new ArrayList<>();
        for (int k = 0; k < 3; k++) {
            BigDecimal level = pwl(in[k], new double[] {0, 1, 0}, u);
            sets.add(new Clipped(out[k], level));
        }
        return centreOfGravity(sets, 0, 100);
    }

    /** The 125-rule system: rule (i, j, k) fires at min of the three degrees; ACCU MAX per output term. */
    static double rules125(double a, double b, double c) {
        BigDecimal[][] deg = new BigDecimal[3][5];
        double[] in = {a, b, c};
        for (int v = 0; v < 3; v++) {
            for (int k = 0; k < 5; k++) {
                deg[v][k] = pwl(PeerPrograms.inputTriangle(k), new double[] {0, 1, 0}, d(in[v]));
            }
        }
        BigDecimal[] level = new BigDecimal[5];
        java.util.Arrays.fill(level, BigDecimal.ZERO);
        for (int i = 0; i < 5; i++) {
            for (int j = 0; j < 5; j++) {
                for (int k = 0; k < 5; k++) {
                    int o = PeerPrograms.conclusion(i, j, k);
                    level[o] = max(level[o], min(deg[0][i], min(deg[1][j], deg[2][k])));
                }
            }
        }
        List<Clipped> sets = new ArrayList<>();
        for (int o = 0; o < 5; o++) {
            sets.add(new Clipped(PeerPrograms.outputTriangle(o), level[o]));
        }
        return centreOfGravity(sets, 0, 100);
    }

    /** A triangle (feet x[0], x[2], peak x[1]) clipped at a level (ACT MIN). */
    record Clipped(double[] x, BigDecimal level) {
        BigDecimal at(BigDecimal u) {
            return min(level, pwl(x, new double[] {0, 1, 0}, u));
        }
    }

    /** A line y = a + b·u. */
    private record Line(BigDecimal a, BigDecimal b) {
    }

    private static BigDecimal mu(List<Clipped> sets, BigDecimal u) {
        BigDecimal m = BigDecimal.ZERO;
        for (Clipped s : sets) {
            m = max(m, s.at(u));
        }
        return m;
    }

    /** ∫u·μ / ∫μ over [lo, hi] for μ = max of the clipped sets; 0 (the DEFAULT) when the area is 0. */
    static double centreOfGravity(List<Clipped> sets, double lo, double hi) {
        List<Line> lines = new ArrayList<>();
        TreeSet<BigDecimal> cuts = new TreeSet<>();
        BigDecimal l = d(lo);
        BigDecimal h = d(hi);
        cuts.add(l);
        cuts.add(h);
        for (Clipped s : sets) {
            lines.add(new Line(s.level(), BigDecimal.ZERO));
            lines.add(new Line(BigDecimal.ZERO, BigDecimal.ZERO));
            for (int i = 0; i < 3; i++) {
                cuts.add(d(s.x()[i]));
            }
            for (int i = 0; i + 1 < 3; i++) {
                BigDecimal x0 = d(s.x()[i]);
                BigDecimal x1 = d(s.x()[i + 1]);
                BigDecimal y0 = i == 0 ? BigDecimal.ZERO : BigDecimal.ONE;
                BigDecimal y1 = i == 0 ? BigDecimal.ONE : BigDecimal.ZERO;
                BigDecimal slope = y1.subtract(y0).divide(x1.subtract(x0), MC);
                lines.add(new Line(y0.subtract(slope.multiply(x0), MC), slope));
            }
        }
        for (int i = 0; i < lines.size(); i++) {
            for (int j = i + 1; j < lines.size(); j++) {
                BigDecimal db = lines.get(i).b().subtract(lines.get(j).b());
                if (db.signum() != 0) {
                    cuts.add(lines.get(j).a().subtract(lines.get(i).a()).divide(db, MC));
                }
            }
        }
        BigDecimal area = BigDecimal.ZERO;
        BigDecimal moment = BigDecimal.ZERO;
        BigDecimal prev = null;
        BigDecimal mPrev = null;
        for (BigDecimal u : cuts.subSet(l, true, h, true)) {
            BigDecimal m = mu(sets, u);
            if (prev != null) {
                BigDecimal w = u.subtract(prev);
                area = area.add(w.multiply(mPrev.add(m)).divide(TWO, MC), MC);
                moment = moment.add(w.multiply(prev.multiply(TWO.multiply(mPrev).add(m))
                        .add(u.multiply(mPrev.add(TWO.multiply(m)))), MC).divide(SIX, MC), MC);
            }
            prev = u;
            mPrev = m;
        }
        return area.signum() == 0 ? 0 : moment.divide(area, MC).doubleValue();
    }
}
