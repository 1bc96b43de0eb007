package org.fclcert.harness;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.SplittableRandom;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Vector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.FairVectors;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Point;
import org.fclcert.model.Program;

/**
 * Fresh input vectors for a positive case, drawn for this run from the run seed ({@link RunSeed}), so that a
 * result cannot be had by remembering the corpus's answers. Up to {@link #COUNT} vectors per case, each input
 * drawn over the span of the case's own values and its terms' points (a point of 1/1000 of the span, read as a
 * short decimal); the expected outputs are the reference's exact path (fclcert's reading of numbers). A drawn
 * vector is kept only when:
 * <ul>
 * <li>the reference evaluates it without error to finite outputs, or, in a case that expects some steps refused
 * (conformance/README.md), ends it in an evaluation error of a code the case expects: a fresh refused step;</li>
 * <li>its outputs do not depend on what came before (the same after the case's first vector as on a fresh
 * instance, and the same where the run puts it, after the corpus vectors), so the harness's reverse-order rerun
 * stays fair;</li>
 * <li>it is fair by the exact judge's knife-edge test ({@link FairVectors#judge}, the case's tolerance deciding
 * what agrees), as corpus lint asks of every corpus vector.</li>
 * </ul>
 * Stateful cases get none (their steps are a story told in order), nor do cases the reference cannot read.
 */
public final class FreshVectors {
    /** How many vectors are drawn per case: guessing all is hopeless, and the exact judge stays cheap. */
    public static final int COUNT = 8;

    private FreshVectors() {
    }

    /** {@code c} with its fresh vectors appended after its own (the same case when none can be drawn). */
    public static RunCase withFresh(RunCase c, long seed) {
        if (c.expectReject() || c.stateful() || c.vectors().isEmpty()) {
            return c;
        }
        List<Vector> fresh = draw(c, RunSeed.forCase(seed, c.id(), "vectors"));
        if (fresh.isEmpty()) {
            return c;
        }
        List<Vector> all = new ArrayList<>(c.vectors());
        all.addAll(fresh);
        return new RunCase(c.id(), c.title(), c.level(), c.features(), c.tests(), c.flags(), c.block(), all,
                c.expectedError(), c.tolerance(), c.program(), c.source(), c.dialect());
    }

    private static List<Vector> draw(RunCase c, SplittableRandom random) {
        Optional<Program> program;
        try {
            program = Analysis.analyze(c.reader(), c.id(), c.program()).program();
        } catch (RuntimeException | StackOverflowError e) {
            return List.of();
        }
        if (program.isEmpty()) {
            return List.of();
        }
        String block = c.block().orElse(null);
        Optional<FunctionBlock> fb = block == null ? program.get().functionBlocks().stream().findFirst()
                : program.get().functionBlock(block);
        if (fb.isEmpty()) {
            return List.of();
        }
        Optional<Vector> model = c.vectors().stream().filter(v -> !v.refused()).findFirst();
        if (model.isEmpty()) {
            return List.of();
        }
        LoadedProgram loaded = Evaluator.load(program.get());
        List<String> inputs = List.copyOf(model.get().in().keySet());
        List<String> outputs = List.copyOf(model.get().out().keySet());
        Map<String, double[]> spans = new LinkedHashMap<>();
        for (String in : inputs) {
            spans.put(in, span(c, fb.get(), in));
        }
        // a case that expects some steps refused gets fresh refused steps too (the same codes), so that refusing the
        // corpus's own inputs is not enough
        Set<String> refusals = new HashSet<>();
        c.vectors().forEach(v -> v.error().ifPresent(refusals::add));
        List<Vector> kept = new ArrayList<>();
        for (int tries = 0; tries < 3 * COUNT && kept.size() < COUNT; tries++) {
            Map<String, Double> in = new LinkedHashMap<>();
            spans.forEach((name, s) -> in.put(name, pick(s, random)));
            expected(loaded, block, List.of(in), outputs, refusals)
                    .filter(alone -> expected(loaded, block, List.of(model.get().in(), in), outputs, refusals)
                            .filter(alone::equals).isPresent())
                    .ifPresent(kept::add);
        }
        return fairInSequence(c, loaded, block, outputs, kept);
    }

