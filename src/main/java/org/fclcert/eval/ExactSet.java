package org.fclcert.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.fclcert.model.AccumulationMethod;

/**
 * The accumulated set of one output with point terms in exact rational arithmetic (the judging path's
 * counterpart of {@link SetBuilder}, same construction: breakpoints at term points, interval ends and MIN clip
 * crossings; upper-envelope corners under MAX, the crossing of 1 under BSUM), and its defuzzification
 * (Tables 1, 2) with every comparison exact: which pieces a clip level crosses, which vertices reach the
 * supremum (LM, RM, MoM), whether there is area, where half the area is reached (CoA). Only CoA's final
 * quadratic root can be irrational; it is then computed to 60 significant digits.
 */
final class ExactSet {
    /** One activated contribution: the term's current points, level, weight, PROD or MIN. */
    record Contribution(Rational[] x, Rational[] y, Rational level, Rational weight, boolean prod) {
        Rational activate(Rational mu) {
            return weight.multiply(prod ? level.multiply(mu) : level.min(mu));
        }
    }

    final List<Rational> px = new ArrayList<>();
    final List<Rational> py = new ArrayList<>();

    void build(AccumulationMethod accu, Rational lo, Rational hi, List<Contribution> cs) {
        px.clear();
        py.clear();
        if (cs.isEmpty() || lo.compareTo(hi) >= 0) {
            return;
        }
        TreeSet<Rational> points = new TreeSet<>();
        points.add(lo);
        points.add(hi);
        for (Contribution c : cs) {
            Rational[] x = c.x();
            Rational[] y = c.y();
            for (Rational xi : x) {
                if (xi.compareTo(lo) > 0 && xi.compareTo(hi) < 0) {
                    points.add(xi);
                }
            }
            if (!c.prod()) {
                Rational l = c.level();
                for (int i = 0; i + 1 < x.length; i++) {
                    int s0 = y[i].compareTo(l);
                    int s1 = y[i + 1].compareTo(l);
                    if (s0 * s1 < 0 && x[i + 1].compareTo(x[i]) > 0) {
                        Rational u = x[i].add(x[i + 1].subtract(x[i]).multiply(l.subtract(y[i]))
                                .divide(y[i + 1].subtract(y[i])));
                        if (u.compareTo(lo) > 0 && u.compareTo(hi) < 0) {
                            points.add(u);
                        }
                    }
                }
            }
        }
        Rational[] bx = points.toArray(Rational[]::new);
        int nb = bx.length;
        int n = cs.size();
        Rational[][] cl = new Rational[n][nb];
        Rational[][] cv = new Rational[n][nb];
        Rational[][] cr = new Rational[n][nb];
        for (int j = 0; j < n; j++) {
            Contribution c = cs.get(j);
            Rational[] x = c.x();
            Rational[] y = c.y();
            int m = x.length;
            int p = 0;
            for (int i = 0; i < nb; i++) {
                Rational u = bx[i];
                while (p < m && x[p].compareTo(u) < 0) {
                    p++;
                }
                Rational l;
                Rational v;
                Rational r;
                if (p < m && x[p].equals(u)) {
                    int q = p;
                    v = y[p];
                    while (q + 1 < m && x[q + 1].equals(u)) {
                        v = v.max(y[++q]);
                    }
                    l = y[p];
                    r = y[q];
                } else if (p == 0 || p == m) {
                    l = v = r = y[p == 0 ? 0 : m - 1];
                } else {
                    l = v = r = interpolate(x[p - 1], y[p - 1], x[p], y[p], u);
                }
                Rational av = c.activate(v);
                cv[j][i] = av;
                cl[j][i] = i == 0 || l.equals(v) ? av : c.activate(l);
                cr[j][i] = i == nb - 1 || r.equals(v) ? av : c.activate(r);
            }
        }
        boolean max = accu == AccumulationMethod.MAX;
        Rational[] aL = new Rational[nb];
        Rational[] aV = new Rational[nb];
        Rational[] aR = new Rational[nb];
        for (int i = 0; i < nb; i++) {
            Rational l = Rational.ZERO;
            Rational v = Rational.ZERO;
            Rational r = Rational.ZERO;
            for (int j = 0; j < n; j++) {
                l = max ? l.max(cl[j][i]) : l.add(cl[j][i]);
                v = max ? v.max(cv[j][i]) : v.add(cv[j][i]);
                r = max ? r.max(cr[j][i]) : r.add(cr[j][i]);
            }
            aL[i] = l;
            aV[i] = v;
            aR[i] = r;
        }
        for (int i = 0; i < nb; i++) {
            if (i > 0) {
                emit(bx[i], aL[i], accu);
            }
            emit(bx[i], aV[i], accu);
            if (i < nb - 1) {
                emit(bx[i], aR[i], accu);
                if (max) {
                    envelope(bx[i], bx[i + 1], i, cl, cr, n);
                } else if (accu == AccumulationMethod.BSUM) {
                    Rational s0 = aR[i];
                    Rational s1 = aL[i + 1];
                    if (s0.compareTo(Rational.ONE) * s1.compareTo(Rational.ONE) < 0) {
                        Rational t = Rational.ONE.subtract(s0).divide(s1.subtract(s0));
                        emitRaw(bx[i].add(bx[i + 1].subtract(bx[i]).multiply(t)), Rational.ONE);
                    }
                }
            }
        }
        if (accu == AccumulationMethod.NSUM) {
            Rational top = Rational.ONE;
            for (Rational y : py) {
                top = top.max(y);
            }
            if (!top.equals(Rational.ONE)) {
                for (int k = 0; k < py.size(); k++) {
                    py.set(k, py.get(k).divide(top));
                }
            }
        }
    }

