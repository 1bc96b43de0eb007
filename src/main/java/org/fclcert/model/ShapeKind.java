package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/**
 * The named membership-function shapes the jFuzzyLogic and fuzzylite dialects write ({@code trian 0 5 10},
 * {@code Gaussian 5 2}, ...), outside the standard (Open Level, Table 10). The standard knows only
 * points and singletons (5.2.2); a named shape is the function its formula defines. Parameters are
 * held in fclcert's canonical order ({@link #parameterNames()}); each dialect reader maps its own
 * order to it. The linear kinds ({@link #linear()}) are exactly a list of points ({@link #points}).
 */
public enum ShapeKind {
    /** (a, 0) (b, 1) (c, 0). */
    TRIANGLE("O-SHAPE-TRIANGLE", true, "a", "b", "c"),
    /** (a, 0) (b, 1) (c, 1) (d, 0). */
    TRAPEZOID("O-SHAPE-TRAPEZOID", true, "a", "b", "c", "d"),
    /** 1 on [start, end], 0 elsewhere. */
    RECTANGLE("O-SHAPE-RECTANGLE", true, "start", "end"),
    /** 0 at start, 1 at end, linear between, constant beyond (rising or falling). */
    RAMP("O-SHAPE-RAMP", true, "start", "end"),
    /** exp(−(u − mean)² / (2 sd²)). */
    GAUSSIAN("O-SHAPE-GAUSSIAN", false, "mean", "sd"),
    /** Left Gaussian shoulder below meanA, 1 between, right shoulder above meanB (their product). */
    GAUSSIAN_PRODUCT("O-SHAPE-GAUSSIAN-PRODUCT", false, "meanA", "sdA", "meanB", "sdB"),
    /** 1 / (1 + |(u − center) / width|^(2 slope)). */
    BELL("O-SHAPE-BELL", false, "center", "width", "slope"),
    /** 1 / (1 + exp(−slope (u − inflection))). */
    SIGMOID("O-SHAPE-SIGMOID", false, "inflection", "slope"),
    /** |s(u; left, rising) − s(u; right, falling)| with s the sigmoid above. */
    SIGMOID_DIFFERENCE("O-SHAPE-SIGMOID-DIFFERENCE", false, "left", "rising", "falling", "right"),
    /** s(u; left, rising) · s(u; right, falling). */
    SIGMOID_PRODUCT("O-SHAPE-SIGMOID-PRODUCT", false, "left", "rising", "falling", "right"),
    /** (1 + cos(2π (u − center) / width)) / 2 for |u − center| ≤ width / 2, 0 elsewhere. */
    COSINE("O-SHAPE-COSINE", false, "center", "width"),
    /** 0 up to start, 1 from end, two parabolas meeting at the midpoint between (smooth step up). */
    S_SHAPE("O-SHAPE-S", false, "start", "end"),
    /** 1 − S_SHAPE(start, end): a smooth step down. */
    Z_SHAPE("O-SHAPE-Z", false, "start", "end"),
    /** S_SHAPE(bottomLeft, topLeft) · Z_SHAPE(topRight, bottomRight). */
    PI_SHAPE("O-SHAPE-PI", false, "bottomLeft", "topLeft", "topRight", "bottomRight"),
    /**
     * fuzzylite's Concave: rising to 1 at end when inflection &lt; end, (end − inflection) / (2 end − inflection − u)
     * below end and 1 from it; mirrored (falling) when inflection &gt; end; the degree is ½ at the inflection.
     */
    CONCAVE("O-SHAPE-CONCAVE", false, "inflection", "end"),
    /** fuzzylite's Spike: exp(−|10 (u − center) / width|). */
    SPIKE("O-SHAPE-SPIKE", false, "center", "width");

    private final String featureId;
    private final boolean linear;
    private final List<String> parameterNames;

    ShapeKind(String featureId, boolean linear, String... parameterNames) {
        this.featureId = featureId;
        this.linear = linear;
        this.parameterNames = List.of(parameterNames);
    }

