package org.fclcert.harness;

import java.util.List;

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
        return Flags.interpretation(flags).isPresent();
    }
}
