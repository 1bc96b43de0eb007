package org.fclcert.lsp;

import java.util.List;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.fclcert.model.Feature;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.RoundTrip;
import org.fclcert.write.Written;

/**
 * Formatting as one edit of the whole text: standard FCL in {@code fclcert fmt}'s layout (the canonical writer,
 * comments kept where they stood), a text read in a library's dialect in that library's layout (its writer in
 * {@link DialectWriters}), so formatting never turns a document into another dialect. It leaves a text alone
 * rather than lose something: a text with errors, a dialect without a writer, a dialect text whose writer would
 * lose a construct, a comment or the program's meaning (read back and evaluated against the original).
 */
final class Formatting {
    /** The edits, or why the document is left alone. */
    record Result(List<TextEdit> edits, String refusal) {
    }

    private Formatting() {
    }

    static Result of(Snapshot s) {
        if (s.analysis().program().isEmpty()) {
            return refused(s.sourceName() + " has errors; not formatted");
        }
        Program program = s.analysis().program().get();
        String formatted;
        if (s.dialect() == Dialect.STRICT) {
            formatted = new CanonicalWriter().write(program);
            // the writer keeps every comment; should one ever go missing, leave the text alone
            int lost = s.outline().comments() - Outline.of(formatted).comments();
            if (lost > 0) {
                return refused(s.sourceName() + " not formatted: the layout would lose " + count(lost, "comment"));
            }
        } else {
            Dialect d = s.dialect();
            String as = s.sourceName() + " is read as " + d.displayName();
            if (!DialectWriters.libraries().contains(d)) {
                return refused(as + ", and fclcert has no writer of " + d.displayName() + "; not formatted ('fclcert"
                        + " convert' turns it into standard FCL, which can be formatted)");
            }
            int comments = dialectComments(s, program);
            if (comments > 0) {
                return refused(as + "; not formatted: it has " + count(comments, "comment") + ", which fclcert's "
                        + d.displayName() + " writer does not keep (standard FCL's layout keeps comments)");
            }
            Written written = DialectWriters.writer(d).write(program);
            if (!written.exact()) {
                return refused(as + "; not formatted: its writer cannot say all of it ("
                        + written.notExpressible().get(0).message() + ")");
            }
            RoundTrip back = DialectWriters.readBackAndCompare(program, written);
            if (!back.equal()) {
                return refused(as + "; not formatted: the text in its writer's layout would not mean the same ("
                        + back.summary() + ")");
            }
            formatted = written.text();
        }
        if (formatted.equals(s.text())) {
            return new Result(List.of(), null);
        }
        Range whole = new Range(s.source().position(0), s.source().position(s.text().length()));
        return new Result(List.of(new TextEdit(whole, formatted)), null);
    }

    /**
     * The comments of a dialect text, none of which a library writer keeps: {@code (* *)} ones (less FFLL's
     * RANGE comments, which its writer writes again) and the styles the dialect readers record ({@code //},
     * {@code /* *\/}, {@code #}).
     */
    private static int dialectComments(Snapshot s, Program program) {
        long ranges = program.dialectFeatures().stream().filter(f -> f.feature() == Feature.O_RANGE_COMMENT).count();
        long styles = program.dialectFeatures().stream().filter(f -> f.feature() == Feature.O_COMMENT_STYLE).count();
        return (int) (Math.max(0, s.outline().comments() - ranges) + styles);
    }

    private static Result refused(String why) {
        return new Result(List.of(), why);
    }

    private static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
