package org.fclcert.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** Collects the pieces of one {@link CaseResult} while a case runs (the record itself stays immutable). */
final class ResultBuilder {
    private final RunCase c;
    private CaseStatus status = CaseStatus.PASSED;
    private String message;
    private Integer step;
    private Map<String, Double> inputs;
    private Object expected;
    private Object actual;
    private String error;
    private Double maxError;
    private ExportStatus exportStatus = ExportStatus.NOT_RUN;
    private String exportMessage;
    private final List<String> notes = new ArrayList<>();
    private RejectionPlace rejection;

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
        step = oneBasedStep;
        inputs = in;
        return this;
    }

    ResultBuilder outcome(Object expectedValue, Object actualValue) {
        expected = expectedValue;
        actual = actualValue;
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

    ResultBuilder note(String note) {
        notes.add(note);
        return this;
    }

    CaseResult build(long durationMs) {
        boolean keepProgram = status != CaseStatus.PASSED || exportStatus == ExportStatus.FAILED;
        return new CaseResult(c.id(), c.title(), c.level().word(), c.tests(), c.flags(), status, message, step,
                inputs, expected, actual, error, maxError, c.tolerance().describe(), exportStatus, exportMessage,
                notes, c.block().orElse(null), keepProgram ? c.program() : null, durationMs, rejection);
    }
}