    static Rational interpolate(Rational x0, Rational y0, Rational x1, Rational y1, Rational u) {
        if (y0.equals(y1)) {
            return y0;
        }
        return y0.add(y1.subtract(y0).multiply(u.subtract(x0)).divide(x1.subtract(x0)));
    }

    /**
     * The corners of the upper envelope of the activated sets on (a, b), where each is the line from cr[j][i]
     * to cl[j][i+1]: from the left, switch to the line that overtakes the current one first (exactly, so a tie
     * is a tie).
     */
    private void envelope(Rational a, Rational b, int i, Rational[][] cl, Rational[][] cr, int n) {
        Rational w = b.subtract(a);
        int cur = 0;
        for (int j = 1; j < n; j++) {
            int c = cr[j][i].compareTo(cr[cur][i]);
            if (c > 0 || c == 0 && cl[j][i + 1].compareTo(cl[cur][i + 1]) > 0) {
                cur = j;
            }
        }
        Rational t0 = Rational.ZERO;
        for (int steps = 0; steps < n; steps++) {
            Rational fa = cr[cur][i];
            Rational fb = cl[cur][i + 1];
            Rational bestT = Rational.ONE;
            int next = -1;
            for (int j = 0; j < n; j++) {
                Rational ga = cr[j][i];
                Rational gb = cl[j][i + 1];
                if (j == cur || fb.compareTo(gb) >= 0) {
                    continue;
                }
                Rational d0 = fa.subtract(ga);
                Rational t = d0.divide(d0.subtract(fb.subtract(gb)));
                if (t.compareTo(t0) < 0) {
                    t = t0;
                }
                int c = t.compareTo(bestT);
                if (c < 0 || c == 0 && next >= 0 && gb.compareTo(cl[next][i + 1]) > 0) {
                    bestT = t;
                    next = j;
                }
            }
            if (next < 0 || bestT.compareTo(Rational.ONE) >= 0) {
                return;
            }
            if (bestT.compareTo(t0) > 0) {
                emitRaw(a.add(w.multiply(bestT)), fa.add(fb.subtract(fa).multiply(bestT)));
            }
            t0 = bestT;
            cur = next;
        }
    }

    private void emit(Rational u, Rational raw, AccumulationMethod accu) {
        emitRaw(u, accu == AccumulationMethod.BSUM ? raw.min(Rational.ONE) : raw);
    }

    private void emitRaw(Rational u, Rational y) {
        int np = px.size();
        if (np > 0 && px.get(np - 1).equals(u) && py.get(np - 1).equals(y)) {
            return;
        }
        if (np > 1 && py.get(np - 1).equals(y) && py.get(np - 2).equals(y)) {
            px.set(np - 1, u); // a flat run needs only its two ends
            return;
        }
        px.add(u);
        py.add(y);
    }

    // ------------------------------------------------------------------------------------ defuzzification

    Rational area() {
        Rational area = Rational.ZERO;
        for (int j = 0; j + 1 < px.size(); j++) {
            area = area.add(piece(j));
        }
        return area;
    }

    private Rational piece(int j) {
        return px.get(j + 1).subtract(px.get(j)).multiply(py.get(j).add(py.get(j + 1))).multiply(Rational.HALF);
    }

    Rational supremum() {
        Rational sup = Rational.ZERO;
        for (Rational y : py) {
            sup = sup.max(y);
        }
        return sup;
    }

