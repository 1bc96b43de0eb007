package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * A term as FFLL can hold it. FFLL ignores the degrees written at a term's points: it takes 3 points as a triangle
 * 0–1–0 and 4 as a trapezoid 0–1–1–0, of degree 0 outside them, on a grid over the variable's RANGE onto which it
 * also clamps its inputs (its {@code MemberFuncTri::calc}, {@code MemberFuncTrap::calc}, {@code
 * convert_value_to_idx}). A term of fclcert's model (piecewise linear, constant beyond its outer points) therefore
 * has an FFLL form only when its degrees are 0 and 1 with straight edges between them: a triangle, a trapezoid, a
 * shoulder or 1 everywhere, its points inside the RANGE. A shoulder is written as a trapezoid with a repeated point
 * at the end of the RANGE, {@code (lo, 1) (lo, 1) (c, 1) (d, 0)}: fclcert reads those points as the shoulder, and
 * FFLL's trapezoid with x0 = x1 = lo is 1 from lo (its plateau overrides the empty rising edge) and on every input
 * it clamps to lo. So the written points mean the same to both, up to FFLL's grid.
 */
final class FfllShapes {
    private FfllShapes() {
    }

    /**
     * The points to write for a term given by literal points {@code xy} (pairs x, degree; ascending x) on the
     * interval [lo, hi]; empty when FFLL cannot hold the term, {@link #why} then says why.
     */
    static Optional<List<double[]>> form(List<double[]> xy, double lo, double hi) {
        List<double[]> p = withoutInnerPoints(xy);
        for (double[] q : p) {
            if (q[1] != 0 && q[1] != 1) {
                return Optional.empty();
            }
        }
        // runs of equal degree: [first x, last x, degree]
        List<double[]> runs = new ArrayList<>();
        for (double[] q : p) {
            double[] last = runs.isEmpty() ? null : runs.get(runs.size() - 1);
            if (last != null && last[2] == q[1]) {
                last[1] = q[0];
            } else {
                runs.add(new double[] {q[0], q[0], q[1]});
            }
        }
        String pattern = runs.stream().map(r -> r[2] == 1 ? "1" : "0").reduce("", String::concat);
        List<double[]> out = new ArrayList<>();
        switch (pattern) {
            case "010" -> {
                double a = runs.get(0)[1];
                double b = runs.get(1)[0];
                double c = runs.get(1)[1];
                double d = runs.get(2)[0];
                out.add(new double[] {a, 0});
                out.add(new double[] {b, 1});
                if (c != b) {
                    out.add(new double[] {c, 1});
                }
                out.add(new double[] {d, 0});
            }
            case "10" -> {
                // a plateau of one point at the RANGE's start is a triangle (lo, lo, d): it keeps its points in FFLL
                out.add(new double[] {lo, 1});
                out.add(new double[] {lo, 1});
                if (runs.get(0)[1] != lo) {
                    out.add(new double[] {runs.get(0)[1], 1});
                }
                out.add(new double[] {runs.get(1)[0], 0});
            }
            case "01" -> {
                out.add(new double[] {runs.get(0)[1], 0});
                out.add(new double[] {runs.get(1)[0], 1});
                if (runs.get(1)[0] != hi) {
                    out.add(new double[] {hi, 1});
                }
                out.add(new double[] {hi, 1});
            }
            case "1" -> {
                return Optional.of(everywhere(lo, hi));
            }
            default -> {
                return Optional.empty();
            }
        }
        for (double[] q : out) {
            if (q[0] < lo || q[0] > hi) {
                return Optional.empty();
            }
        }
        return out.size() == 4 && !keptByCopy(out, lo, hi) ? Optional.empty() : Optional.of(out);
    }

