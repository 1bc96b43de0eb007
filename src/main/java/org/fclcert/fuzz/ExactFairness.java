package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.corpus.Tolerance;
import org.fclcert.eval.FairVectors;

/**
 * The fairness judge of the exact judging path ({@link FairVectors}, docs/semantics.md point 10): the step,
 * after the steps before it on the same instance, is run exactly under fclcert's reading of numbers and
 * under the other reading, in double arithmetic, and with its inputs nudged by an ulp; it is fair when every
 * output stays within a quarter of its tolerance class under all of them. A step of a program without state
 * is judged alone: the steps before it cannot change its outputs.
 */
public final class ExactFairness implements FairnessJudge {
    private static final double SAFETY = 0.25;

    @Override
    public boolean fair(ReferenceProgram program, List<Map<String, Double>> before, Map<String, Double> step) {
        List<Map<String, Double>> steps = new ArrayList<>(program.stateful() ? before : List.of());
        steps.add(step);
        FairVectors.Agreement agreement = (output, a, b) -> Double.isNaN(a) ? Double.isNaN(b)
                : Math.abs(a - b) <= SAFETY * Tolerance.CONTINUOUS.allowed(a, program.scales().width(output));
        try {
            return FairVectors.judge(program.loaded(), null, steps, agreement).fair(steps.size());
        } catch (RuntimeException e) {
            return false;
        }
    }
}
