package org.fclcert.lsp;

import java.util.List;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.CanonicalWriter;

/**
 * Formatting with {@code fclcert fmt}'s layout: the canonical writer's text of the program, as one edit. Like
 * {@code fmt --write} it leaves a text alone rather than lose something: a text with errors, a text read in a
 * library's dialect (fmt would convert it to standard FCL) and a text whose comments the writer would drop (the
 * writer's output is compared with the text's comments, so formatting keeps comments as soon as the writer does).
 */
final class Formatting {
    /** The edits, or why the document is left alone. */
    record Result(List<TextEdit> edits, String refusal) {
    }

    private Formatting() {
    }

    static Result of(Snapshot s) {
        if (s.analysis().program().isEmpty()) {
            return new Result(List.of(), s.sourceName() + " has errors; not formatted");
        }
        if (s.dialect() != Dialect.STRICT) {
            return new Result(List.of(), s.sourceName() + " is read as " + s.dialect().displayName()
                    + "; formatting writes standard FCL only ('fclcert convert' turns it into standard FCL)");
        }
        Program program = s.analysis().program().get();
        String canonical = new CanonicalWriter().write(program);
        int lost = s.outline().comments() - Outline.of(canonical).comments();
        if (lost > 0) {
            return new Result(List.of(), s.sourceName() + " not formatted: it has " + s.outline().comments()
                    + (s.outline().comments() == 1 ? " comment" : " comments")
                    + ", which fmt's layout does not keep yet; formatting would lose them");
        }
        if (canonical.equals(s.text())) {
            return new Result(List.of(), null);
        }
        Range whole = new Range(s.source().position(0), s.source().position(s.text().length()));
        return new Result(List.of(new TextEdit(whole, canonical)), null);
    }
}
