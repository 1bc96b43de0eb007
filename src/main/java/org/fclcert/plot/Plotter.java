package org.fclcert.plot;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;
import org.fclcert.check.CoverageGaps;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.Trace;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * Draws one function block of a checked program: a picture of the terms of every fuzzified input and
 * defuzzified output; for every output, its control surface over the first two inputs (the others fixed)
 * or, with one input, its transfer curve. Fixed inputs take the value given, else their initial value,
 * else the middle of their terms' span. Usage: {@code new Plotter(program, "fb", Map.of()).pictures()}.
 */
public final class Plotter {
    /** Picture size and plot area, in SVG user units (= CSS pixels): the tests find the curves by them. */
    public static final int WIDTH = 640;
    public static final int HEIGHT = 400;
    public static final int LEFT = 64;
    public static final int TOP = 36;
    public static final int PLOT_WIDTH = 400;
    public static final int PLOT_HEIGHT = 300;
    /** Samples of an input's axis for input terms and transfer curves; cells per side of a surface. */
    static final int SAMPLES = 240;
    static final int CELLS = 48;
    /** Term colours, in term order (colour-blind safe Tableau 10 order). */
    public static final List<String> PALETTE = List.of("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
            "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22");
    /** The heat map's colour scale, low to high (viridis at five stops, interpolated between them). */
    static final int[][] SCALE = {{0x44, 0x01, 0x54}, {0x3b, 0x52, 0x8b}, {0x21, 0x91, 0x8c}, {0x5e, 0xc9, 0x62},
        {0xfd, 0xe7, 0x25}};

    /** One picture: a file name ({@code block-variable-terms.svg}) and its SVG text. */
    public record Picture(String fileName, String svg) {
    }

    private final FunctionBlock block;
    private final FunctionBlockInstance instance;
    private final Map<String, Double> fixed = new LinkedHashMap<>();

    /**
     * @param program  a checked program (no errors)
     * @param block    the function block to draw, or null for the first
     * @param given    values for inputs held fixed in surfaces and curves (by name, case-insensitive)
     */
    public Plotter(Program program, String block, Map<String, Double> given) throws EvaluationException {
        this.block = block == null ? program.functionBlocks().get(0)
                : program.functionBlock(block).orElseThrow(() -> new IllegalArgumentException("no block " + block));
        this.instance = Evaluator.load(program).newInstance(this.block.name());
        for (Variable v : this.block.variables(VariableKind.INPUT)) {
            Double value = given.entrySet().stream().filter(e -> Names.same(e.getKey(), v.name()))
                    .map(Map.Entry::getValue).findFirst()
                    .orElse(v.initialValue().map(Literal::value).orElse(middle(domain(v.name()))));
            fixed.put(v.name(), value);
        }
    }

    private List<String> axes = List.of();

    /**
     * The two inputs a control surface is drawn over, x then y (default: the first two inputs with terms); the
     * others are held at their fixed values.
     *
     * @throws IllegalArgumentException when a name is not an input with a FUZZIFY block, or both are one input
     */
    public Plotter withAxes(String x, String y) {
        String ax = axisInput(x);
        String ay = axisInput(y);
        if (Names.same(ax, ay)) {
            throw new IllegalArgumentException("--axes names '" + ax + "' twice; give two different inputs");
        }
        axes = List.of(ax, ay);
        return this;
    }

