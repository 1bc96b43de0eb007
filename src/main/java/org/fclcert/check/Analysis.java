package org.fclcert.check;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.ReadResult;

/**
 * Reading plus checking, the whole front end in one call.
 *
 * @param program     present exactly when there is no error at all (warnings allowed)
 * @param diagnostics reader diagnostics, then check diagnostics, merged by position (a reader
 *                    diagnostic comes first when both are at the same position)
 */
public record Analysis(Optional<Program> program, List<Diagnostic> diagnostics) {
    public Analysis {
        diagnostics = List.copyOf(diagnostics);
    }

    /** Reads the text; when it has no syntax error (or only ones a one-token repair mends), checks the program. */
    public static Analysis analyze(FclReader reader, String sourceName, String text) {
        return of(reader.read(sourceName, text));
    }

    /**
     * Checks what a reader made of a text, as {@link #analyze} does (for a caller that keeps the reading too,
     * such as the language server, which navigates the repaired program of a text with errors).
     */
    public static Analysis of(ReadResult read) {
        List<Diagnostic> all = new ArrayList<>(read.diagnostics());
        if (!read.hasErrors() && read.program().isPresent()) {
            all.addAll(new Checker().check(read.program().get()));
        } else if (read.repaired().isPresent()) {
            // the syntax errors were one-token slips: the rest of the program is still worth checking
            all.addAll(new Checker().check(read.repaired().get()));
        }
        // a stable sort on position alone keeps reader diagnostics ahead of checks at the same position
        all.sort(Comparator.comparing(Diagnostic::location));
        boolean ok = read.program().isPresent() && all.stream().noneMatch(Diagnostic::isError);
        return new Analysis(ok ? read.program() : Optional.empty(), all);
    }

    public boolean hasErrors() {
        return diagnostics.stream().anyMatch(Diagnostic::isError);
    }
}