    /** The id of the Open Level feature that stands for this shape, e.g. {@code O-SHAPE-GAUSSIAN}. */
    public String featureId() {
        return featureId;
    }

    /** True for the shapes that are exactly piece-wise linear. */
    public boolean linear() {
        return linear;
    }

    /** The canonical parameter names, in order. */
    public List<String> parameterNames() {
        return parameterNames;
    }

    public int arity() {
        return parameterNames.size();
    }

    /**
     * The points of a linear shape, exact (5.2.2 reading: linear between points, the outer degrees
     * beyond them, a vertical edge as two points with one x); empty for the other kinds or a wrong
     * parameter count. A falling ramp gives its points sorted by x.
     */
    public Optional<double[][]> points(double[] p) {
        if (!linear || p.length != arity()) {
            return Optional.empty();
        }
        double[][] xy = switch (this) {
            case TRIANGLE -> new double[][] {{p[0], p[1], p[2]}, {0, 1, 0}};
            case TRAPEZOID -> new double[][] {{p[0], p[1], p[2], p[3]}, {0, 1, 1, 0}};
            case RECTANGLE -> new double[][] {{p[0], p[0], p[1], p[1]}, {0, 1, 1, 0}};
            case RAMP -> p[0] <= p[1] ? new double[][] {{p[0], p[1]}, {0, 1}} : new double[][] {{p[1], p[0]}, {1, 0}};
            default -> throw new IllegalStateException(name());
        };
        return Optional.of(xy);
    }

    /** The degree at {@code u} by the shape's formula; parameters in canonical order (count not checked). */
    public double degree(double[] p, double u) {
        return switch (this) {
            case TRIANGLE, TRAPEZOID, RECTANGLE, RAMP -> linearDegree(points(p).orElseThrow(), u);
            case GAUSSIAN -> gauss(u, p[0], p[1]);
            case GAUSSIAN_PRODUCT -> (u < p[0] ? gauss(u, p[0], p[1]) : 1.0) * (u > p[2] ? gauss(u, p[2], p[3]) : 1.0);
            case BELL -> 1.0 / (1.0 + Math.pow(Math.abs((u - p[0]) / p[1]), 2 * p[2]));
            case SIGMOID -> sigmoid(u, p[0], p[1]);
            case SIGMOID_DIFFERENCE -> Math.abs(sigmoid(u, p[0], p[1]) - sigmoid(u, p[3], p[2]));
            case SIGMOID_PRODUCT -> sigmoid(u, p[0], p[1]) * sigmoid(u, p[3], p[2]);
            case COSINE -> Math.abs(u - p[0]) > p[1] / 2 ? 0.0 : 0.5 * (1 + Math.cos(2 * Math.PI * (u - p[0]) / p[1]));
            case S_SHAPE -> sShape(u, p[0], p[1]);
            case Z_SHAPE -> 1.0 - sShape(u, p[0], p[1]);
            case PI_SHAPE -> sShape(u, p[0], p[1]) * (1.0 - sShape(u, p[2], p[3]));
            case CONCAVE -> concave(u, p[0], p[1]);
            case SPIKE -> Math.exp(-Math.abs(10.0 / p[1] * (u - p[0])));
        };
    }

    /**
     * The places where the shape is not smooth (a kink or jump of the formula or its derivative) or has
     * a maximum, so that integration and maximum search can split there. Parameters in canonical order.
     */
    public double[] specialPoints(double[] p) {
        return switch (this) {
            case TRIANGLE, TRAPEZOID, RECTANGLE, RAMP -> points(p).orElseThrow()[0];
            case GAUSSIAN, SIGMOID -> new double[] {p[0]};
            case GAUSSIAN_PRODUCT -> new double[] {p[0], p[2]};
            case BELL -> new double[] {p[0]};
            case SIGMOID_DIFFERENCE, SIGMOID_PRODUCT -> new double[] {p[0], p[3], (p[0] + p[3]) / 2};
            case COSINE -> new double[] {p[0] - p[1] / 2, p[0], p[0] + p[1] / 2};
            case S_SHAPE, Z_SHAPE -> new double[] {p[0], (p[0] + p[1]) / 2, p[1]};
            case PI_SHAPE -> new double[] {p[0], (p[0] + p[1]) / 2, p[1], p[2], (p[2] + p[3]) / 2, p[3]};
            case CONCAVE -> new double[] {p[0], p[1]};
            case SPIKE -> new double[] {p[0]};
        };
    }

