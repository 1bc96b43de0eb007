package org.fclcert.check;

import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.Severity;
import org.fclcert.model.SourceLocation;

/**
 * One semantic check, named after what it asserts, owning exactly one diagnostic code. A rule reads
 * the model only, never throws on any program a reader can produce, and reports every violation it
 * finds to the sink (it does not stop at the first).
 */
public interface CheckRule {
    /** The stable code this rule owns, e.g. {@code FCL-C002}; {@code FCL-W...} codes are warnings. */
    String code();

    /** One line saying what the rule asserts of a valid program. */
    String asserts();

    void check(Program program, DiagnosticSink sink);

    /** Warnings for {@code FCL-W} codes, errors otherwise. */
    default Severity severity() {
        return code().startsWith("FCL-W") ? Severity.WARNING : Severity.ERROR;
    }

    /** A diagnostic with this rule's code and severity. */
    default Diagnostic finding(SourceLocation at, String message) {
        return new Diagnostic(at, severity(), code(), message);
    }
}