    private String axisInput(String name) {
        return block.variables(VariableKind.INPUT).stream().map(Variable::name)
                .filter(n -> Names.same(n, name) && block.fuzzification(n).isPresent()).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("--axes " + name + ": not an input with terms; "
                        + "the inputs with terms: " + String.join(", ", block.variables(VariableKind.INPUT).stream()
                                .map(Variable::name).filter(n -> block.fuzzification(n).isPresent()).toList())));
    }

    /** True when the block declares this input (case-insensitive). */
    public boolean hasInput(String name) {
        return fixed.keySet().stream().anyMatch(n -> Names.same(n, name));
    }

    public List<String> inputNames() {
        return List.copyOf(fixed.keySet());
    }

    /** Every picture of the block, in a stable order: terms of inputs, of outputs, then surfaces or curves. */
    public List<Picture> pictures() throws EvaluationException {
        List<Picture> all = new ArrayList<>();
        for (Variable v : block.variables(VariableKind.INPUT)) {
            if (block.fuzzification(v.name()).isPresent()) {
                all.add(inputTerms(v.name()));
            }
        }
        for (Variable v : block.variables(VariableKind.OUTPUT)) {
            if (block.defuzzification(v.name()).isPresent()) {
                all.add(outputTerms(v.name()));
            }
        }
        List<String> inputs = block.variables(VariableKind.INPUT).stream().map(Variable::name)
                .filter(n -> block.fuzzification(n).isPresent()).toList();
        for (Variable out : block.variables(VariableKind.OUTPUT)) {
            if (!axes.isEmpty()) {
                all.add(surface(axes.get(0), axes.get(1), out.name()));
            } else if (inputs.size() >= 2) {
                all.add(surface(inputs.get(0), inputs.get(1), out.name()));
            } else if (inputs.size() == 1) {
                all.add(transfer(inputs.get(0), out.name()));
            }
        }
        return all;
    }

    /** The span an axis shows: the declared RANGE, else the span of the terms' abscissas. */
    double[] domain(String variable) {
        Optional<Range> range = block.defuzzification(variable).flatMap(Defuzzification::range)
                .or(() -> block.fuzzification(variable).flatMap(Fuzzification::declaredRange));
        if (range.isPresent()) {
            return widen(range.get().min().value(), range.get().max().value());
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Term t : terms(variable)) {
            for (double x : abscissas(t.function())) {
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        return lo > hi ? new double[] {0, 1} : widen(lo, hi);
    }

    private static double[] widen(double lo, double hi) {
        return hi > lo ? new double[] {lo, hi} : new double[] {lo - 1, hi + 1};
    }

    private static double middle(double[] d) {
        return (d[0] + d[1]) / 2;
    }

    private List<Term> terms(String variable) {
        return block.fuzzification(variable).map(Fuzzification::terms)
                .or(() -> block.defuzzification(variable).map(Defuzzification::terms)).orElse(List.of());
    }

    /** The literal abscissas a term is drawn through (points, a singleton, a shape's parameters). */
    private static List<Double> abscissas(MembershipFunction f) {
        List<Double> xs = new ArrayList<>();
        if (f instanceof MembershipFunction.Points p) {
            for (Point pt : p.points()) {
                if (pt.x() instanceof Literal l) {
                    xs.add(l.value());
                }
            }
        } else if (f instanceof MembershipFunction.Singleton s && s.value() instanceof Literal l) {
            xs.add(l.value());
        } else if (f instanceof MembershipFunction.NamedShape n) {
            for (double v : n.values()) {
                xs.add(v);
            }
        }
        return xs;
    }

    private Picture inputTerms(String input) throws EvaluationException {
        double[] d = domain(input);
        TreeSet<Double> us = samples(d);
        for (Term t : terms(input)) {
            abscissas(t.function()).stream().filter(x -> x >= d[0] && x <= d[1]).forEach(us::add);   // exact corners
        }
        List<Term> terms = terms(input);
        double[][] degrees = new double[terms.size()][us.size()];
        int i = 0;
        for (double u : us) {
            Trace trace = evaluateAt(Map.of(input, u));
            for (int k = 0; k < terms.size(); k++) {
                degrees[k][i] = trace.termDegree(input, terms.get(k).name()).orElse(0.0);
            }
            i++;
        }
        double[] xs = us.stream().mapToDouble(Double::doubleValue).toArray();
        Svg svg = frame("terms of input " + input, d, new double[] {0, 1}, input, "degree of membership");
        for (int k = 0; k < terms.size(); k++) {
            curve(svg, xs, degrees[k], d, new double[] {0, 1}, PALETTE.get(k % PALETTE.size()), "term");
        }
        legend(svg, terms.stream().map(Term::name).toList());
        return new Picture(fileName(input + "-terms"), svg.finish());
    }

    private Picture outputTerms(String output) {
        double[] d = domain(output);
        List<Term> terms = terms(output);
        Svg svg = frame("terms of output " + output, d, new double[] {0, 1}, output, "degree of membership");
        for (int k = 0; k < terms.size(); k++) {
            String colour = PALETTE.get(k % PALETTE.size());
            MembershipFunction f = terms.get(k).function();
            if (f instanceof MembershipFunction.Singleton s && s.value() instanceof Literal l) {
                double x = px(l.value(), d);
                svg.line(x, py(0, new double[] {0, 1}), x, py(1, new double[] {0, 1}), colour, 3);
            } else if (f instanceof MembershipFunction.Points p && p.points().stream()
                    .allMatch(pt -> pt.x() instanceof Literal && pt.degree() instanceof Literal)) {
                List<Point> pts = p.points();
                double[] xs = new double[pts.size() + 2];
                double[] ys = new double[pts.size() + 2];
                // outside its points a term keeps the degree of its outer points (5.2.2)
                xs[0] = Math.min(d[0], ((Literal) pts.get(0).x()).value());
                ys[0] = ((Literal) pts.get(0).degree()).value();
                for (int j = 0; j < pts.size(); j++) {
                    xs[j + 1] = ((Literal) pts.get(j).x()).value();
                    ys[j + 1] = ((Literal) pts.get(j).degree()).value();
                }
                xs[pts.size() + 1] = Math.max(d[1], xs[pts.size()]);
                ys[pts.size() + 1] = ys[pts.size()];
                curve(svg, xs, ys, d, new double[] {0, 1}, colour, "term");
            } else if (f instanceof MembershipFunction.NamedShape n) {
                TreeSet<Double> us = samples(d);
                double[] xs = us.stream().mapToDouble(Double::doubleValue).toArray();
                double[] ys = new double[xs.length];
                for (int j = 0; j < xs.length; j++) {
                    ys[j] = n.kind().degree(n.values(), xs[j]);
                }
                curve(svg, xs, ys, d, new double[] {0, 1}, colour, "term");
            }
        }
        legend(svg, terms.stream().map(Term::name).toList());
        return new Picture(fileName(output + "-terms"), svg.finish());
    }

    private Picture transfer(String input, String output) throws EvaluationException {
        double[] d = domain(input);
        double[] xs = samples(d).stream().mapToDouble(Double::doubleValue).toArray();
        double[] ys = new double[xs.length];
        for (int i = 0; i < xs.length; i++) {
            ys[i] = valueAt(Map.of(input, xs[i]), output);
        }
        double[] range = span(ys, domain(output));
        Svg svg = frame(output + " over " + input + fixedNote(List.of(input)), d, range, input, output);
        gaps(svg, output, input, null, d, range);
        curve(svg, xs, ys, d, range, PALETTE.get(0), "transfer");
        return new Picture(fileName(output + "-over-" + input), svg.finish());
    }

    private Picture surface(String x, String y, String output) throws EvaluationException {
        double[] dx = domain(x);
        double[] dy = domain(y);
        double[][] z = new double[CELLS][CELLS];
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < CELLS; i++) {
            for (int j = 0; j < CELLS; j++) {
                double u = dx[0] + (i + 0.5) * (dx[1] - dx[0]) / CELLS;
                double v = dy[0] + (j + 0.5) * (dy[1] - dy[0]) / CELLS;
                z[i][j] = valueAt(Map.of(x, u, y, v), output);
                lo = Math.min(lo, z[i][j]);
                hi = Math.max(hi, z[i][j]);
            }
        }
        Svg svg = frame(output + " over " + x + " and " + y + fixedNote(List.of(x, y)), dx, dy, x, y);
        svg.raw("<g shape-rendering=\"crispEdges\">");
        double w = (double) PLOT_WIDTH / CELLS;
        double h = (double) PLOT_HEIGHT / CELLS;
        for (int i = 0; i < CELLS; i++) {
            for (int j = 0; j < CELLS; j++) {
                double t = hi > lo ? (z[i][j] - lo) / (hi - lo) : 0.5;
                // cells overlap by a hair so that no background shows between them
                svg.rect(LEFT + i * w, TOP + PLOT_HEIGHT - (j + 1) * h, w + 0.3, h + 0.3, colour(t));
            }
        }
        svg.raw("</g>");
        gaps(svg, output, x, y, dx, dy);
        // the colour scale: a bar from low (bottom) to high (top), labelled with the output's values
        int bx = LEFT + PLOT_WIDTH + 30;
        int steps = 60;
        svg.raw("<g shape-rendering=\"crispEdges\">");
        for (int k = 0; k < steps; k++) {
            svg.rect(bx, TOP + PLOT_HEIGHT - (k + 1) * (double) PLOT_HEIGHT / steps, 18,
                    (double) PLOT_HEIGHT / steps + 0.3, colour((k + 0.5) / steps));
        }
        svg.raw("</g>");
        for (int k = 0; k <= 4; k++) {
            double value = lo + (hi - lo) * k / 4;
            // a sum that should be 0 may come out as -2.8e-14: labels are for reading
            svg.text(bx + 24, TOP + PLOT_HEIGHT - k * PLOT_HEIGHT / 4.0 + 4, "start",
                    label(Math.abs(value) < 1e-9 * Math.max(Math.abs(lo), Math.abs(hi)) ? 0 : value));
        }
        svg.text(bx + 9, TOP - 10, "middle", output);
        return new Picture(fileName(output + "-over-" + x + "-and-" + y), svg.finish());
    }

    /** Colour of the regions where no rule fires (FCL-W005). */
    public static final String GAP = "#ff00cc";

    /**
     * The regions where no rule of the one rule block concluding {@code output} fires ({@link CoverageGaps}), cut
     * at the values the other inputs are held at: hatched boxes outlined in {@link #GAP} (a zero-width region is
     * a line), over a surface ({@code y} an input) or as bands over a transfer curve ({@code y} null).
     */
    private void gaps(Svg svg, String output, String x, String y, double[] dx, double[] dy) {
        List<RuleBlock> concluding = block.ruleBlocks().stream().filter(rb -> rb.rules().stream()
                .anyMatch(r -> r.conclusion().stream().anyMatch(c -> Names.same(c.variable(), output)))).toList();
        if (concluding.size() != 1) {
            return;    // with several blocks, the output falls back only where all are silent: not drawn
        }
        CoverageGaps.Result result = CoverageGaps.of(block, concluding.get(0));
        List<double[]> boxes = new ArrayList<>();
        for (CoverageGaps.Box box : result.gaps()) {
            double[] r = {Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                Double.POSITIVE_INFINITY};
            boolean shown = true;
            for (int a = 0; a < result.inputs().size(); a++) {
                String input = result.inputs().get(a);
                CoverageGaps.Interval in = box.intervals().get(a);
                if (Names.same(input, x)) {
                    r[0] = in.low();
                    r[1] = in.high();
                } else if (y != null && Names.same(input, y)) {
                    r[2] = in.low();
                    r[3] = in.high();
                } else {
                    shown &= contains(in, fixed.get(input));
                }
            }
            if (shown) {
                boxes.add(r);
            }
        }
        if (boxes.isEmpty()) {
            return;
        }
        svg.raw("<defs><pattern id=\"gap-hatch\" width=\"8\" height=\"8\" patternUnits=\"userSpaceOnUse\""
                + " patternTransform=\"rotate(45)\"><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"8\" stroke=\"" + GAP
                + "\" stroke-width=\"3\"/></pattern></defs>");
        svg.raw("<g class=\"gaps\">");
        for (double[] r : boxes) {
            double x0 = px(Math.max(r[0], dx[0]), dx);
            double x1 = px(Math.min(r[1], dx[1]), dx);
            double y0 = y == null ? TOP + PLOT_HEIGHT : py(Math.max(r[2], dy[0]), dy);
            double y1 = y == null ? TOP : py(Math.min(r[3], dy[1]), dy);
            if (x1 < x0 || y0 < y1) {
                continue;    // outside the drawn span
            }
            // a zero-width region still shows: at least 2 px wide
            double w = Math.max(x1 - x0, 2);
            double h = Math.max(y0 - y1, 2);
            svg.raw("<rect class=\"gap\" x=\"" + Svg.n(x0 - (w - (x1 - x0)) / 2) + "\" y=\""
                    + Svg.n(y1 - (h - (y0 - y1)) / 2) + "\" width=\"" + Svg.n(w) + "\" height=\"" + Svg.n(h)
                    + "\" fill=\"url(#gap-hatch)\" fill-opacity=\"0.6\" stroke=\"" + GAP + "\" stroke-width=\"2\"/>");
        }
        svg.raw("</g>");
        svg.text(LEFT, HEIGHT - 8, "start", "hatched: no rule fires, " + output + " falls back (FCL-W005)");
    }

    private static boolean contains(CoverageGaps.Interval in, Double v) {
        return v != null && in.contains(v);
    }

    private String fixedNote(List<String> varying) {
        List<String> others = new ArrayList<>();
        fixed.forEach((name, value) -> {
            if (varying.stream().noneMatch(v -> Names.same(v, name))) {
                others.add(name + " = " + label(value));
            }
        });
        return others.isEmpty() ? "" : " (" + String.join(", ", others) + ")";
    }

    private Trace evaluateAt(Map<String, Double> varying) throws EvaluationException {
        instance.reset();
        for (Map.Entry<String, Double> e : fixed.entrySet()) {
            instance.set(e.getKey(), varying.getOrDefault(e.getKey(), e.getValue()));
        }
        Trace trace = new Trace();
        instance.evaluate(trace);
        return trace;
    }

    private double valueAt(Map<String, Double> varying, String output) throws EvaluationException {
        instance.reset();
        for (Map.Entry<String, Double> e : fixed.entrySet()) {
            instance.set(e.getKey(), varying.getOrDefault(e.getKey(), e.getValue()));
        }
        instance.evaluate();
        return instance.get(output);
    }

    private static TreeSet<Double> samples(double[] d) {
        TreeSet<Double> us = new TreeSet<>();
        for (int i = 0; i <= SAMPLES; i++) {
            us.add(d[0] + (d[1] - d[0]) * i / SAMPLES);
        }
        return us;
    }

    private static double[] span(double[] ys, double[] fallback) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double y : ys) {
            if (Double.isFinite(y)) {
                lo = Math.min(lo, y);
                hi = Math.max(hi, y);
            }
        }
        if (lo > hi) {
            return fallback;
        }
        double pad = hi > lo ? (hi - lo) * 0.05 : 1;
        return new double[] {lo - pad, hi + pad};
    }

    /** Plot coordinates: value {@code u} on an axis spanning {@code d}. */
    public static double px(double u, double[] d) {
        return LEFT + (u - d[0]) / (d[1] - d[0]) * PLOT_WIDTH;
    }

    public static double py(double v, double[] d) {
        return TOP + (1 - (v - d[0]) / (d[1] - d[0])) * PLOT_HEIGHT;
    }

    private Svg frame(String title, double[] dx, double[] dy, String xLabel, String yLabel) {
        return frame(block.name() + ": " + title, dx, dy, xLabel, yLabel, WIDTH);
    }

    /** A picture with its title, the plot area's border, ticks and labels on both axes. */
    static Svg frame(String title, double[] dx, double[] dy, String xLabel, String yLabel, int width) {
        Svg svg = new Svg(width, HEIGHT, title);
        svg.text(LEFT + PLOT_WIDTH / 2.0, 20, "middle", title);
        svg.raw("<rect x=\"" + LEFT + "\" y=\"" + TOP + "\" width=\"" + PLOT_WIDTH + "\" height=\"" + PLOT_HEIGHT
                + "\" fill=\"none\" stroke=\"#444444\" stroke-width=\"1\"/>");
        for (int k = 0; k <= 5; k++) {
            double u = dx[0] + (dx[1] - dx[0]) * k / 5;
            double x = px(u, dx);
            svg.line(x, TOP + PLOT_HEIGHT, x, TOP + PLOT_HEIGHT + 5, "#444444", 1);
            svg.text(x, TOP + PLOT_HEIGHT + 18, "middle", label(u));
            double v = dy[0] + (dy[1] - dy[0]) * k / 5;
            double y = py(v, dy);
            svg.line(LEFT - 5, y, LEFT, y, "#444444", 1);
            svg.text(LEFT - 8, y + 4, "end", label(v));
        }
        svg.text(LEFT + PLOT_WIDTH / 2.0, TOP + PLOT_HEIGHT + 38, "middle", xLabel);
        svg.raw("<text x=\"16\" y=\"" + Svg.n(TOP + PLOT_HEIGHT / 2.0) + "\" text-anchor=\"middle\" fill=\"#222222\""
                + " transform=\"rotate(-90 16 " + Svg.n(TOP + PLOT_HEIGHT / 2.0) + ")\">" + Svg.escape(yLabel)
                + "</text>");
        return svg;
    }

    static void curve(Svg svg, double[] xs, double[] ys, double[] dx, double[] dy, String colour,
            String cssClass) {
        double[] px = new double[xs.length];
        double[] py = new double[ys.length];
        for (int i = 0; i < xs.length; i++) {
            px[i] = px(xs[i], dx);
            py[i] = py(ys[i], dy);
        }
        svg.polyline(px, py, colour, 2.5, cssClass);
    }

    private static void legend(Svg svg, List<String> names) {
        int x = LEFT + PLOT_WIDTH + 24;
        for (int k = 0; k < names.size(); k++) {
            int y = TOP + 10 + k * 20;
            svg.line(x, y, x + 24, y, PALETTE.get(k % PALETTE.size()), 3);
            svg.text(x + 30, y + 4, "start", names.get(k));
        }
    }

    /** A colour of the scale at {@code t} in [0, 1]. */
    static String colour(double t) {
        double s = Math.max(0, Math.min(1, t)) * (SCALE.length - 1);
        int i = Math.min((int) s, SCALE.length - 2);
        double f = s - i;
        int[] rgb = new int[3];
        for (int c = 0; c < 3; c++) {
            rgb[c] = (int) Math.round(SCALE[i][c] + f * (SCALE[i + 1][c] - SCALE[i][c]));
        }
        return String.format(Locale.ROOT, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
    }

    static String label(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e9) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.4g", v).replaceAll("(\\.\\d*?)0+$", "$1").replaceAll("\\.$", "");
    }

    private String fileName(String what) {
        return (block.name() + "-" + what).replaceAll("[^A-Za-z0-9_.-]", "_") + ".svg";
    }
}
