package org.fclcert.plot;

import java.util.List;

/**
 * The accumulated set of one output at one step, as fclcert's reference evaluator computed it, with the
 * standard's value and the implementation's marked on its axis: what report.html shows beside a wrong value.
 * A piece-wise linear set is drawn filled; singletons as bars at their values, as high as their degrees. A
 * value far off the set's span is drawn at the edge it lies beyond, and the legend says so. Two values so close that
 * their lines would merge (E-ACCU-NSUM-002: 49.13 against 49.72) are drawn again under the legend on a magnified
 * strip of the axis, where they stand apart.
 */
public final class SetPicture {
    /** Wider than {@link Plotter#WIDTH}: the legend carries the two values. */
    public static final int WIDTH = 800;
    public static final String SET_FILL = "#aec7e8";
    public static final String SET_LINE = Plotter.PALETTE.get(0);
    public static final String EXPECTED = Plotter.PALETTE.get(2);
    public static final String ACTUAL = Plotter.PALETTE.get(1);

    private SetPicture() {
    }

    /**
     * @param title      the picture's title
     * @param variable   the output's name (the x axis)
     * @param singletons true: {@code set} holds one {@code [value, degree]} per term; false: the set's vertices
     *                   {@code [u, degree]}, left to right
     * @param expected   the standard's value
     * @param actual     the implementation's value, or null when it gave none
     */
    public static String svg(String title, String variable, boolean singletons, List<List<Double>> set, double expected,
            Double actual) {
        double[] d = domain(set, singletons, expected, actual);
        double[] unit = {0, 1};
        Svg svg = Plotter.frame(title, d, unit, variable, "degree of membership", WIDTH);
        // the set's fill first, the two values over it, the set's outline on top: a narrow peak under a marker
        // still shows, and so does a marker inside a wide set
        StringBuilder outline = new StringBuilder();
        if (!singletons && !set.isEmpty()) {
            outline.append(Svg.n(Plotter.px(set.get(0).get(0), d))).append(',').append(Svg.n(Plotter.py(0, unit)));
            for (List<Double> p : set) {
                outline.append(' ').append(Svg.n(Plotter.px(p.get(0), d))).append(',').append(Svg.n(Plotter.py(p.get(1), unit)));
            }
            outline.append(' ').append(Svg.n(Plotter.px(set.get(set.size() - 1).get(0), d))).append(',')
                    .append(Svg.n(Plotter.py(0, unit)));
            svg.raw("<polygon class=\"set\" points=\"" + outline + "\" fill=\"" + SET_FILL + "\" stroke=\"none\"/>");
        }
        String expectedNote = marker(svg, expected, d, EXPECTED, null);
        String actualNote = actual == null ? "none given" : marker(svg, actual, d, ACTUAL, "6 4");
        if (singletons) {
            for (List<Double> p : set) {
                if (p.get(1) > 0) {
                    svg.line(Plotter.px(p.get(0), d), Plotter.py(0, unit), Plotter.px(p.get(0), d), Plotter.py(p.get(1), unit),
                            SET_LINE, 8);
                }
            }
        } else if (outline.length() > 0) {
            svg.raw("<polyline class=\"set\" points=\"" + outline + "\" fill=\"none\" stroke=\"" + SET_LINE
                    + "\" stroke-width=\"2\" stroke-linejoin=\"round\"/>");
        }
        int x = Plotter.LEFT + Plotter.PLOT_WIDTH + 24;
        int y = Plotter.TOP + 10;
        svg.raw("<rect x=\"" + x + "\" y=\"" + (y - 6) + "\" width=\"24\" height=\"12\" fill=\"" + (singletons ? SET_LINE
                : SET_FILL) + "\" stroke=\"" + SET_LINE + "\" stroke-width=\"2\"/>");
        svg.text(x + 30, y + 4, "start", singletons ? "accumulated degrees" : "accumulated set");
        svg.line(x + 12, y + 12, x + 12, y + 28, EXPECTED, 3);
        svg.text(x + 30, y + 24, "start", "standard: " + expectedNote);
        svg.raw("<line x1=\"" + (x + 12) + "\" y1=\"" + (y + 32) + "\" x2=\"" + (x + 12) + "\" y2=\"" + (y + 48)
                + "\" stroke=\"" + ACTUAL + "\" stroke-width=\"3\" stroke-dasharray=\"6 4\"/>");
        svg.text(x + 30, y + 44, "start", "implementation: " + actualNote);
        if (actual != null && tooClose(expected, actual, d)) {
            magnified(svg, x, y + 80, expected, actual, d);
        }
        return svg.finish();
    }

    /** Two values closer than this many pixels on the main axis get the magnified strip: their lines would merge. */
    static final double CLOSE_PIXELS = 12;
    /** The magnified strip: its width, and how much of it the two values span (they sit at a fifth and four fifths). */
    static final int STRIP_WIDTH = 260;

    static boolean tooClose(double expected, double actual, double[] d) {
        return Double.isFinite(expected) && Double.isFinite(actual) && expected != actual
                && expected >= d[0] && expected <= d[1] && actual >= d[0] && actual <= d[1]
                && Math.abs(Plotter.px(expected, d) - Plotter.px(actual, d)) < CLOSE_PIXELS;
    }

