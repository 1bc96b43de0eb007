package org.fclcert.model;

import java.util.Objects;

/**
 * One finding about a program: where, how serious, a stable code and a plain sentence.
 *
 * <p>Codes are stable identifiers that tools key on: {@code FCL-Snnn} for syntax (the reader),
 * {@code FCL-Cnnn} for semantic checks, {@code FCL-Wnnn} for warnings. Each code is owned by exactly
 * one reader rule or check rule; {@code docs/diagnostics.md} lists them all.
 */
public record Diagnostic(SourceLocation location, Severity severity, String code, String message) {
    public Diagnostic {
        Objects.requireNonNull(location, "location");
        Objects.requireNonNull(severity, "severity");
        Objects.requireNonNull(code, "code");
        Objects.requireNonNull(message, "message");
    }

    public static Diagnostic error(SourceLocation at, String code, String message) {
        return new Diagnostic(at, Severity.ERROR, code, message);
    }

    public static Diagnostic warning(SourceLocation at, String code, String message) {
        return new Diagnostic(at, Severity.WARNING, code, message);
    }

    public boolean isError() {
        return severity == Severity.ERROR;
    }

    /** {@code path:line:col: severity CODE: message}. */
    @Override
    public String toString() {
        return location + ": " + severity.word() + " " + code + ": " + message;
    }
}
