package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;
import org.fclcert.syntax.dialect.DialectReader.Giveaway;

/**
 * The shared ground of the giveaways: one lexing of the text that knows every comment style of every
 * library ({@code //}, {@code /* *\/}, {@code (* *)}, {@code #}), so no word inside a comment ever counts,
 * handed to each {@link LibraryDialect#giveaways} strategy.
 */
final class Giveaways {
    private static final DialectLexer.Style ALL_COMMENTS = new DialectLexer.Style(true, true, true, "any library");

    private Giveaways() {
    }

    /** The text's tokens outside comments and where its comments are. */
    static final class Scan {
        private final DialectLexer lexer;
        private final boolean[] inVar;

        Scan(String text) {
            this.lexer = DialectLexer.lex(text == null ? "" : text, ALL_COMMENTS);
            List<Token> t = lexer.tokens;
            inVar = new boolean[t.size()];
            boolean in = false;
            for (int i = 0; i < t.size(); i++) {
                Token tok = t.get(i);
                if (tok.is("VAR_INPUT") || tok.is("VAR_OUTPUT") || tok.is("VAR")) {
                    in = true;
                } else if (tok.is("END_VAR")) {
                    in = false;
                }
                inVar[i] = in;
            }
        }

        List<Token> tokens() {
            return lexer.tokens;
        }

        /** The lines of the comments written in {@code style} ({@code //}, {@code /* *\/}, {@code #}). */
        List<Integer> comments(String style) {
            return lexer.comments.stream().filter(c -> c.style().equals(style)).map(DialectLexer.Comment::line).toList();
        }

        boolean inVarSection(int token) {
            return inVar[token];
        }
    }

    /**
     * One dialect's giveaways in source order. A failure of the scan is a bug of fclcert, not evidence: it is
     * thrown as an {@link IllegalStateException} for {@link DialectReaders#auto} to report, never swallowed.
     */
    static List<Giveaway> find(String text, LibraryDialect dialect) {
        List<Giveaway> out;
        try {
            out = new ArrayList<>(dialect.giveaways(new Scan(text)));
        } catch (RuntimeException | StackOverflowError e) {
            throw new IllegalStateException("the " + dialect.library() + " giveaway scan failed", e);
        }
        out.sort(Comparator.comparingInt(Giveaway::line));
        return List.copyOf(out);
    }

    /** A RULE whose line holds no ';' and whose next token is on a later line. */
    static boolean ruleWithoutSemicolon(List<Token> t, int i) {
        int line = t.get(i).line();
        for (int j = i + 1; j < t.size(); j++) {
            Token x = t.get(j);
            if (x.line() != line || x.kind() == Kind.EOF) {
                // the rule really ends with its line only when the next line starts the next rule or ends the
                // block; a standard rule continued on the next line ('AND ...', 'THEN ...') is no giveaway
                return j > i + 1 && (x.kind() == Kind.EOF || x.is("RULE") || x.is("END_RULEBLOCK"));
            }
            if (x.kind() == Kind.SEMI) {
                return false;
            }
        }
        return false;
    }
}