    /**
     * Whether FFLL keeps a trapezoid's points. It loads each term into a set it then copies ({@code
     * FuzzySetBase::copy}): the copy first spreads the four points evenly over the term's width on its grid of 201
     * points ({@code MemberFuncTrap::init_nodes}) and then sets them one by one with its checks, which pull the
     * second point back to the evenly spread third when it lies at or beyond it. So the second point must lie
     * before x0 + 2·⌊w/3⌋ (grid indexes), or exactly there. A triangle's points are always kept.
     */
    static boolean keptByCopy(List<double[]> trapezoid, double lo, double hi) {
        int x0 = index(trapezoid.get(0)[0], lo, hi);
        int x1 = index(trapezoid.get(1)[0], lo, hi);
        int x3 = index(trapezoid.get(3)[0], lo, hi);
        int width = x3 - x0;
        int third = x0 + 2 * (width / 3);
        return x1 < third || x1 == third && index(trapezoid.get(2)[0], lo, hi) == third;
    }

    /** FFLL's grid index of x on [lo, hi] (201 points; {@code convert_value_to_idx}). */
    private static int index(double x, double lo, double hi) {
        int idx = (int) ((x - lo) / ((hi - lo) / 200) + 0.5);
        return Math.max(0, Math.min(200, idx));
    }

    /**
     * The end of the RANGE a term needs on the right: for a shoulder rising to 1 at the end, {@code (a, 0) (b, 1)},
     * FFLL keeps its trapezoid {@code (a, b, hi, hi)} only when the rise spans less than 2/3 of it
     * ({@link #keptByCopy}); then hi moves right to a + 1.6 (b − a) and a grid step more. Otherwise {@code hi}.
     */
    static double rightEnd(List<double[]> xy, double lo, double hi) {
        Optional<List<double[]>> form = form(xy, lo, hi);
        List<double[]> p = withoutInnerPoints(xy);
        if (form.isPresent() || p.size() < 2 || p.get(p.size() - 1)[1] != 1) {
            return hi;
        }
        double a = 0;
        double b = 0;
        for (int i = 1; i < p.size(); i++) {
            if (p.get(i - 1)[1] == 0 && p.get(i)[1] == 1) {
                a = p.get(i - 1)[0];
                b = p.get(i)[0];
            }
        }
        double wider = a + 1.6 * (b - a);
        wider += (wider - lo) / 200;
        return Math.max(hi, wider);
    }

    /** A term of degree 1 on all of [lo, hi] (and, clamped, beyond): FFLL's trapezoid over the whole RANGE. */
    static List<double[]> everywhere(double lo, double hi) {
        return List.of(new double[] {lo, 1}, new double[] {lo, 1}, new double[] {hi, 1}, new double[] {hi, 1});
    }

    /** Why {@link #form} found no FFLL form, in words. */
    static String why(String term, double lo, double hi) {
        return "FFLL ignores the degrees written at a term's points (3 points are a triangle 0-1-0, 4 a trapezoid"
                + " 0-1-1-0, 0 outside them, inputs clamped to the RANGE " + LibraryText.number(lo) + " .. "
                + LibraryText.number(hi) + ", and a trapezoid whose rising edge spans 2/3 of it or more loses its"
                + " second point); term '" + term + "' is not such a shape, a shoulder or 1 everywhere within that RANGE";
    }

    /** The points without those that lie on the straight line between their neighbours (they change no degree). */
    private static List<double[]> withoutInnerPoints(List<double[]> xy) {
        List<double[]> out = new ArrayList<>();
        for (double[] q : xy) {
            if (!out.isEmpty() && out.get(out.size() - 1)[0] == q[0] && out.get(out.size() - 1)[1] == q[1]) {
                continue;   // the same point twice
            }
            while (out.size() >= 2) {
                double[] a = out.get(out.size() - 2);
                double[] b = out.get(out.size() - 1);
                boolean straight = (b[1] - a[1]) * (q[0] - a[0]) == (q[1] - a[1]) * (b[0] - a[0])
                        && a[0] != b[0] && b[0] != q[0];
                if (!straight) {
                    break;
                }
                out.remove(out.size() - 1);
            }
            out.add(q);
        }
        return out;
    }
}
