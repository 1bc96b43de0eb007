package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction.NamedShape;
import org.fclcert.model.Point;
import org.fclcert.model.SourceLocation;

/**
 * Named shapes (jFuzzyLogic, fuzzylite) as standard FCL points (5.2.2), for conversion to standard FCL.
 * Linear shapes convert exactly; smooth ones approximately, with their largest membership error
 * computed (not guessed). Hedges have no standard equivalent, except {@code not} as the outermost hedge
 * (the standard's IS NOT, which the readers already produce) and {@code any} (degree 1: the subcondition
 * can be dropped from an AND chain; elsewhere it has no equivalent). docs/dialects.md.
 */
public final class ShapePoints {
    /** Sub-samples per approximation segment used to measure the error. */
    static final int ERROR_SAMPLES = 64;

    private ShapePoints() {
    }

    /** The exact points of a linear shape (triangle, trapezoid, rectangle, ramp); empty for smooth shapes. */
    public static Optional<List<Point>> exact(NamedShape shape) {
        return shape.points();
    }

    /**
     * Points approximating a shape over [lo, hi] (the shape's variable RANGE) and the largest difference
     * between the shape and the piece-wise linear function through the points, over [lo, hi].
     *
     * @param points        the points; outside [lo, hi] the standard's outer-degree rule continues them flat
     * @param maxError      an upper bound of |μ_shape(u) − μ_points(u)| on [lo, hi]: the largest
     *                      difference at 64 sub-samples of every segment plus (L + s)·δ/2, where L is the
     *                      shape's slope bound ({@link org.fclcert.model.ShapeKind#slopeBound}), s the
     *                      segment's slope and δ the sub-sample spacing (between two sub-samples the
     *                      difference changes by at most (L + s)·δ/2 from the nearer one); +∞ when the
     *                      shape's slope is unbounded (a bell with slope below 1/2)
     * @param sampledError  the largest difference actually seen at the sub-samples (a lower bound)
     */
    public record Approximation(List<Point> points, double maxError, double sampledError) {
        public Approximation {
            points = List.copyOf(points);
        }
    }

    /**
     * n ≥ 2 equally spaced points over [lo, hi], plus the shape's special points inside (peaks, ends of
     * support, kinks), each point on the shape. A linear shape gives its exact points (error 0).
     */
    public static Approximation approximate(NamedShape shape, double lo, double hi, int n) {
        if (n < 2 || !(lo < hi) || !Double.isFinite(lo) || !Double.isFinite(hi)) {
            throw new IllegalArgumentException("need n >= 2 and a finite interval lo < hi");
        }
        Optional<List<Point>> exact = exact(shape);
        if (exact.isPresent()) {
            return new Approximation(exact.get(), 0, 0);
        }
        double[] p = shape.values();
        List<Double> xs = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            xs.add(i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1));
        }
        for (double u : shape.kind().specialPoints(p)) {
            if (u > lo && u < hi) {
                xs.add(u);
            }
        }
        double[] x = xs.stream().mapToDouble(Double::doubleValue).sorted().distinct().toArray();
        double[] y = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            y[i] = shape.kind().degree(p, x[i]);
        }
        double slope = shape.kind().slopeBound(p);
        double sampled = 0;
        double bound = 0;
        for (int i = 0; i + 1 < x.length; i++) {
            double h = x[i + 1] - x[i];
            double s = Math.abs(y[i + 1] - y[i]) / h;
            double delta = h / ERROR_SAMPLES;
            double worst = 0;
            for (int j = 1; j < ERROR_SAMPLES; j++) {
                double u = x[i] + j * delta;
                double line = y[i] + (y[i + 1] - y[i]) * j / ERROR_SAMPLES;
                worst = Math.max(worst, Math.abs(shape.kind().degree(p, u) - line));
            }
            sampled = Math.max(sampled, worst);
            bound = Math.max(bound, worst + (slope + s) * delta / 2);
        }
        List<Point> points = new ArrayList<>();
        SourceLocation at = shape.parameters().isEmpty() ? SourceLocation.UNKNOWN : shape.parameters().get(0).location();
        for (int i = 0; i < x.length; i++) {
            points.add(new Point(Literal.of(x[i]), Literal.of(y[i]), at));
        }
        return new Approximation(points, bound, sampled);
    }
}
