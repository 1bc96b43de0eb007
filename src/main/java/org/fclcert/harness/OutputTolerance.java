package org.fclcert.harness;

/**
 * How far an output may be from its expected value in one case: the corpus's tolerance class resolved for
 * that case's program (the continuous class depends on each output's RANGE width).
 */
public interface OutputTolerance {
    /** Short description for reports, e.g. {@code exact} or {@code continuous (±0.2)}. */
    String describe();

    /** The largest absolute error accepted for {@code output} when {@code expected} is the right value. */
    double allowedError(String output, double expected);

    /** True when {@code actual} is close enough; a NaN or infinite actual never is. */
    default boolean accepts(String output, double expected, double actual) {
        return Double.isFinite(actual) && Math.abs(actual - expected) <= allowedError(output, expected);
    }
}