    /** ∫u·μ / ∫μ; null when there is no area. */
    Rational centreOfGravity() {
        Rational area = Rational.ZERO;
        Rational moment = Rational.ZERO;
        Rational sixth = Rational.of(java.math.BigInteger.ONE, java.math.BigInteger.valueOf(6));
        for (int j = 0; j + 1 < px.size(); j++) {
            Rational x0 = px.get(j);
            Rational x1 = px.get(j + 1);
            Rational y0 = py.get(j);
            Rational y1 = py.get(j + 1);
            Rational h = x1.subtract(x0);
            if (h.isZero() || y0.isZero() && y1.isZero()) {
                continue;
            }
            area = area.add(h.multiply(y0.add(y1)).multiply(Rational.HALF));
            moment = moment.add(h.multiply(x0.multiply(y0.add(y0).add(y1)).add(x1.multiply(y0.add(y1).add(y1))))
                    .multiply(sixth));
        }
        return area.signum() > 0 ? moment.divide(area) : null;
    }

    /** The u′ with equal area on both sides; the midpoint of a zero gap at the halfway point; null without area. */
    Rational centreOfArea() {
        Rational total = area();
        if (total.signum() <= 0) {
            return null;
        }
        Rational half = total.multiply(Rational.HALF);
        return fromLeft(half).add(fromRight(half)).multiply(Rational.HALF);
    }

    private Rational fromLeft(Rational half) {
        Rational cum = Rational.ZERO;
        for (int j = 0; j + 1 < px.size(); j++) {
            Rational next = cum.add(piece(j));
            int c = next.compareTo(half);
            if (c == 0) {
                return px.get(j + 1);
            }
            if (c > 0) {
                return px.get(j).add(solve(py.get(j), py.get(j + 1), px.get(j + 1).subtract(px.get(j)),
                        half.subtract(cum)));
            }
            cum = next;
        }
        return px.get(px.size() - 1);
    }

    private Rational fromRight(Rational half) {
        Rational cum = Rational.ZERO;
        for (int j = px.size() - 2; j >= 0; j--) {
            Rational next = cum.add(piece(j));
            int c = next.compareTo(half);
            if (c == 0) {
                return px.get(j);
            }
            if (c > 0) {
                return px.get(j + 1).subtract(solve(py.get(j + 1), py.get(j), px.get(j + 1).subtract(px.get(j)),
                        half.subtract(cum)));
            }
            cum = next;
        }
        return px.get(0);
    }

    /** The t in a piece of width h from degree y0 to y1 with area target up to t: y0·t + (y1−y0)/h·t²/2 = target. */
    static Rational solve(Rational y0, Rational y1, Rational h, Rational target) {
        if (target.signum() <= 0) {
            return Rational.ZERO;
        }
        Rational s = y1.subtract(y0).divide(h);
        Rational t;
        if (s.isZero()) {
            t = target.divide(y0);
        } else {
            Rational disc = y0.multiply(y0).add(Rational.TWO.multiply(s).multiply(target)).max(Rational.ZERO);
            Rational den = y0.add(disc.sqrt());
            t = den.signum() > 0 ? Rational.TWO.multiply(target).divide(den) : h;
        }
        return t.max(Rational.ZERO).min(h);
    }

    /** Leftmost (or rightmost) u reaching the supremum, exactly; null when no degree is positive. */
    Rational extremeMaximum(boolean leftmost) {
        Rational sup = supremum();
        if (sup.signum() <= 0) {
            return null;
        }
        int np = px.size();
        for (int k = 0; k < np; k++) {
            int j = leftmost ? k : np - 1 - k;
            if (py.get(j).equals(sup)) {
                return px.get(j);
            }
        }
        return null;
    }

    /** MoM (Open Level): centre of the plateaus at the supremum, else the mean of the distinct maximising points. */
    Rational meanOfMaximum() {
        Rational sup = supremum();
        if (sup.signum() <= 0) {
            return null;
        }
        Rational length = Rational.ZERO;
        Rational moment = Rational.ZERO;
        int np = px.size();
        for (int j = 0; j + 1 < np; j++) {
            Rational h = px.get(j + 1).subtract(px.get(j));
            if (h.signum() > 0 && py.get(j).equals(sup) && py.get(j + 1).equals(sup)) {
                length = length.add(h);
                moment = moment.add(h.multiply(px.get(j).add(px.get(j + 1))).multiply(Rational.HALF));
            }
        }
        if (length.signum() > 0) {
            return moment.divide(length);
        }
        Rational sum = Rational.ZERO;
        int count = 0;
        for (int j = 0; j < np; j++) {
            if (py.get(j).equals(sup) && (count == 0 || !px.get(j).equals(px.get(j - 1)) || !py.get(j - 1).equals(sup))) {
                sum = sum.add(px.get(j));
                count++;
            }
        }
        return sum.divide(Rational.of(count));
    }
}
