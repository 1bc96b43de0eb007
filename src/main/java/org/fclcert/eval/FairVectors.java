package org.fclcert.eval;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.DoubleUnaryOperator;

/**
 * Tells whether a sequence of input vectors is fair to judge (docs/semantics.md, point 10): whether every
 * reasonable arithmetic gives the same outputs within tolerance. The sequence is run on the exact path under
 * fclcert's reading ({@link NumberReading#DECIMAL}) and under perturbations that a conforming implementation may
 * equally well apply:
 * <ul>
 * <li>the other reading of numbers ({@link NumberReading#BINARY}: literals and inputs as their exact doubles);</li>
 * <li>plain double arithmetic ({@link LoadedProgram#newDoubleInstance}: the reference's arithmetic without its exact
 * fallback);</li>
 * <li>each input set by the vectors nudged one ulp up, then one ulp down (in every step), except in a step
 * where another input has the same value: equal inputs are equal in every arithmetic, so a tie between them is
 * no knife edge;</li>
 * <li>all those inputs nudged up together, and down together.</li>
 * </ul>
 * An input is not nudged in a step where its value equals a number written in the program (a point's x or
 * degree, a singleton, a weight, a RANGE bound) or is 0 or 1: it then is the same number in every arithmetic
 * (both are read alike), interpolation and comparison at it are exact everywhere, and nudging it would test
 * the program's continuity rather than the arithmetic (an input exactly at a term's foot, where the rule stops
 * firing, is a fair test of DEFAULT).
 * An integer-typed output whose exact value before rounding is within 1e-9 of a half-integer, but not exactly one,
 * is a knife edge outright (the rounding is decided by bits no arithmetic need get right). One exactly at .5
 * stays .5 under every nudge (a flat set's CoG of 57.5), so the double-arithmetic run decides: if doubles give
 * 57.49999999999999, the vector is a knife edge; if they give 57.5 exactly (dyadic data), it is fair.
 * A step whose outputs differ beyond the agreement under any perturbation (or that fails under one and not the
 * other) is a <em>knife edge</em>: its expected value rests on a tie that rounding may break either way (a clip
 * level exactly at a vertex that decides LM, two equal maxima, an integer output at exactly .5, an input exactly
 * where a rule stops firing and nothing else fires). Corpus lint rejects such a vector unless its case flags it
 * ({@code knife-edge:<n>}), the harness then reports it as not judged; the fuzzer never generates one.
 *
 * <p>The runs are independent of the caller's instances. Cost: (2·inputs + 3) exact evaluations per step.
 */
public final class FairVectors {
    private FairVectors() {
    }

    /** Whether two values of one output count as the same answer. */
    @FunctionalInterface
    public interface Agreement {
        boolean same(String output, double reference, double other);
    }

    /** Within 1e-6, relative above magnitude 1 (the probe's comparison); NaN agrees with NaN. */
    public static final Agreement DEFAULT_AGREEMENT = (output, a, b) -> Double.isNaN(a) ? Double.isNaN(b)
            : Math.abs(a - b) <= 1e-6 * Math.max(1, Math.abs(a));

    /**
     * One knife edge: at {@code step} (1-based) {@code output} is {@code reference} under fclcert's reading and
     * {@code other} under {@code perturbation} (an output name {@code "<error>"} when one run failed: the values
     * are then NaN and {@code detail} holds the error).
     */
    public record KnifeEdge(int step, String output, double reference, double other, String perturbation,
            String detail) {
        @Override
        public String toString() {
            return "step " + step + ": " + output + " = " + reference + ", but " + other + " with " + perturbation
                    + (detail.isEmpty() ? "" : " (" + detail + ")");
        }
    }

    /**
     * The verdict on a sequence: its knife edges (empty when fair); {@code exact} false when the program uses a
     * construct the exact path computes in floating point (smooth shapes, PROBOR on point terms), so that the
     * verdict itself is only as good as doubles.
     */
    public record Verdict(List<KnifeEdge> knifeEdges, boolean exact) {
        public Verdict {
            knifeEdges = List.copyOf(knifeEdges);
        }

        public boolean fair() {
            return knifeEdges.isEmpty();
        }

        /** Whether step (1-based) is fair. */
        public boolean fair(int step) {
            return knifeEdges.stream().noneMatch(k -> k.step() == step);
        }

        /** The 1-based steps that are knife edges, ascending. */
        public List<Integer> knifeEdgeSteps() {
            return knifeEdges.stream().map(KnifeEdge::step).distinct().sorted().toList();
        }
    }

    /** Whether one vector, on a fresh instance of the first function block, is fair (default agreement). */
    public static boolean isFair(LoadedProgram program, Map<String, Double> inputs) {
        return judge(program, null, List.of(inputs), DEFAULT_AGREEMENT).fair();
    }

