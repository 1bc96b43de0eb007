package org.fclcert.harness;

import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.Names;

/** Compares the outputs of one evaluation with the expected ones (names are case-insensitive). */
final class StepComparison {
    private StepComparison() {
    }

    /**
     * Records the measured error of every expected output and returns the first problem: a missing output,
     * or one outside the case's tolerance.
     */
    static Optional<String> compare(RunCase c, Map<String, Double> expected, Map<String, Double> actual,
            ResultBuilder r) {
        String first = null;
        for (Map.Entry<String, Double> e : expected.entrySet()) {
            Optional<Double> got = lookup(actual, e.getKey());
            if (got.isEmpty()) {
                first = first != null ? first : "no value for output " + e.getKey();
                continue;
            }
            double want = e.getValue();
            double error = Double.isFinite(got.get()) ? Math.abs(got.get() - want) : Double.POSITIVE_INFINITY;
            r.measured(error);
            if (first == null && !c.tolerance().accepts(e.getKey(), want, got.get())) {
                first = e.getKey() + " = " + got.get() + " where " + want + " is expected (error " + error
                        + ", allowed " + c.tolerance().allowedError(e.getKey(), want) + ")";
            }
        }
        return Optional.ofNullable(first);
    }

    /** The first output whose value differs at all between two evaluations of the same step. */
    static Optional<String> difference(Collection<String> outputs, Map<String, Double> before,
            Map<String, Double> after) {
        for (String name : outputs) {
            Optional<Double> a = lookup(before, name);
            Optional<Double> b = lookup(after, name);
            if (!a.equals(b)) {
                return Optional.of(name + " = " + b.map(String::valueOf).orElse("nothing") + " instead of "
                        + a.map(String::valueOf).orElse("nothing"));
            }
        }
        return Optional.empty();
    }

    static Optional<Double> lookup(Map<String, Double> outputs, String name) {
        Double exact = outputs.get(name);
        if (exact != null) {
            return Optional.of(exact);
        }
        return outputs.entrySet().stream().filter(e -> Names.same(e.getKey(), name) && e.getValue() != null)
                .map(Map.Entry::getValue).findFirst();
    }
}