    /**
     * An upper bound of |dμ/du| where the shape is differentiable (its Lipschitz constant between
     * {@link #specialPoints}), from the formula: Gaussian 1/(sd·√e), sigmoid |slope|/4, cosine π/width,
     * S/Z 2/(end − start), bell 2·slope/width for slope ≥ 1/2 (unbounded below: +∞). Linear kinds:
     * the steepest segment.
     */
    public double slopeBound(double[] p) {
        return switch (this) {
            case TRIANGLE, TRAPEZOID, RECTANGLE, RAMP -> {
                double[][] xy = points(p).orElseThrow();
                double s = 0;
                for (int i = 0; i + 1 < xy[0].length; i++) {
                    double h = xy[0][i + 1] - xy[0][i];
                    if (h > 0) {
                        s = Math.max(s, Math.abs(xy[1][i + 1] - xy[1][i]) / h);
                    }
                }
                yield s;
            }
            case GAUSSIAN -> 1 / (Math.abs(p[1]) * Math.sqrt(Math.E));
            case GAUSSIAN_PRODUCT -> 1 / (Math.abs(p[1]) * Math.sqrt(Math.E)) + 1 / (Math.abs(p[3]) * Math.sqrt(Math.E));
            case BELL -> p[2] >= 0.5 ? 2 * p[2] / Math.abs(p[1]) : Double.POSITIVE_INFINITY;
            case SIGMOID -> Math.abs(p[1]) / 4;
            case SIGMOID_DIFFERENCE, SIGMOID_PRODUCT -> Math.abs(p[1]) / 4 + Math.abs(p[2]) / 4;
            case COSINE -> Math.PI / Math.abs(p[1]);
            case S_SHAPE, Z_SHAPE -> 2 / Math.abs(p[1] - p[0]);
            case PI_SHAPE -> 2 / Math.abs(p[1] - p[0]) + 2 / Math.abs(p[3] - p[2]);
            // d/du (e − i) / (2e − i − u) is steepest at u = e, where it is 1 / |e − i|
            case CONCAVE -> 1 / Math.abs(p[1] - p[0]);
            case SPIKE -> 10 / Math.abs(p[1]);
        };
    }

    /**
     * Places where the shape crosses {@code level} (0 &lt; level &lt; 1), in closed form where the formula
     * inverts simply (Gaussian, its product's shoulders, bell, sigmoid, cosine, S and Z); empty for the
     * others. Only split points for integration: a missing or superfluous one costs time, not accuracy.
     */
    public double[] levelCrossings(double[] p, double level) {
        if (!(level > 0 && level < 1)) {
            return new double[0];
        }
        return switch (this) {
            case GAUSSIAN -> {
                double r = Math.abs(p[1]) * Math.sqrt(-2 * Math.log(level));
                yield new double[] {p[0] - r, p[0] + r};
            }
            case GAUSSIAN_PRODUCT -> {
                double l = Math.sqrt(-2 * Math.log(level));
                yield new double[] {p[0] - Math.abs(p[1]) * l, p[2] + Math.abs(p[3]) * l};
            }
            case BELL -> {
                double t = Math.abs(p[1]) * Math.pow(1 / level - 1, 1 / (2 * p[2]));
                yield new double[] {p[0] - t, p[0] + t};
            }
            case SIGMOID -> new double[] {p[0] - Math.log(1 / level - 1) / p[1]};
            case COSINE -> {
                double t = Math.abs(p[1]) * Math.acos(2 * level - 1) / (2 * Math.PI);
                yield new double[] {p[0] - t, p[0] + t};
            }
            case S_SHAPE, Z_SHAPE -> {
                double l = this == S_SHAPE ? level : 1 - level;
                double t = l <= 0.5 ? Math.sqrt(l / 2) : 1 - Math.sqrt((1 - l) / 2);
                yield new double[] {p[0] + t * (p[1] - p[0])};
            }
            default -> new double[0];
        };
    }

