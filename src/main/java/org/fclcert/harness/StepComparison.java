package org.fclcert.harness;

import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import org.fclcert.corpus.Comparison;
import org.fclcert.corpus.OutputComparison;

/** Judges the outputs of one evaluation by the corpus's one {@link OutputComparison} and words the problem. */
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
        for (Comparison cmp : OutputComparison.compareAll(expected, actual, c.tolerance())) {
            if (cmp.missing()) {
                first = first != null ? first : "no value for output " + cmp.output();
                continue;
            }
            r.measured(cmp.error());
            if (first == null && !cmp.passed()) {
                first = cmp.output() + " = " + cmp.actual() + " where " + cmp.expected() + " is expected (error "
                        + cmp.error() + ", allowed " + cmp.allowed() + ")";
            }
        }
        return Optional.ofNullable(first);
    }

    /** The first output whose value differs at all between two evaluations of the same step. */
    static Optional<String> difference(Collection<String> outputs, Map<String, Double> before,
            Map<String, Double> after) {
        for (String name : outputs) {
            Optional<Double> a = OutputComparison.lookup(before, name);
            Optional<Double> b = OutputComparison.lookup(after, name);
            if (!a.equals(b)) {
                return Optional.of(name + " = " + b.map(String::valueOf).orElse("nothing") + " instead of "
                        + a.map(String::valueOf).orElse("nothing"));
            }
        }
        return Optional.empty();
    }
}