    /** Whether a sequence of vectors on one instance of {@code block} (null: the first) is fair. */
    public static boolean isFair(LoadedProgram program, String block, List<Map<String, Double>> steps) {
        return judge(program, block, steps, DEFAULT_AGREEMENT).fair();
    }

    /**
     * Runs {@code steps} in order on fresh exact instances of {@code block} (null: the first function block), one
     * per perturbation, and reports every step whose outputs move beyond {@code agreement}.
     *
     * @throws IllegalArgumentException when the program has no such block
     */
    public static Verdict judge(LoadedProgram program, String block, List<Map<String, Double>> steps,
            Agreement agreement) {
        return judge(program, block, steps, agreement, true);
    }

    /**
     * As {@link #judge(LoadedProgram, String, List, Agreement)}; without the double-arithmetic run when
     * {@code withFastPath} is false — without the plain-double run, for a test that compares doubles with the exact
     * path, which must not let doubles vouch for themselves. An integer output rounded from exactly k + ½ is then a knife edge
     * outright (doubles may compute k + ½ − 1 ulp).
     */
    static Verdict judge(LoadedProgram program, String block, List<Map<String, Double>> steps, Agreement agreement,
            boolean withFastPath) {
        Objects.requireNonNull(agreement);
        Set<String> inputs = new LinkedHashSet<>();
        steps.forEach(s -> inputs.addAll(s.keySet()));
        List<Run> runs = new ArrayList<>();
        Run reference = run(program, block, steps, NumberReading.DECIMAL, (n, v) -> false, v -> v,
                "fclcert's reading", !withFastPath);
        runs.add(run(program, block, steps, NumberReading.BINARY, (n, v) -> false, v -> v,
                "literals and inputs read as their exact binary doubles"));
        if (withFastPath) {
            runs.add(fast(program, block, steps));
        }
        BlockPlan plan = program.plan(block);
        Set<Double> literals = plan == null ? Set.of() : literals(plan);
        java.util.function.BiPredicate<String, Double> nudgeable = (name, v) -> !literals.contains(v);
        for (String in : inputs) {
            // alone only where no other input of the step has the same value (equal inputs stay equal everywhere)
            java.util.function.BiPredicate<String, Double> alone = (n, v) -> n.equals(in) && nudgeable.test(n, v)
                    && steps.stream().noneMatch(st -> v.equals(st.get(in)) && st.entrySet().stream()
                            .anyMatch(e -> !e.getKey().equals(in) && v.equals(e.getValue())));
            runs.add(run(program, block, steps, NumberReading.DECIMAL, alone, Math::nextUp, "input " + in + " one ulp up"));
            runs.add(run(program, block, steps, NumberReading.DECIMAL, alone, Math::nextDown,
                    "input " + in + " one ulp down"));
        }
        if (inputs.size() > 1) {
            runs.add(run(program, block, steps, NumberReading.DECIMAL, nudgeable, Math::nextUp,
                    "every input one ulp up"));
            runs.add(run(program, block, steps, NumberReading.DECIMAL, nudgeable, Math::nextDown,
                    "every input one ulp down"));
        }
        List<KnifeEdge> edges = new ArrayList<>();
        for (int i = 0; i < steps.size(); i++) {
            if (i < reference.halfway.size() && reference.halfway.get(i) != null) {
                String out = reference.halfway.get(i);
                double value = reference.outputs.get(i).get(out);
                edges.add(new KnifeEdge(i + 1, out, value, value + (value > 0 ? -1 : 1),
                        "rounding to the integer type at (or within 1e-9 of) a half-integer", ""));
                continue;
            }
            for (Run other : runs) {
                KnifeEdge k = compare(i, reference, other, agreement);
                if (k != null) {
                    edges.add(k);
                    break;
                }
            }
        }
        return new Verdict(edges, reference.exact);
    }

    private static KnifeEdge compare(int i, Run ref, Run other, Agreement agreement) {
        String refError = i < ref.errors.size() ? ref.errors.get(i) : "not run";
        String otherError = i < other.errors.size() ? other.errors.get(i) : "not run";
        if (refError != null || otherError != null) {
            if (Objects.equals(codeOf(refError), codeOf(otherError))) {
                return null;
            }
            String detail = refError != null ? "fclcert's reading: " + refError : other.name + ": " + otherError;
            return new KnifeEdge(i + 1, "<error>", Double.NaN, Double.NaN, other.name, detail);
        }
        Map<String, Double> a = ref.outputs.get(i);
        Map<String, Double> b = other.outputs.get(i);
        for (Map.Entry<String, Double> e : a.entrySet()) {
            double x = e.getValue();
            double y = b.get(e.getKey());
            if (!agreement.same(e.getKey(), x, y)) {
                return new KnifeEdge(i + 1, e.getKey(), x, y, other.name, "");
            }
        }
        return null;
    }

