package org.fclcert.corpus;

/**
 * The result of comparing one output ({@link OutputComparison}): the expected and actual values, the measured
 * error (|actual - expected|; +&infin; when the actual value is NaN or infinite; NaN when it is missing), the
 * allowance of the tolerance class, whether it passed, and whether the output was missing altogether
 * (then {@code actual} is NaN). Reports always show the measured error, whatever the class.
 */
public record Comparison(String output, double expected, double actual, double error, double allowed, boolean passed,
        boolean missing) {

    /** An expected output that was not returned at all. */
    public static Comparison missing(String output, double expected, double allowed) {
        return new Comparison(output, expected, Double.NaN, Double.NaN, allowed, false, true);
    }

    /** {@code valve: expected 74.80314960629921, actual 69.343, error 5.46 (allowed 7.48e-08) FAIL}. */
    @Override
    public String toString() {
        return output + ": expected " + expected + ", actual " + (missing ? "none" : String.valueOf(actual))
                + ", error " + error + " (allowed " + allowed + ") " + (passed ? "ok" : "FAIL");
    }
}
