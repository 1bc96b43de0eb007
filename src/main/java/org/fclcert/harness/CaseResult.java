package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.List;
import java.util.Map;

/**
 * The outcome of one case: one line of {@code results.jsonl}, carrying everything the reports need.
 *
 * <p>For a positive case {@code expected}/{@code actual} are output maps of the first wrong step (or of
 * the last step when all passed are not kept: both are then null); for a negative case they are sentences
 * ({@code reject FCL-C002 at line 14} / {@code accepted}). {@code maxError} is the largest absolute error
 * measured over every compared output of the case, whatever its status. The program text is kept only for
 * cases that did not pass, so a report can show it. {@code rejection} says, for a negative case the
 * implementation rejected, whether it named the error's line (null otherwise).
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record CaseResult(
        String id,
        String title,
        String level,
        List<String> tests,
        List<String> flags,
        CaseStatus status,
        String message,
        Integer step,
        Map<String, Double> inputs,
        Object expected,
        Object actual,
        String error,
        Double maxError,
        String tolerance,
        ExportStatus exportStatus,
        String exportMessage,
        List<String> notes,
        String block,
        String program,
        Long durationMs,
        RejectionPlace rejection) {

    public CaseResult {
        tests = tests == null ? List.of() : List.copyOf(tests);
        flags = flags == null ? List.of() : List.copyOf(flags);
        notes = notes == null ? List.of() : List.copyOf(notes);
        exportStatus = exportStatus == null ? ExportStatus.NOT_RUN : exportStatus;
    }

    /** The 1-based steps reported as not judged: the vectors the case flags {@code knife-edge:<n>}. */
    public java.util.SortedSet<Integer> notJudgedSteps() {
        return Flags.knifeEdges(flags);
    }

    public boolean interpretation() {
        return Flags.interpretation(flags).isPresent();
    }

    /** A skipped result for a planned case that never ran. */
    public static CaseResult skipped(PlannedCase c, String reason) {
        return new CaseResult(c.id(), c.title(), c.level(), c.tests(), c.flags(), CaseStatus.SKIPPED, reason,
                null, null, null, null, null, null, null, ExportStatus.NOT_RUN, null, List.of(), null, null, null, null);
    }
}
