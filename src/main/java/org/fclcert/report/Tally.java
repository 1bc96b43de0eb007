package org.fclcert.report;

import org.fclcert.harness.CaseResult;

/**
 * The one count of a run's cases that every front end prints — the Maven log, {@code junit.xml} (and Surefire's
 * {@code TEST-fclcert.xml}), {@code report.html}, {@code report.md} and the terminal: passed; failures and errors that
 * count (a Basic Level case, a negative case, or a case of a feature the implementation claims); failures and errors
 * of Extension or Open Level features it does not claim (skipped in the JUnit file, {@link JunitReport#unclaimed});
 * and cases not run.
 */
public record Tally(int cases, int passed, int failures, int errors, int unclaimed, int notRun) {

    public static Tally of(Report r) {
        int passed = 0;
        int failures = 0;
        int errors = 0;
        int unclaimed = 0;
        int notRun = 0;
        for (CaseResult c : r.cases()) {
            if (JunitReport.unclaimed(r, c) != null) {
                unclaimed++;
                continue;
            }
            switch (c.status()) {
                case PASSED -> passed++;
                case FAILED -> failures++;
                case ERRORED -> errors++;
                case SKIPPED -> notRun++;
            }
        }
        return new Tally(r.cases().size(), passed, failures, errors, unclaimed, notRun);
    }

    /** True for a case counted in {@link #unclaimed}: it did not pass, in a feature the implementation does not claim. */
    public static boolean unclaimed(Report r, CaseResult c) {
        return JunitReport.unclaimed(r, c) != null;
    }

    /**
     * {@code 197 cases: 113 passed; 0 failed, 0 errored (counted); 84 failed or errored in features not claimed
     * (skipped in junit.xml); 0 not run}.
     */
    public String sentence() {
        return cases + " cases: " + passed + " passed; " + failures + " failed, " + errors + " errored (counted); "
                + unclaimed + " failed or errored in features not claimed (skipped in junit.xml); " + notRun
                + " not run";
    }

    /** How the JUnit file's {@code skipped} is made up, for a line beside Surefire's. */
    public String skippedSentence() {
        return "Skipped: " + (unclaimed + notRun) + " = " + unclaimed + " failed or errored in features not claimed + "
                + notRun + " not run";
    }
}
