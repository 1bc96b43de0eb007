package org.fclcert.report;

import java.util.Locale;

/**
 * {@code --fail-on}: which outcome makes {@code fclcert certify} exit with 1.
 * {@code none}: never; {@code basic}: the Basic Level is not conformant; {@code claimed}: the Basic Level is
 * not conformant or a feature the implementation claims is not realised (claiming an extension implies the
 * Basic Level, clause 6.1 c); {@code any}: any case failed or errored.
 */
public enum FailOn {
    NONE,
    BASIC,
    CLAIMED,
    ANY;

    /** The word the command line takes: {@code none}, {@code basic}, {@code claimed}, {@code any}. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static FailOn byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT));
    }

    /** True when the report satisfies this condition (exit 0). */
    public boolean holds(Report report) {
        return switch (this) {
            case NONE -> true;
            case BASIC -> report.basicLevel().conformant();
            case CLAIMED -> report.basicLevel().conformant() && report.claims().notRealised().isEmpty()
                    && report.claims().unknown().isEmpty();
            case ANY -> report.summary().failed() == 0 && report.summary().errored() == 0;
        };
    }

    /** Why it does not hold, for the terminal. */
    public String explain(Report report) {
        return switch (this) {
            case NONE -> "";
            case BASIC -> "Basic Level " + report.basicLevel().sentence();
            case CLAIMED -> report.basicLevel().conformant()
                    ? "claimed but not realised: " + String.join(", ", report.claims().notRealised())
                            + (report.claims().unknown().isEmpty() ? ""
                                    : "; unknown claims: " + String.join(", ", report.claims().unknown()))
                    : "Basic Level " + report.basicLevel().sentence();
            case ANY -> report.summary().failed() + " case(s) failed, " + report.summary().errored()
                    + " errored";
        };
    }
}
