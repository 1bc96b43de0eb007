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
                out.add(new double[] {lo, 1});
                out.add(new double[] {lo, 1});
                out.add(new double[] {runs.get(0)[1], 1});
                out.add(new double[] {runs.get(1)[0], 0});
            }
            case "01" -> {
                out.add(new double[] {runs.get(0)[1], 0});
                out.add(new double[] {runs.get(1)[0], 1});
                out.add(new double[] {hi, 1});
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
        return Optional.of(out);
    }

    /** A term of degree 1 on all of [lo, hi] (and, clamped, beyond): FFLL's trapezoid over the whole RANGE. */
    static List<double[]> everywhere(double lo, double hi) {
        return List.of(new double[] {lo, 1}, new double[] {lo, 1}, new double[] {hi, 1}, new double[] {hi, 1});
    }

    /** Why {@link #form} found no FFLL form, in words. */
    static String why(String term, double lo, double hi) {
        return "FFLL ignores the degrees written at a term's points (3 points are a triangle 0-1-0, 4 a trapezoid"
                + " 0-1-1-0, 0 outside them, inputs clamped to the RANGE " + LibraryText.number(lo) + " .. "
                + LibraryText.number(hi) + "); term '" + term + "' is not such a shape, a shoulder or 1 everywhere"
                + " within that RANGE";
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
