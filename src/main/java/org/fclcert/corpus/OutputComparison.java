package org.fclcert.corpus;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.Names;

/**
 * The one comparison of computed outputs with a case's expected ones. {@code fclcert corpus lint} judges the
 * reference evaluator with it, {@code fclcert certify} an implementation under test, so a case file means the
 * same to both. The rule ({@code docs/corpus-format.md}, "Tolerance"):
 *
 * <ul>
 *   <li>Expected values are finite: the case-file reader refuses anything else.</li>
 *   <li>An output passes when its value is finite and |actual &minus; expected| &le; the allowed error of
 *       the case's tolerance class ({@link Tolerance#allowed}).</li>
 *   <li>A non-finite value (NaN, +&infin; or &minus;&infin;) never passes, whatever the allowance; its
 *       measured error is +&infin; (it is infinitely far from any finite value, and a case's largest error
 *       then says so).</li>
 *   <li>An expected output that is absent (or null) never passes; nothing is measured (error NaN).</li>
 *   <li>Output names match exactly, else ignoring case (FCL identifiers are case-insensitive); outputs
 *       nobody expects are ignored.</li>
 * </ul>
 */
public final class OutputComparison {
    private OutputComparison() {
    }

    /** The largest absolute error accepted for {@code output} when {@code expected} is the right value. */
    @FunctionalInterface
    public interface Allowance {
        double allowedError(String output, double expected);
    }

    /** The measured error of one value: |actual &minus; expected|, or +&infin; for a non-finite actual. */
    public static double error(double expected, double actual) {
        return Double.isFinite(actual) ? Math.abs(actual - expected) : Double.POSITIVE_INFINITY;
    }

    /** True when {@code actual} is finite and within {@code allowed} of {@code expected}. */
    public static boolean passes(double expected, double actual, double allowed) {
        return Double.isFinite(actual) && Math.abs(actual - expected) <= allowed;
    }

    /** Compares one output value. */
    public static Comparison compare(String output, double expected, double actual, double allowed) {
        return new Comparison(output, expected, actual, error(expected, actual), allowed,
                passes(expected, actual, allowed), false);
    }

    /**
     * Compares every expected output of one step with what was computed, in the expected outputs' order;
     * an expected output that is missing fails.
     */
    public static List<Comparison> compareAll(Map<String, Double> expected, Map<String, Double> actual,
            Allowance allowance) {
        List<Comparison> result = new ArrayList<>();
        for (Map.Entry<String, Double> e : expected.entrySet()) {
            String name = e.getKey();
            double want = e.getValue();
            double allowed = allowance.allowedError(name, want);
            Optional<Double> got = lookup(actual, name);
            result.add(got.isEmpty() ? Comparison.missing(name, want, allowed)
                    : compare(name, want, got.get(), allowed));
        }
        return List.copyOf(result);
    }

    /** The value of output {@code name}: by its exact name, else ignoring case; empty when absent or null. */
    public static Optional<Double> lookup(Map<String, Double> outputs, String name) {
        Double exact = outputs.get(name);
        if (exact != null) {
            return Optional.of(exact);
        }
        return outputs.entrySet().stream().filter(e -> e.getValue() != null && Names.same(e.getKey(), name))
                .map(Map.Entry::getValue).findFirst();
    }
}