    /** The kept vectors that give the same values after the corpus vectors and are no knife edge there. */
    private static List<Vector> fairInSequence(RunCase c, LoadedProgram loaded, String block, List<String> outputs,
            List<Vector> fresh) {
        if (fresh.isEmpty()) {
            return fresh;
        }
        List<Map<String, Double>> steps = new ArrayList<>(c.vectors().stream().map(Vector::in).toList());
        fresh.forEach(v -> steps.add(v.in()));
        FairVectors.Verdict verdict;
        List<Vector> inOrder;
        try {
            verdict = FairVectors.judge(loaded, block, steps, (out, a, b) -> c.tolerance().accepts(out, a, b));
            inOrder = run(loaded, block, steps, outputs);
        } catch (RuntimeException | EvaluationException e) {
            // fresh vectors are extra evidence: where the judge cannot judge them (a defect of fclcert's own, as an
            // ArithmeticException of the exact path would be) none is drawn, and the case's own vectors still run
            return List.of();
        }
        List<Vector> out = new ArrayList<>();
        int first = c.vectors().size();
        for (int i = 0; i < fresh.size(); i++) {
            int step = first + i + 1;
            if (verdict.fair(step) && i + first < inOrder.size() && inOrder.get(i + first).equals(fresh.get(i))) {
                out.add(fresh.get(i));
            }
        }
        return out;
    }

    /**
     * The answer of one fresh exact instance to the last of {@code steps}: its outputs when finite, or a refused step
     * when the evaluation ends in an error whose code is one of {@code refusals}; empty otherwise.
     */
    private static Optional<Vector> expected(LoadedProgram loaded, String block, List<Map<String, Double>> steps,
            List<String> outputs, Set<String> refusals) {
        try {
            List<Vector> all = run(loaded, block, steps, outputs);
            Vector last = all.get(all.size() - 1);
            boolean usable = last.refused() ? refusals.contains(last.error().get())
                    : last.out().values().stream().allMatch(Double::isFinite);
            return usable ? Optional.of(last) : Optional.empty();
        } catch (EvaluationException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /**
     * Each of {@code steps} on one exact instance, with its outputs, or refused with the code of the evaluation error
     * it ends in (a corpus step that must be refused: the steps after it still run).
     */
    private static List<Vector> run(LoadedProgram loaded, String block, List<Map<String, Double>> steps,
            List<String> outputs) throws EvaluationException {
        ExactInstance fb = loaded.newExactInstance(block, NumberReading.DECIMAL);
        List<Vector> out = new ArrayList<>();
        for (Map<String, Double> step : steps) {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                fb.set(e.getKey(), e.getValue());
            }
            String refused = EvaluationException.refusalOf(fb::evaluate);
            if (refused != null) {
                out.add(Vector.refused(step, refused));
                continue;
            }
            Map<String, Double> values = new LinkedHashMap<>();
            for (String o : outputs) {
                values.put(o, fb.get(o));
            }
            out.add(new Vector(step, values));
        }
        return out;
    }

    /** The span an input is drawn over: the case's own values of it and its terms' written points. */
    private static double[] span(RunCase c, FunctionBlock fb, String input) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Vector v : c.vectors()) {
            Double x = v.in().get(input);
            if (x != null && Double.isFinite(x)) {
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        for (Fuzzification f : fb.fuzzifications()) {
            if (!Names.same(f.variable(), input)) {
                continue;
            }
            for (double x : f.terms().stream().flatMap(t -> xs(t.function()).stream()).toList()) {
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        if (!(lo < hi)) {
            double at = Double.isFinite(lo) ? lo : 0;
            return new double[] {at - 1, at + 1};
        }
        return new double[] {lo, hi};
    }

    private static List<Double> xs(MembershipFunction f) {
        List<Double> out = new ArrayList<>();
        List<Point> points = f instanceof MembershipFunction.Points p ? p.points()
                : f instanceof MembershipFunction.NamedShape s ? s.points().orElse(List.of()) : List.of();
        for (Point p : points) {
            if (p.x() instanceof Literal l && Double.isFinite(l.value())) {
                out.add(l.value());
            }
        }
        if (f instanceof MembershipFunction.Singleton s && s.value() instanceof Literal l) {
            out.add(l.value());
        }
        return out;
    }

    /**
     * A point of 1/1000 of the span, written with at most 6 significant digits (a short decimal). A span wider
     * than the largest double (term points near both ends of LREAL) is stepped on its halved ends:
     * its width would overflow to infinity and the point with it.
     */
    static double pick(double[] span, SplittableRandom random) {
        int k = random.nextInt(1001);
        double width = span[1] - span[0];
        double x = Double.isFinite(width) ? span[0] + width * k / 1000.0
                : 2 * (span[0] / 2 + (span[1] / 2 - span[0] / 2) * (k / 1000.0));
        return new BigDecimal(x).round(new MathContext(6)).doubleValue();
    }
}
