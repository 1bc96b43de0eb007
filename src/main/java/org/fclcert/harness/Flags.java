package org.fclcert.harness;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The case flags the runner and the reports act on ({@code stateful}, {@code interpretation:<point>},
 * {@code knife-edge:<vector>}).
 */
public final class Flags {
    private Flags() {
    }

    public static boolean stateful(List<String> flags) {
        return flags.stream().anyMatch(f -> f.equalsIgnoreCase("stateful"));
    }

    /**
     * The 1-based vectors flagged {@code knife-edge:<n>}: not fair to judge (FairVectors), so the runner reports
     * them as not judged instead of comparing them.
     */
    public static java.util.SortedSet<Integer> knifeEdges(List<String> flags) {
        java.util.SortedSet<Integer> steps = new java.util.TreeSet<>();
        for (String f : flags) {
            String lower = f.toLowerCase(Locale.ROOT);
            if (lower.startsWith("knife-edge:")) {
                try {
                    steps.add(Integer.parseInt(lower.substring("knife-edge:".length()).strip()));
                } catch (NumberFormatException e) {
                    // not a vector number: corpus lint reports such a flag; the runner judges the vector
                }
            }
        }
        return steps;
    }

    /** The {@code interpretation:*} flag, when the case depends on a reading of the standard. */
    public static Optional<String> interpretation(List<String> flags) {
        return flags.stream().filter(f -> f.toLowerCase(Locale.ROOT).startsWith("interpretation")).findFirst();
    }
}
