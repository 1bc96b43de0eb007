package org.fclcert.fuzz;

import java.util.List;
import java.util.Map;

/**
 * Decides whether a step is fair: whether a correct implementation can be expected to give the reference's
 * answer within the tolerance class, or whether the step sits on a knife edge (a one-ulp difference in an
 * input, or the other reading of a literal, moves the result by more than the tolerance). Unfair steps are
 * never put to an implementation.
 */
public interface FairnessJudge {
    /**
     * @param program the program, loaded on the reference
     * @param before  the steps run before on the same instance (they set its state)
     * @param step    the inputs of the step to judge
     */
    boolean fair(ReferenceProgram program, List<Map<String, Double>> before, Map<String, Double> step);
}
