package org.fclcert.report;

import org.fclcert.harness.CaseResult;
import org.fclcert.harness.ExportStatus;

/**
 * The few facts of a case result that causes and the comparison page read, in one place, so that they do not
 * depend on how {@link CaseResult} arranges its fields.
 */
final class CaseFacts {
    private CaseFacts() {
    }

    /** The expected side of the first mismatch: an output map, a sentence, or null. */
    static Object expected(CaseResult c) {
        return c.mismatch().map(CaseResult.Mismatch::expected).orElse(null);
    }

    /** The actual side of the first mismatch: an output map, a sentence, or null. */
    static Object actual(CaseResult c) {
        return c.mismatch().map(CaseResult.Mismatch::actual).orElse(null);
    }

    /** The program text as sent, when the result kept it (cases that did not pass). */
    static String program(CaseResult c) {
        return c.setup().program();
    }

    /** The 1-based step of the first failure, or null. */
    static Integer step(CaseResult c) {
        return c.evidence().step() == null ? null : c.evidence().step().number();
    }

    static ExportStatus exportStatus(CaseResult c) {
        return c.export().status();
    }
}
