package org.fclcert.check;

import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.Severity;
import org.fclcert.model.SourceLocation;

/**
 * One semantic check, named after what it asserts, owning exactly one diagnostic code, which it declares
 * itself ({@link CheckCode}). A rule reads the model only, never throws on any program a reader can produce,
 * and reports every violation it finds to the sink (it does not stop at the first).
 */
public interface CheckRule {
    /** The code this rule owns, with its severity, clause and meaning. */
    CheckCode diagnosticCode();

    void check(Program program, DiagnosticSink sink);

    /** The stable code as text, e.g. {@code FCL-C002}. */
    default String code() {
        return diagnosticCode().code();
    }

    /** One line saying what the rule asserts of a valid program (its code's meaning). */
    default String asserts() {
        return diagnosticCode().meaning();
    }

    default Severity severity() {
        return diagnosticCode().severity();
    }

    /** A diagnostic with this rule's code and severity. */
    default Diagnostic finding(SourceLocation at, String message) {
        return Diagnostic.of(at, diagnosticCode(), message);
    }
}
