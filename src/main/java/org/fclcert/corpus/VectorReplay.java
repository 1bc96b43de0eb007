package org.fclcert.corpus;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.Program;

/**
 * Runs a positive case's vectors on the reference evaluator's exact judging path (for a dialect construct it has no
 * exact form of, the reference itself: {@link #instance()}): in order on one instance (every expected output
 * must be reproduced within the case's tolerance, and a step that must be refused must end in its evaluation error,
 * the same code), then, for a case not flagged {@code stateful}, in reverse
 * order on a fresh instance, as the harness does, so that a case whose steps depend on each other is caught
 * here rather than blamed on an implementation.
 */
final class VectorReplay {
    private final CorpusCase c;
    private final LoadedProgram loaded;
    private final OutputScales scales;
    private final List<String> messages = new ArrayList<>();

    private VectorReplay(CorpusCase c, Program program) {
        this.c = c;
        this.loaded = Evaluator.load(program);
        this.scales = OutputScales.of(CorpusLint.blockOf(c, program));
    }

    /** Every disagreement, as plain sentences with the exact numbers; empty when the case is reproduced. */
    static List<String> check(CorpusCase c, Program program) {
        VectorReplay replay = new VectorReplay(c, program);
        try {
            if (replay.forward() && !c.stateful()) {
                replay.reversed();
            }
        } catch (EvaluationException e) {
            replay.messages.add("the reference evaluator failed: " + e.getMessage());
        }
        return List.copyOf(replay.messages);
    }

    /** One instance of the judging path, as far as a replay needs it. */
    private record Instance(Setter setter, Step step, java.util.function.Supplier<Map<String, Double>> outputs) {
        void set(String name, double value) throws EvaluationException {
            setter.set(name, value);
        }

        void evaluate() throws EvaluationException {
            step.run();
        }
    }

    private interface Setter {
        void set(String name, double value) throws EvaluationException;
    }

    private interface Step {
        void run() throws EvaluationException;
    }

    /**
     * The exact path; for a dialect case whose program it refuses (Takagi-Sugeno terms, Tsukamoto's method, hedges
     * in conclusions: {@link #exactPathEvaluates}), the reference evaluator itself, whose double path with its error
     * bounds is the only arithmetic fclcert has for them. A standard case is always judged exactly.
     */
    private Instance instance() throws EvaluationException {
        String block = c.block().orElse(null);
        if (c.inDialect() && !exactPathEvaluates(loaded, c)) {
            FunctionBlockInstance fb = block == null ? loaded.newInstance() : loaded.newInstance(block);
            return new Instance(fb::set, fb::evaluate, fb::outputs);
        }
        ExactInstance fb = loaded.newExactInstance(block, NumberReading.DECIMAL);
        return new Instance(fb::set, fb::evaluate, fb::outputs);
    }

    /** Whether the exact path evaluates the case's block (it refuses the dialect constructs it has no exact form of). */
    static boolean exactPathEvaluates(LoadedProgram loaded, CorpusCase c) {
        try {
            loaded.newExactInstance(c.block().orElse(null), NumberReading.DECIMAL);
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        } catch (EvaluationException e) {
            return true;   // no such block: the replay reports it
        }
    }

    private boolean forward() throws EvaluationException {
        Instance fb = instance();
        boolean ok = true;
        for (int i = 0; i < c.vectors().size(); i++) {
            for (String problem : step(fb, i)) {
                ok = false;
                messages.add("vector " + (i + 1) + ": " + problem);
            }
        }
        return ok;
    }

    private void reversed() throws EvaluationException {
        Instance fb = instance();
        for (int i = c.vectors().size() - 1; i >= 0; i--) {
            List<String> problems = step(fb, i);
            if (!problems.isEmpty()) {
                messages.add("vector " + (i + 1) + " depends on the steps before it: run in reverse order on a fresh "
                        + "instance, " + problems.get(0) + "; flag the case 'stateful' or set every input in every step");
                return;
            }
        }
    }

    /** How step {@code index} disagrees with the case (empty: reproduced; a step that must be refused, refused so). */
    private List<String> step(Instance fb, int index) throws EvaluationException {
        Vector v = c.vectors().get(index);
        for (Map.Entry<String, Double> in : v.in().entrySet()) {
            try {
                fb.set(in.getKey(), in.getValue());
            } catch (EvaluationException e) {
                throw new EvaluationException(e.diagnosticCode(), "vector " + (index + 1) + ": " + e.getMessage());
            }
        }
        try {
            fb.evaluate();
        } catch (EvaluationException e) {
            if (v.refused()) {
                return v.error().get().equals(e.code()) ? List.of()
                        : List.of("expected the evaluation to be refused with " + v.error().get()
                                + ", the reference evaluator refuses it with " + e);
            }
            throw new EvaluationException(e.diagnosticCode(), "vector " + (index + 1) + ": " + e.getMessage());
        }
        if (v.refused()) {
            return List.of("expected the evaluation to be refused with " + v.error().get() + ", the reference evaluator"
                    + " gives " + fb.outputs().get());
        }
        List<String> problems = new ArrayList<>();
        for (Comparison cmp : c.tolerance().compareAll(v.out(), fb.outputs().get(), scales)) {
            if (!cmp.passed()) {
                problems.add(describe(cmp));
            }
        }
        return problems;
    }

    private static String describe(Comparison cmp) {
        if (cmp.missing()) {
            return "'" + cmp.output() + "' expected " + cmp.expected() + ", but the block has no such output";
        }
        return "'" + cmp.output() + "' expected " + cmp.expected() + ", the reference evaluator gives " + cmp.actual()
                + " (error " + cmp.error() + ", allowed " + cmp.allowed() + ")";
    }
}
