package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.Feature;

/**
 * The tokens of the jFuzzyLogic and fuzzylite dialects: words, numbers, the FCL punctuation; comments
 * as each library writes them ({@link Style}). Never fails: a mistake is a problem with a place, and
 * lexing goes on. The name after {@code FUNCTION_BLOCK} and {@code RULEBLOCK} is the rest of its line
 * (fuzzylite 5 wrote engine names verbatim, with blanks or '-'); none when the line ends there.
 */
final class DialectLexer {
    enum Kind { WORD, NUMBER, ASSIGN, COLON, SEMI, COMMA, LPAREN, RPAREN, DOTDOT, BAR, EXPRESSION, EOF }

    record Token(Kind kind, String text, int line, int column) {
        boolean is(String word) {
            return kind == Kind.WORD && text.equalsIgnoreCase(word);
        }
    }

    /**
     * How a library writes comments and numbers.
     *
     * @param hashComments  {@code #} starts a comment (fuzzylite)
     * @param blockComments {@code /* *\/} and {@code (* *)} are comments (jFuzzyLogic); when false they are
     *                      skipped as comments but reported as a style the library rejects
     * @param leadingDot    {@code .5} is a number (fuzzylite)
     */
    record Style(boolean hashComments, boolean blockComments, boolean leadingDot, String library) {
    }

    record Problem(DialectCode code, int line, int column, String message) {
    }

    /** A non-standard comment, for the O-COMMENT-STYLE feature and the giveaways. */
    record Comment(String style, int line, int column) {
    }

    final List<Token> tokens = new ArrayList<>();
    final List<Problem> problems = new ArrayList<>();
    final List<Comment> comments = new ArrayList<>();
    static final Feature COMMENT_FEATURE = Feature.O_COMMENT_STYLE;

    private final String s;
    private final Style style;
    private int i;
    private int line = 1;
    private int col = 1;

    private DialectLexer(String text, Style style) {
        this.s = text.startsWith("\uFEFF") ? text.substring(1) : text;
        this.style = style;
    }

    static DialectLexer lex(String text, Style style) {
        DialectLexer l = new DialectLexer(text, style);
        l.run();
        return l;
    }

    private char at(int k) {
        return k < s.length() ? s.charAt(k) : '\0';
    }

