package org.fclcert.fuzz;

import java.util.Map;

/**
 * One disagreement: at which step (0-based; -1 for the load), which output, the reference's and the
 * implementation's values (NaN where there is none) and a sentence saying what happened.
 */
public record Deviation(DeviationKind kind, int step, String output, double expected, double actual, String message,
        Map<String, Double> actualOutputs) {
    public Deviation {
        actualOutputs = actualOutputs == null ? Map.of() : Map.copyOf(actualOutputs);
    }

    static Deviation atLoad(DeviationKind kind, String message) {
        return new Deviation(kind, -1, "", Double.NaN, Double.NaN, message, Map.of());
    }
}
