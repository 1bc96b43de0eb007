package org.fclcert.model;

import java.util.Objects;

/**
 * One finding about a program: where, how serious, a code of the catalogue and a plain sentence.
 *
 * <p>Codes are stable identifiers that tools key on: {@code FCL-Snnn} for syntax (the reader),
 * {@code FCL-Cnnn} for semantic checks, {@code FCL-Wnnn} for warnings, and so on; each is a
 * {@link DiagnosticCode} owned by exactly one reader, check rule or converter, and
 * {@code docs/diagnostics.md} lists them all. {@link #code()} is the code's stable text, as printed.
 *
 * @param severity       usually the code's own {@link DiagnosticCode#severity()}; a front end may lower an
 *                       error to a warning when the user asked for that (e.g. {@code convert --allow-lossy})
 * @param diagnosticCode the catalogue entry
 */
public record Diagnostic(SourceLocation location, Severity severity, DiagnosticCode diagnosticCode, String message) {
    public Diagnostic {
        Objects.requireNonNull(location, "location");
        Objects.requireNonNull(severity, "severity");
        Objects.requireNonNull(diagnosticCode, "diagnosticCode");
        Objects.requireNonNull(message, "message");
    }

    /** A diagnostic with the code's own severity. */
    public static Diagnostic of(SourceLocation at, DiagnosticCode code, String message) {
        return new Diagnostic(at, code.severity(), code, message);
    }

    public static Diagnostic error(SourceLocation at, DiagnosticCode code, String message) {
        return new Diagnostic(at, Severity.ERROR, code, message);
    }

    public static Diagnostic warning(SourceLocation at, DiagnosticCode code, String message) {
        return new Diagnostic(at, Severity.WARNING, code, message);
    }

    /** The stable code as text, e.g. {@code FCL-C002} (what the text and JSON output show). */
    public String code() {
        return diagnosticCode.code();
    }

    public boolean isError() {
        return severity == Severity.ERROR;
    }

    /** {@code path:line:col: severity CODE: message}. */
    @Override
    public String toString() {
        return location + ": " + severity.word() + " " + code() + ": " + message;
    }
}
