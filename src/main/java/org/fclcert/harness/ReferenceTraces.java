package org.fclcert.harness;

import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.Trace;

/** The reference evaluator run on a case up to the step that went wrong, traced at that step. */
final class ReferenceTraces {
    private ReferenceTraces() {
    }

    /**
     * The trace at {@code step} (1-based) of a positive case, the steps before it evaluated first on the same
     * instance; null for a negative case, a step the case does not have, or a program fclcert cannot evaluate (the
     * corpus lint keeps the last from happening; a report without the trace is still a report).
     */
    static ReferenceTrace at(RunCase c, int step) {
        if (c.expectReject() || step < 1 || step > c.vectors().size()) {
            return null;
        }
        try {
            Analysis analysis = Analysis.analyze(c.reader(), c.id(), c.program());
            if (analysis.program().isEmpty()) {
                return null;
            }
            LoadedProgram loaded = Evaluator.load(analysis.program().get());
            FunctionBlockInstance fb = c.block().isPresent() ? loaded.newInstance(c.block().get()) : loaded.newInstance();
            Trace trace = new Trace();
            for (int i = 0; i < step; i++) {
                for (Map.Entry<String, Double> in : c.vectors().get(i).in().entrySet()) {
                    fb.set(in.getKey(), in.getValue());
                }
                if (i == step - 1) {
                    fb.evaluate(trace);
                } else {
                    try {
                        fb.evaluate(null);
                    } catch (EvaluationException e) {
                        // a step before, refused as the case expects; the steps after it still run
                    }
                }
            }
            return ReferenceTrace.of(step, trace);
        } catch (EvaluationException | RuntimeException | StackOverflowError e) {
            return null;
        }
    }
}