    /** The span of the magnified strip: the two values at a fifth and four fifths of it. */
    static double[] stripDomain(double expected, double actual) {
        double lo = Math.min(expected, actual);
        double hi = Math.max(expected, actual);
        double pad = (hi - lo) / 3 * 2;
        return new double[] {lo - pad / 2, hi + pad / 2};
    }

    /** Where {@code value} is drawn in the strip that starts at {@code left}. */
    static double stripX(double value, double[] strip, int left) {
        return left + STRIP_WIDTH * (value - strip[0]) / (strip[1] - strip[0]);
    }

    /**
     * Beside the plot, under the legend: a strip of the axis around the two values, so wide that they stand apart
     * (a person cannot tell two lines 2 pixels apart), with its ends and how much it magnifies written on it.
     */
    private static void magnified(Svg svg, int left, int top, double expected, double actual, double[] d) {
        double[] strip = stripDomain(expected, actual);
        long times = Math.round((d[1] - d[0]) / Plotter.PLOT_WIDTH * STRIP_WIDTH / (strip[1] - strip[0]));
        int axis = top + 60;
        svg.text(left, top, "start", "the two values, magnified " + times + "×:");
        svg.raw("<rect class=\"strip\" x=\"" + left + "\" y=\"" + (top + 10) + "\" width=\"" + STRIP_WIDTH
                + "\" height=\"50\" fill=\"#f6f7f9\" stroke=\"#b5bcc5\"/>");
        svg.line(stripX(expected, strip, left), top + 12, stripX(expected, strip, left), axis - 2, EXPECTED, 3);
        svg.raw("<line class=\"marker\" x1=\"" + Svg.n(stripX(actual, strip, left)) + "\" y1=\"" + (top + 12)
                + "\" x2=\"" + Svg.n(stripX(actual, strip, left)) + "\" y2=\"" + (axis - 2) + "\" stroke=\"" + ACTUAL
                + "\" stroke-width=\"3\" stroke-dasharray=\"6 4\"/>");
        svg.text(left, axis + 16, "start", text(strip[0]));
        svg.text(left + STRIP_WIDTH, axis + 16, "end", text(strip[1]));
    }

    /**
     * The span drawn: the set's (singletons with room beside the outer bars), widened to take in values up to one
     * span beyond it, then rounded out to five ticks of a round step.
     */
    static double[] domain(List<List<Double>> set, boolean singletons, double expected, Double actual) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (List<Double> p : set) {
            lo = Math.min(lo, p.get(0));
            hi = Math.max(hi, p.get(0));
        }
        if (lo > hi) {
            lo = Double.isFinite(expected) ? expected : 0;
            hi = lo;
        }
        double reach = Math.max(hi - lo, 1);
        for (Double v : new Double[] {expected, actual}) {
            if (v != null && Double.isFinite(v) && v >= lo - reach && v <= hi + reach) {
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
            }
        }
        if (singletons || hi == lo) {
            double room = hi > lo ? (hi - lo) * 0.04 : 1;
            lo -= room;
            hi += room;
        }
        return roundOut(lo, hi);
    }

    /** The smallest span of five equal steps of 1, 2, 2.5 or 5 times a power of ten that holds [lo, hi]. */
    static double[] roundOut(double lo, double hi) {
        double step = Math.pow(10, Math.floor(Math.log10((hi - lo) / 5)));
        for (int k = 0; k < 12; k++) {
            for (double m : new double[] {1, 2, 2.5, 5}) {
                double s = step * m;
                double start = Math.floor(lo / s) * s;
                if (start + 5 * s >= hi) {
                    return new double[] {start, start + 5 * s};
                }
            }
            step *= 10;
        }
        return new double[] {lo, hi};
    }

    /** A value as the legend writes it: an integer as such, else six significant digits without trailing zeros. */
    static String text(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value)
                : String.format(java.util.Locale.ROOT, "%.6g", value).replaceAll("(\\.\\d*?)0+($|e)", "$1$2")
                        .replaceAll("\\.($|e)", "$1");
    }

    /** A vertical line at {@code value}, or at the edge it lies beyond; the legend's text for it. */
    private static String marker(Svg svg, double value, double[] d, String colour, String dashes) {
        String text = text(value);
        if (Double.isNaN(value)) {
            return text + " (not drawn)";
        }
        double u = Math.max(d[0], Math.min(d[1], value));
        String note = u == value ? text : text + (value < d[0] ? " (off the axis, left)" : " (off the axis, right)");
        double x = Plotter.px(u, d);
        svg.raw("<line class=\"marker\" x1=\"" + Svg.n(x) + "\" y1=\"" + Plotter.TOP + "\" x2=\"" + Svg.n(x) + "\" y2=\""
                + (Plotter.TOP + Plotter.PLOT_HEIGHT) + "\" stroke=\"" + colour + "\" stroke-width=\"2.5\""
                + (dashes == null ? "" : " stroke-dasharray=\"" + dashes + "\"") + "/>");
        return note;
    }
}
