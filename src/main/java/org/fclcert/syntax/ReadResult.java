package org.fclcert.syntax;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;

/**
 * What a reader made of a text: the program, present exactly when the text has no syntax error,
 * and the diagnostics (syntax errors, and warnings about constructs accepted only because the
 * standard is inconsistent), in source order.
 */
public record ReadResult(Optional<Program> program, List<Diagnostic> diagnostics) {
    public ReadResult {
        diagnostics = List.copyOf(diagnostics);
    }

    public boolean hasErrors() {
        return diagnostics.stream().anyMatch(Diagnostic::isError);
    }
}
