package org.fclcert.harness;

/**
 * Judges the FCL text an implementation exported for a case (clause 6 e): it must read back under the
 * strict reader with no error and evaluate like the original on the case's vectors.
 */
public interface ExportCheck {
    /** The verdict on one exported text; {@code status} is PASSED or FAILED. */
    record Verdict(ExportStatus status, String message) {
    }

    Verdict check(String exportedFcl, RunCase c);
}
