package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.SourceLocation;

/** What a writer found while writing: losses (errors) and the library's deviations (warnings), in order. */
final class Findings {
    private final String library;
    private final List<Diagnostic> losses = new ArrayList<>();
    private final List<Diagnostic> differences = new ArrayList<>();

    Findings(String library) {
        this.library = library;
    }

    String library() {
        return library;
    }

    void lost(SourceLocation at, WriterCode code, String message) {
        losses.add(Diagnostic.of(at == null ? SourceLocation.UNKNOWN : at, code, message));
    }

    void differs(SourceLocation at, WriterCode code, String message) {
        Diagnostic d = Diagnostic.of(at == null ? SourceLocation.UNKNOWN : at, code, message);
        if (differences.stream().noneMatch(x -> x.message().equals(d.message()) && x.location().sameAs(d.location()))) {
            differences.add(d);
        }
    }

    List<Diagnostic> losses() {
        return losses;
    }

    List<Diagnostic> differences() {
        return differences;
    }
}
