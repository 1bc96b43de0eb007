package org.fclcert.corpus;

/**
 * The result of comparing one output: the expected and actual values, the measured error |actual - expected|
 * (NaN when the actual value is NaN, infinite or missing), the allowance of the tolerance class, and whether it
 * passed. Reports always show the measured error, whatever the class.
 */
public record Comparison(String output, double expected, double actual, double error, double allowed, boolean passed) {

    /** An expected output the implementation did not return at all. */
    public static Comparison missing(String output, double expected, double allowed) {
        return new Comparison(output, expected, Double.NaN, Double.NaN, allowed, false);
    }

    /** {@code valve: expected 74.80314960629921, actual 69.343, error 5.46 (allowed 7.48e-08) FAIL}. */
    @Override
    public String toString() {
        return output + ": expected " + expected + ", actual " + actual + ", error " + error
                + " (allowed " + allowed + ") " + (passed ? "ok" : "FAIL");
    }
}
