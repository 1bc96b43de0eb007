package org.fclcert.harness.fakes;

import java.util.List;
import java.util.Optional;
import org.fclcert.eval.Trace;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Term;

/** A tiny defuzzifier of the fakes' own (numeric, deliberately not the reference's closed forms). */
final class Shapes {
    private Shapes() {
    }

    /** A term cut at a height: min(height, μ(x)). */
    record Clipped(Term term, double height) {
    }

    static Optional<Double> singletonValue(Term t) {
        return t.function() instanceof MembershipFunction.Singleton s && s.value() instanceof Literal l
                ? Optional.of(l.value()) : Optional.empty();
    }

    /** True when every term of the output has constant points (the own integrator handles no others). */
    static boolean constantPoints(org.fclcert.model.Defuzzification d) {
        return d.terms().stream().allMatch(t -> t.function() instanceof MembershipFunction.Points p
                && p.points().stream().allMatch(pt -> pt.x() instanceof Literal && pt.degree() instanceof Literal));
    }

    /** μ of a constant point term, linear between points, constant beyond the outer points. */
    static double membership(Term t, double x) {
        List<Point> pts = ((MembershipFunction.Points) t.function()).points();
        double x0 = value(pts.get(0).x());
        if (x <= x0) {
            return value(pts.get(0).degree());
        }
        for (int i = 1; i < pts.size(); i++) {
            double x1 = value(pts.get(i).x());
            if (x <= x1) {
                double y0 = value(pts.get(i - 1).degree());
                double y1 = value(pts.get(i).degree());
                double xPrev = value(pts.get(i - 1).x());
                return x1 == xPrev ? y1 : y0 + (y1 - y0) * (x - xPrev) / (x1 - xPrev);
            }
        }
        return value(pts.get(pts.size() - 1).degree());
    }

    private static double value(org.fclcert.model.Operand o) {
        return ((Literal) o).value();
    }

    /**
     * CoG of clipped terms accumulated with MAX, BSUM or NSUM over [lo, hi], by the midpoint rule on
     * 200 000 strips (NSUM divides by the largest sum over the interval when it exceeds 1).
     */
    static Optional<Double> clippedCog(List<Clipped> clipped, AccumulationMethod accu, double lo, double hi) {
        int n = 200_000;
        double h = (hi - lo) / n;
        double[] mu = new double[n];
        double peak = 0;
        for (int i = 0; i < n; i++) {
            double x = lo + (i + 0.5) * h;
            double acc = 0;
            for (Clipped c : clipped) {
                double m = Math.min(c.height(), membership(c.term(), x));
                acc = accu == AccumulationMethod.MAX ? Math.max(acc, m) : acc + m;
            }
            mu[i] = accu == AccumulationMethod.BSUM ? Math.min(1, acc) : acc;
            peak = Math.max(peak, mu[i]);
        }
        double scale = accu == AccumulationMethod.NSUM ? Math.max(1, peak) : 1;
        double num = 0;
        double den = 0;
        for (int i = 0; i < n; i++) {
            num += (lo + (i + 0.5) * h) * mu[i] / scale;
            den += mu[i] / scale;
        }
        return den > 0 ? Optional.of(num / den) : Optional.empty();
    }

    /** Defuzzifies a piece-wise linear set sampled at the midpoints of n equal strips of its interval. */
    static Optional<Double> sampled(DefuzzificationMethod method, List<Trace.Breakpoint> set, int n) {
        double lo = set.get(0).u();
        double hi = set.get(set.size() - 1).u();
        double[] u = new double[n];
        double[] mu = new double[n];
        double total = 0;
        double max = 0;
        for (int i = 0; i < n; i++) {
            u[i] = lo + (i + 0.5) * (hi - lo) / n;
            mu[i] = at(set, u[i]);
            total += mu[i];
            max = Math.max(max, mu[i]);
        }
        if (total == 0) {
            return Optional.empty();
        }
        return Optional.of(switch (method) {
            case LM -> u[first(mu, max)];
            case RM -> u[last(mu, max)];
            case COA -> u[half(mu, total)];
            case MOM -> meanOfMaximum(u, mu, max);
            default -> weighted(u, mu, total);
        });
    }

    /** The mean of the samples at the maximum (how sampling implementations compute MoM). */
    private static double meanOfMaximum(double[] u, double[] mu, double max) {
        double sum = 0;
        int n = 0;
        for (int i = 0; i < u.length; i++) {
            if (mu[i] >= max) {
                sum += u[i];
                n++;
            }
        }
        return sum / n;
    }

    private static double weighted(double[] u, double[] mu, double total) {
        double num = 0;
        for (int i = 0; i < u.length; i++) {
            num += u[i] * mu[i];
        }
        return num / total;
    }

    private static int first(double[] mu, double max) {
        int i = 0;
        while (mu[i] < max) {
            i++;
        }
        return i;
    }

    private static int last(double[] mu, double max) {
        int i = mu.length - 1;
        while (mu[i] < max) {
            i--;
        }
        return i;
    }

    private static int half(double[] mu, double total) {
        double sum = 0;
        for (int i = 0; i < mu.length; i++) {
            sum += mu[i];
            if (sum >= total / 2) {
                return i;
            }
        }
        return mu.length - 1;
    }

    /** The set's degree at u (linear between breakpoints; at a jump, the right-hand value). */
    private static double at(List<Trace.Breakpoint> set, double u) {
        for (int i = 1; i < set.size(); i++) {
            Trace.Breakpoint a = set.get(i - 1);
            Trace.Breakpoint b = set.get(i);
            if (u >= a.u() && u < b.u()) {
                return a.degree() + (b.degree() - a.degree()) * (u - a.u()) / (b.u() - a.u());
            }
        }
        return set.get(set.size() - 1).degree();
    }
}
