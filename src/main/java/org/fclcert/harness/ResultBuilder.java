package org.fclcert.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** Collects the pieces of one {@link CaseResult} while a case runs (the record itself stays immutable). */
final class ResultBuilder {
    private final RunCase c;
    private CaseStatus status = CaseStatus.PASSED;
    private String message;
    private CaseResult.Step step;
    private CaseResult.Mismatch mismatch;
    private String error;
    private Double maxError;
    private ExportStatus exportStatus = ExportStatus.NOT_RUN;
    private String exportMessage;
    private final List<String> notes = new ArrayList<>();
    private RejectionPlace rejection;
    private ReferenceTrace reference;

    ResultBuilder(RunCase c) {
        this.c = c;
    }

    CaseStatus status() {
        return status;
    }

    ResultBuilder passed(String why) {
        status = CaseStatus.PASSED;
        message = why;
        return this;
    }

    ResultBuilder failed(String why) {
        status = CaseStatus.FAILED;
        message = why;
        return this;
    }

    ResultBuilder errored(String why, String errorText) {
        status = CaseStatus.ERRORED;
        message = why;
        error = errorText;
        return this;
    }

    ResultBuilder error(String errorText) {
        error = errorText;
        return this;
    }

    ResultBuilder at(int oneBasedStep, Map<String, Double> in) {
        step = new CaseResult.Step(oneBasedStep, in);
        return this;
    }

    /** The output values expected at a step and those the implementation gave. */
    ResultBuilder outputs(Map<String, Double> expected, Map<String, Double> actual) {
        mismatch = new CaseResult.Mismatch.Outputs(expected, actual);
        return this;
    }

    /** What was expected of a load or a rejection, and what happened, in words. */
    ResultBuilder sentences(String expected, String actual) {
        mismatch = new CaseResult.Mismatch.Sentences(expected, actual);
        return this;
    }

    /** Keeps the largest absolute error measured so far. */
    ResultBuilder measured(double absoluteError) {
        if (!Double.isNaN(absoluteError) && (maxError == null || absoluteError > maxError)) {
            maxError = absoluteError;
        }
        return this;
    }

    ResultBuilder export(ExportStatus s, String why) {
        exportStatus = s;
        exportMessage = why;
        return this;
    }

    ResultBuilder rejection(RejectionPlace place) {
        rejection = place;
        return this;
    }

    /**
     * The reference evaluator's trace at the step that went wrong (positive cases that did not pass), on
     * {@code original}: the case as the corpus writes it, also when a library's layout of it was sent.
     */
    ResultBuilder traceReference(RunCase original) {
        if (status != CaseStatus.PASSED && step != null) {
            reference = ReferenceTraces.at(original, step.number());
        }
        return this;
    }

    ResultBuilder note(String note) {
        notes.add(note);
        return this;
    }

    CaseResult build(long durationMs) {
        boolean keepProgram = status != CaseStatus.PASSED || exportStatus == ExportStatus.FAILED;
        return new CaseResult(c.plan(), new CaseResult.Verdict(status, message, notes, rejection),
                new CaseResult.Evidence(step, mismatch, error, maxError, reference), new CaseResult.Export(exportStatus,
                        exportMessage), new CaseResult.Setup(c.block().orElse(null), c.tolerance().describe(),
                        keepProgram ? c.program() : null, durationMs));
    }
}
