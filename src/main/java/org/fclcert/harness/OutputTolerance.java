package org.fclcert.harness;

import org.fclcert.corpus.OutputComparison;

/**
 * How far an output may be from its expected value in one case: the corpus's tolerance class resolved for
 * that case's program (the continuous class depends on each output's RANGE width).
 */
public interface OutputTolerance extends OutputComparison.Allowance {
    /** Short description for reports, e.g. {@code exact} or {@code continuous (±0.2)}. */
    String describe();

    /** The largest absolute error accepted for {@code output} when {@code expected} is the right value. */
    @Override
    double allowedError(String output, double expected);

    /** True when {@code actual} is close enough ({@link OutputComparison}: a NaN or infinite actual never is). */
    default boolean accepts(String output, double expected, double actual) {
        return OutputComparison.passes(expected, actual, allowedError(output, expected));
    }
}
