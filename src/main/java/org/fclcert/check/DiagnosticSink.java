package org.fclcert.check;

import org.fclcert.model.Diagnostic;

/** Where a {@link CheckRule} reports what it finds. */
@FunctionalInterface
public interface DiagnosticSink {
    void report(Diagnostic diagnostic);
}