    /** True for the shapes that rise or fall monotonically (fuzzylite's Ramp, Sigmoid, SShape, ZShape, Concave). */
    public boolean monotonic() {
        return this == RAMP || this == SIGMOID || this == S_SHAPE || this == Z_SHAPE || this == CONCAVE;
    }

    /**
     * Tsukamoto's inverse of a {@link #monotonic()} shape at degree {@code w} &gt; 0, in closed form: for a rising
     * shape the least u with μ(u) ≥ w, for a falling one the greatest; {@code +∞} (rising) or {@code −∞} (falling)
     * when the shape never reaches w (a sigmoid never reaches 1). NaN for the other kinds. Parameters in canonical
     * order.
     */
    public double inverse(double[] p, double w) {
        if (!monotonic() || !(w > 0)) {
            return Double.NaN;
        }
        boolean rising = rising(p);
        double never = rising ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        return switch (this) {
            case RAMP -> w > 1 ? never : p[0] + w * (p[1] - p[0]);
            case SIGMOID -> w >= 1 ? never : p[0] - Math.log(1 / w - 1) / p[1];
            case S_SHAPE -> w > 1 ? never : w <= 0.5 ? p[0] + (p[1] - p[0]) * Math.sqrt(w / 2)
                    : p[1] - (p[1] - p[0]) * Math.sqrt((1 - w) / 2);
            case Z_SHAPE -> w > 1 ? never : w >= 0.5 ? p[0] + (p[1] - p[0]) * Math.sqrt((1 - w) / 2)
                    : p[1] - (p[1] - p[0]) * Math.sqrt(w / 2);
            // rising: (e − i) / (2e − i − u) = w below e; falling: (i − e) / (i − 2e + u) = w above e; both solve to
            // the one expression u = 2e − i − (e − i) / w
            case CONCAVE -> w > 1 ? never : 2 * p[1] - p[0] - (p[1] - p[0]) / w;
            default -> Double.NaN;
        };
    }

    /** Whether a {@link #monotonic()} shape rises (else it falls). */
    public boolean rising(double[] p) {
        return switch (this) {
            case RAMP -> p[0] <= p[1];
            case SIGMOID -> p[1] >= 0;
            case Z_SHAPE -> false;
            case CONCAVE -> p[0] <= p[1];
            default -> true;
        };
    }

    private static double linearDegree(double[][] xy, double u) {
        double[] x = xy[0];
        double[] y = xy[1];
        int n = x.length;
        if (u < x[0]) {
            return y[0];
        }
        if (u > x[n - 1]) {
            return y[n - 1];
        }
        double best = -1;
        for (int i = 0; i < n; i++) {
            if (x[i] == u) {
                best = Math.max(best, y[i]);
            }
        }
        if (best >= 0) {
            return best;
        }
        int i = 1;
        while (x[i] < u) {
            i++;
        }
        return y[i - 1] + (y[i] - y[i - 1]) * (u - x[i - 1]) / (x[i] - x[i - 1]);
    }

    private static double gauss(double u, double mean, double sd) {
        double t = (u - mean) / sd;
        return Math.exp(-0.5 * t * t);
    }

    private static double sigmoid(double u, double inflection, double slope) {
        return 1.0 / (1.0 + Math.exp(-slope * (u - inflection)));
    }

    private static double concave(double u, double inflection, double end) {
        if (inflection <= end) {
            return u < end ? (end - inflection) / (2 * end - inflection - u) : 1.0;
        }
        return u > end ? (inflection - end) / (inflection - 2 * end + u) : 1.0;
    }

    private static double sShape(double u, double start, double end) {
        if (u <= start) {
            return 0.0;
        }
        if (u >= end) {
            return 1.0;
        }
        double t = (u - start) / (end - start);
        return t <= 0.5 ? 2 * t * t : 1 - 2 * (1 - t) * (1 - t);
    }
}
