package org.fclcert.harness;

import java.util.List;
import java.util.Locale;

/**
 * A selected case as listed in the run header, so that a report rebuilt from an interrupted results file
 * still knows which cases were meant to run (and reports them as skipped).
 */
public record PlannedCase(String id, String title, String level, List<String> tests, List<String> flags) {
    public PlannedCase {
        tests = List.copyOf(tests);
        flags = List.copyOf(flags);
    }

    public boolean interpretation() {
        return flags.stream().anyMatch(f -> f.toLowerCase(Locale.ROOT).startsWith("interpretation"));
    }
}
