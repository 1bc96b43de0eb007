package org.fclcert.report;

import java.util.List;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;

/** Case results for the causes and texts tests, made in one place (the shape of CaseResult may change). */
final class MadeResults {
    private MadeResults() {
    }

    /** A result with the given outcome; {@code expected}/{@code actual} as the harness records them. */
    static CaseResult made(String id, String level, List<String> tests, List<String> flags, CaseStatus status,
            String message, Object expected, Object actual, ExportStatus export, String program) {
        return new CaseResult(id, "title of " + id, level, tests, flags, status, message, expected == null ? null : 1,
                null, expected, actual, null, null, "exact", export, null, List.of(), null, program, 1L, null);
    }
}