    private static String codeOf(String error) {
        return error == null ? null : error.length() >= 8 ? error.substring(0, 8) : error;
    }

    /** One perturbed run: per step its outputs, or the evaluation error it ended in. */
    private static final class Run {
        final String name;
        final List<Map<String, Double>> outputs = new ArrayList<>();
        final List<String> errors = new ArrayList<>();
        /** Per step: an output rounded to its integer type from a half-integer, else null. */
        final List<String> halfway = new ArrayList<>();
        /** On the reference run when no double-arithmetic run can tell (see judge). */
        boolean exactHalfIsKnifeEdge;
        boolean exact = true;

        Run(String name) {
            this.name = name;
        }
    }

    /** Every number written in the block (points, singletons, weights, ranges, defaults), and 0 and 1. */
    private static Set<Double> literals(BlockPlan plan) {
        Set<Double> out = new java.util.HashSet<>();
        out.add(0.0);
        out.add(-0.0);
        out.add(1.0);
        for (Shape s : plan.shapes) {
            for (int i = 0; i < s.n; i++) {
                if (s.xSlot[i] < 0) {
                    out.add(s.xConst[i]);
                }
                if (s.ySlot[i] < 0) {
                    out.add(s.yConst[i]);
                }
            }
        }
        for (BlockPlan.OutputPlan o : plan.outputs) {
            if (o.hasRange()) {
                out.add(o.rangeMin());
                out.add(o.rangeMax());
            }
        }
        for (BlockPlan.RuleBlockPlan rb : plan.ruleBlocks) {
            for (BlockPlan.SubconclusionPlan[] scs : rb.conclusions()) {
                for (BlockPlan.SubconclusionPlan sc : scs) {
                    if (sc.weightSlot() < 0) {
                        out.add(sc.weightConst());
                    }
                }
            }
        }
        return out;
    }

    /** Plain double arithmetic as one more arithmetic. */
    private static Run fast(LoadedProgram program, String block, List<Map<String, Double>> steps) {
        Run run = new Run("plain double arithmetic");
        FunctionBlockInstance fb;
        try {
            fb = program.newDoubleInstance(block);
        } catch (EvaluationException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        for (Map<String, Double> step : steps) {
            try {
                for (Map.Entry<String, Double> in : step.entrySet()) {
                    fb.set(in.getKey(), in.getValue());
                }
                fb.evaluate();
                run.outputs.add(new LinkedHashMap<>(fb.outputs()));
                run.errors.add(null);
                run.halfway.add(null);
            } catch (EvaluationException e) {
                run.outputs.add(Map.of());
                run.errors.add(e.toString());
                run.halfway.add(null);
                // the next steps still run: a step a case expects refused is followed by ordinary ones
            }
        }
        return run;
    }

    private static Run run(LoadedProgram program, String block, List<Map<String, Double>> steps,
            NumberReading reading, java.util.function.BiPredicate<String, Double> nudged, DoubleUnaryOperator nudge,
            String name) {
        return run(program, block, steps, reading, nudged, nudge, name, false);
    }

    private static Run run(LoadedProgram program, String block, List<Map<String, Double>> steps,
            NumberReading reading, java.util.function.BiPredicate<String, Double> nudged, DoubleUnaryOperator nudge,
            String name, boolean exactHalfIsKnifeEdge) {
        Run run = new Run(name);
        run.exactHalfIsKnifeEdge = exactHalfIsKnifeEdge;
        ExactInstance fb;
        try {
            fb = program.newExactInstance(block, reading);
        } catch (EvaluationException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        run.exact = fb.exact();
        for (Map<String, Double> step : steps) {
            try {
                for (Map.Entry<String, Double> in : step.entrySet()) {
                    double v = in.getValue();
                    fb.set(in.getKey(), Double.isFinite(v) && nudged.test(in.getKey(), v) ? nudge.applyAsDouble(v) : v);
                }
                fb.evaluate();
                run.outputs.add(new LinkedHashMap<>(fb.outputs()));
                run.errors.add(null);
                String half = null;
                for (String out : fb.outputNames()) {
                    if (half == null && (fb.roundedNearHalf(out)
                            || run.exactHalfIsKnifeEdge && fb.roundedFromExactHalf(out))) {
                        half = out;
                    }
                }
                run.halfway.add(half);
            } catch (EvaluationException e) {
                run.outputs.add(Map.of());
                run.errors.add(e.toString());
                run.halfway.add(null);
                // the next steps still run: a step a case expects refused is followed by ordinary ones
            }
        }
        return run;
    }
}
