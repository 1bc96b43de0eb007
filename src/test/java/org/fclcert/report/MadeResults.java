package org.fclcert.report;

import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.harness.PlannedCase;

/** Case results for the causes and texts tests, made in one place (the shape of CaseResult may change). */
final class MadeResults {
    private MadeResults() {
    }

    /**
     * A result with the given outcome; {@code expected}/{@code actual} as the harness records them: output maps
     * for a wrong value, sentences for a load or a rejection, null for none.
     */
    @SuppressWarnings("unchecked")
    static CaseResult made(String id, String level, List<String> tests, List<String> flags, CaseStatus status,
            String message, Object expected, Object actual, ExportStatus export, String program) {
        CaseResult.Mismatch mismatch = expected instanceof Map<?, ?> want
                ? new CaseResult.Mismatch.Outputs((Map<String, Double>) want, (Map<String, Double>) actual)
                : expected != null ? new CaseResult.Mismatch.Sentences((String) expected, String.valueOf(actual)) : null;
        return new CaseResult(new PlannedCase(id, "title of " + id, level, tests, flags),
                new CaseResult.Verdict(status, message, List.of(), null),
                new CaseResult.Evidence(mismatch == null ? null : new CaseResult.Step(1, Map.of()), mismatch, null, null),
                new CaseResult.Export(export, null), new CaseResult.Setup(null, "exact", program, 1L));
    }
}
