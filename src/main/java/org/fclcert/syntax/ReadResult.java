package org.fclcert.syntax;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;

/**
 * What a reader made of a text: the program, present exactly when the text has no syntax error,
 * and the diagnostics (syntax errors, and warnings about constructs accepted only because the
 * standard is inconsistent), in source order; after syntax errors that a one-token repair mends (a
 * missing ';'), {@code repaired} is the program of the repaired text, for the semantic checks only, so
 * that one slip does not hide the mistakes after it.
 */
public record ReadResult(Optional<Program> program, List<Diagnostic> diagnostics, Optional<Program> repaired) {
    public ReadResult {
        diagnostics = List.copyOf(diagnostics);
        repaired = program.isPresent() ? Optional.empty() : repaired;
    }

    /** A result with no repaired program. */
    public ReadResult(Optional<Program> program, List<Diagnostic> diagnostics) {
        this(program, diagnostics, Optional.empty());
    }

    public boolean hasErrors() {
        return diagnostics.stream().anyMatch(Diagnostic::isError);
    }
}