    private void advance() {
        if (s.charAt(i) == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
        i++;
    }

    private void run() {
        while (i < s.length()) {
            char c = s.charAt(i);
            int l0 = line;
            int c0 = col;
            if (Character.isWhitespace(c)) {
                advance();
            } else if (c == '/' && at(i + 1) == '/' || style.hashComments() && c == '#') {
                comments.add(new Comment(c == '#' ? "#" : "//", l0, c0));
                while (i < s.length() && s.charAt(i) != '\n') {
                    advance();
                }
            } else if (c == '/' && at(i + 1) == '*' || c == '(' && at(i + 1) == '*') {
                String end = c == '/' ? "*/" : "*)";
                if (!style.blockComments()) {
                    problems.add(new Problem(DialectCode.COMMENT_STYLE, l0, c0, style.library() + " does not accept '"
                            + c + "*' comments; it comments with '//' or '#'"));
                }
                if (c == '/') {
                    comments.add(new Comment("/* */", l0, c0));
                }
                advance();
                advance();
                boolean closed = false;
                while (i < s.length()) {
                    if (s.startsWith(end, i)) {
                        advance();
                        advance();
                        closed = true;
                        break;
                    }
                    advance();
                }
                if (!closed) {
                    problems.add(new Problem(DialectCode.UNTERMINATED_COMMENT, l0, c0,
                            "the comment starting here is never closed by '" + end + "'"));
                }
            } else if (Character.isLetter(c) || c == '_') {
                int start = i;
                while (i < s.length() && (Character.isLetterOrDigit(s.charAt(i)) || s.charAt(i) == '_')) {
                    advance();
                }
                String word = s.substring(start, i);
                tokens.add(new Token(Kind.WORD, word, l0, c0));
                if (word.equalsIgnoreCase("FUNCTION_BLOCK") || word.equalsIgnoreCase("RULEBLOCK")) {
                    blockName();
                } else if (word.equalsIgnoreCase("function") && tokens.size() > 1
                        && tokens.get(tokens.size() - 2).kind() == Kind.ASSIGN) {
                    expression();
                }
            } else if (Character.isDigit(c) || c == '.' && Character.isDigit(at(i + 1))
                    || (c == '+' || c == '-') && (Character.isDigit(at(i + 1)) || at(i + 1) == '.'
                            || Character.isLetter(at(i + 1)))) {
                number(l0, c0);
            } else if (c == ':' && at(i + 1) == '=') {
                advance();
                advance();
                tokens.add(new Token(Kind.ASSIGN, ":=", l0, c0));
            } else if (c == '.' && at(i + 1) == '.') {
                advance();
                advance();
                tokens.add(new Token(Kind.DOTDOT, "..", l0, c0));
            } else {
                Kind k = switch (c) {
                    case ':' -> Kind.COLON;
                    case ';' -> Kind.SEMI;
                    case ',' -> Kind.COMMA;
                    case '(' -> Kind.LPAREN;
                    case ')' -> Kind.RPAREN;
                    case '|' -> Kind.BAR;
                    default -> null;
                };
                if (k == null) {
                    problems.add(new Problem(DialectCode.UNEXPECTED_CHARACTER, l0, c0,
                            "unexpected character '" + printable(c) + "'"));
                } else {
                    tokens.add(new Token(k, String.valueOf(c), l0, c0));
                }
                advance();
            }
        }
        tokens.add(new Token(Kind.EOF, "end of text", line, col));
    }

    /** [+-] digits [. digits] [e [+-] digits], '.5' (fuzzylite only), and [+-]inf / nan (fuzzylite, checked later). */
    private void number(int l0, int c0) {
        int start = i;
        if (s.charAt(i) == '+' || s.charAt(i) == '-') {
            advance();
        }
        if (Character.isLetter(at(i))) {
            int w = i;
            while (i < s.length() && Character.isLetterOrDigit(s.charAt(i))) {
                advance();
            }
            String word = s.substring(w, i);
            if (!word.equals("inf")) {
                problems.add(new Problem(DialectCode.BAD_NUMBER, l0, c0, "'" + s.substring(start, i)
                        + "' is not a number"));
            }
            tokens.add(new Token(Kind.NUMBER, s.substring(start, i), l0, c0));
            return;
        }
        boolean leadingDot = at(i) == '.';
        while (Character.isDigit(at(i))) {
            advance();
        }
        if (at(i) == '.' && at(i + 1) != '.') {
            advance();
            if (!Character.isDigit(at(i))) {
                problems.add(new Problem(DialectCode.BAD_NUMBER, l0, c0, "a number needs digits after '.'"));
            }
            while (Character.isDigit(at(i))) {
                advance();
            }
        }
        if ((at(i) == 'e' || at(i) == 'E') && (Character.isDigit(at(i + 1))
                || (at(i + 1) == '+' || at(i + 1) == '-') && Character.isDigit(at(i + 2)))) {
            advance();
            if (at(i) == '+' || at(i) == '-') {
                advance();
            }
            while (Character.isDigit(at(i))) {
                advance();
            }
        }
        String text = s.substring(start, i);
        if (leadingDot && !style.leadingDot()) {
            problems.add(new Problem(DialectCode.BAD_NUMBER, l0, c0,
                    "jFuzzyLogic rejects '" + text + "': write a digit before the '.'"));
        }
        if (Character.isLetter(at(i)) || at(i) == '_') {
            int w = i;
            while (i < s.length() && (Character.isLetterOrDigit(s.charAt(i)) || s.charAt(i) == '_')) {
                advance();
            }
            problems.add(new Problem(DialectCode.BAD_NUMBER, l0, c0,
                    "'" + text + s.substring(w, i) + "' is not a number"));
        }
        tokens.add(new Token(Kind.NUMBER, text, l0, c0));
    }

    /** The rest of the line after a block keyword, up to a comment, as one WORD (blanks inside kept). */
    private void blockName() {
        while (i < s.length() && (s.charAt(i) == ' ' || s.charAt(i) == '\t')) {
            advance();
        }
        int l0 = line;
        int c0 = col;
        int start = i;
        while (i < s.length() && s.charAt(i) != '\n' && s.charAt(i) != '\r' && !commentStart(i) && s.charAt(i) != ';') {
            advance();
        }
        String name = s.substring(start, i).strip();
        if (!name.isEmpty()) {
            tokens.add(new Token(Kind.WORD, name, l0, c0));
        }
    }

    /** A Takagi–Sugeno term's formula ({@code TERM t := Function sin(x)/x;}): its text up to ';', as one token. */
    private void expression() {
        int l0 = line;
        int c0 = col;
        int start = i;
        while (i < s.length() && s.charAt(i) != ';' && s.charAt(i) != '\n' && !commentStart(i)) {
            advance();
        }
        tokens.add(new Token(Kind.EXPRESSION, s.substring(start, i).strip(), l0, c0));
    }

    private boolean commentStart(int k) {
        char c = s.charAt(k);
        return c == '/' && (at(k + 1) == '/' || at(k + 1) == '*') || c == '(' && at(k + 1) == '*'
                || style.hashComments() && c == '#';
    }

    private static String printable(char c) {
        return c < 32 || c > 126 ? String.format("\\u%04x", (int) c) : String.valueOf(c);
    }
}
