package org.fclcert.corpus;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.Program;

/**
 * Runs a positive case's vectors on the reference evaluator's exact judging path: in order on one instance (every expected output
 * must be reproduced within the case's tolerance), then, for a case not flagged {@code stateful}, in reverse
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

    private ExactInstance instance() throws EvaluationException {
        return loaded.newExactInstance(c.block().orElse(null), NumberReading.DECIMAL);
    }

    private boolean forward() throws EvaluationException {
        ExactInstance fb = instance();
        boolean ok = true;
        for (int i = 0; i < c.vectors().size(); i++) {
            for (Comparison cmp : step(fb, i)) {
                if (!cmp.passed()) {
                    ok = false;
                    messages.add("vector " + (i + 1) + ": " + describe(cmp));
                }
            }
        }
        return ok;
    }

    private void reversed() throws EvaluationException {
        ExactInstance fb = instance();
        for (int i = c.vectors().size() - 1; i >= 0; i--) {
            for (Comparison cmp : step(fb, i)) {
                if (!cmp.passed()) {
                    messages.add("vector " + (i + 1) + " depends on the steps before it: run in reverse order on a fresh "
                            + "instance, " + describe(cmp) + "; flag the case 'stateful' or set every input in every step");
                    return;
                }
            }
        }
    }

    private List<Comparison> step(ExactInstance fb, int index) throws EvaluationException {
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
            throw new EvaluationException(e.diagnosticCode(), "vector " + (index + 1) + ": " + e.getMessage());
        }
        return c.tolerance().compareAll(v.out(), fb.outputs(), scales);
    }

    private static String describe(Comparison cmp) {
        if (cmp.missing()) {
            return "'" + cmp.output() + "' expected " + cmp.expected() + ", but the block has no such output";
        }
        return "'" + cmp.output() + "' expected " + cmp.expected() + ", the reference evaluator gives " + cmp.actual()
                + " (error " + cmp.error() + ", allowed " + cmp.allowed() + ")";
    }
}
