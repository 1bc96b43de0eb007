package org.fclcert.syntax;

import java.util.HashMap;
import java.util.Map;
import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.CommonTokenFactory;
import org.antlr.v4.runtime.IntStream;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenFactory;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.misc.Interval;
import org.antlr.v4.runtime.misc.Pair;

/**
 * The lexer rules of Fcl.g4, written out by hand: the same tokens as the generated {@link FclLexer} — type,
 * channel, start and stop (code-point indices), line, column and text — several times faster, because it
 * decides each token from a character or two instead of running the lexer's ATN simulation.
 * {@code FclTokenSourceTest} holds the two together on the corpus, on every code point and on random text.
 * The grammar stays the one description of the language; this class is how the strict reader reads it.
 *
 * <p>Identifier and keyword texts are shared: every occurrence of one spelling is the same String, which
 * the model keeps (a large program names a few variables and terms many times).
 *
 * <p>The rules, longest match first and the earlier rule on a tie, as ANTLR does: keywords (any case) over
 * IDENT over BAD_IDENT for a run of letters, digits and underscores; numbers with an optional sign (REAL,
 * BASED_INTEGER, INTEGER, BAD_REAL); {@code (* ... *)} comments on the hidden channel, running to the end of
 * the text when unterminated; white space skipped; any other code point an ANY token.
 */
final class FclTokenSource implements TokenSource {
    private static final Map<String, Integer> KEYWORDS = keywords();

    /**
     * The text's characters (scanned far more often than a String's accessors are cheap); dropped at the end
     * of the text, since every token made keeps this source (token texts come from the input stream).
     */
    private char[] text;
    private final int length;
    private final CharStream input;
    private final Pair<TokenSource, CharStream> pair;
    /** Spellings of words seen (identifiers and keywords, each one shared String) and their token types. */
    private String[] wordText = new String[256];
    private int[] wordType = new int[256];
    private int words;
    private TokenFactory<?> factory = CommonTokenFactory.DEFAULT;
    private final boolean supplementary;
    /** Position: char index into the text, code-point index (ANTLR's), line and column (in code points). */
    private int pos;
    private int index;
    private int line = 1;
    private int column;

    FclTokenSource(String text, String sourceName) {
        this.text = text.toCharArray();
        this.length = this.text.length;
        boolean sup = false;
        for (int i = 0; i < length && !sup; i++) {
            sup = Character.isSurrogate(this.text[i]);
        }
        this.supplementary = sup;
        // token texts come from the input stream by code-point index: without surrogates that is the String's
        this.input = sup ? CharStreams.fromString(text, sourceName) : new StringCharStream(text, sourceName);
        this.pair = new Pair<>(this, input);
    }

    /** A CharStream over a String without surrogates, where code-point and char indices agree: no copy. */
    private static final class StringCharStream implements CharStream {
        private final String text;
        private final String name;
        private int p;

        StringCharStream(String text, String name) {
            this.text = text;
            this.name = name;
        }

        @Override
        public String getText(Interval interval) {
            int from = Math.max(0, interval.a);
            int to = Math.min(text.length() - 1, interval.b);
            return from > to ? "" : text.substring(from, to + 1);
        }

        @Override
        public void consume() {
            if (p >= text.length()) {
                throw new IllegalStateException("cannot consume EOF");
            }
            p++;
        }

        @Override
        public int LA(int i) {
            int at = i > 0 ? p + i - 1 : p + i;
            return i == 0 || at < 0 || at >= text.length() ? IntStream.EOF : text.charAt(at);
        }

        @Override
        public int mark() {
            return -1;
        }

        @Override
        public void release(int marker) {
        }

        @Override
        public int index() {
            return p;
        }

        @Override
        public void seek(int index) {
            p = Math.min(index, text.length());
        }

        @Override
        public int size() {
            return text.length();
        }

        @Override
        public String getSourceName() {
            return name == null || name.isEmpty() ? IntStream.UNKNOWN_SOURCE_NAME : name;
        }

        @Override
        public String toString() {
            return text;
        }
    }

    @Override
    public Token nextToken() {
        if (text == null) {
            return token(Token.EOF, index, index - 1, line, column);
        }
        skipWhiteSpace();
        if (pos >= length) {
            text = null;
            return token(Token.EOF, index, index - 1, line, column);
        }
        int startPos = pos;
        int startIndex = index;
        int startLine = line;
        int startColumn = column;
        char c = text[pos];
        int type;
        int end;    // char index after the token
        if (isLetter(c) || c == '_') {
            end = run(pos);
            int at = word(startPos, end);
            advanceSimple(end);
            CommonToken t = token(wordType[at], startIndex, index - 1, startLine, startColumn);
            t.setText(wordText[at]);
            return t;
        }
        if (isDigit(c) || (c == '+' || c == '-' || c == '.') && numberFollows(pos)) {
            long packed = number(pos);
            type = (int) (packed >>> 32);
            end = (int) packed;
            advanceSimple(end);
            return token(type, startIndex, index - 1, startLine, startColumn);
        }
        switch (c) {
            case '(' -> {
                if (pos + 1 < length && text[pos + 1] == '*') {
                    int close = pos + 2;
                    while (close + 1 < length && !(text[close] == '*' && text[close + 1] == ')')) {
                        close++;
                    }
                    end = close + 1 < length ? close + 2 : length;
                    advance(end);
                    return token(FclLexer.COMMENT, Token.HIDDEN_CHANNEL, startIndex, index - 1, startLine,
                            startColumn);
                }
                type = FclLexer.LPAREN;
                end = pos + 1;
            }
            case ')' -> {
                type = FclLexer.RPAREN;
                end = pos + 1;
            }
            case ':' -> {
                boolean assign = pos + 1 < length && text[pos + 1] == '=';
                type = assign ? FclLexer.ASSIGN : FclLexer.COLON;
                end = pos + (assign ? 2 : 1);
            }
            case ';' -> {
                type = FclLexer.SEMI;
                end = pos + 1;
            }
            case ',' -> {
                type = FclLexer.COMMA;
                end = pos + 1;
            }
            case '=' -> {
                type = FclLexer.EQUALS;
                end = pos + 1;
            }
            case '.' -> {
                boolean dots = pos + 1 < length && text[pos + 1] == '.';
                type = dots ? FclLexer.DOTDOT : FclLexer.ANY;
                end = pos + (dots ? 2 : 1);
            }
            default -> {
                type = FclLexer.ANY;
                end = pos + Character.charCount(Character.codePointAt(text, pos));
            }
        }
        advance(end);
        return token(type, startIndex, index - 1, startLine, startColumn);
    }

    private CommonToken token(int type, int start, int stop, int atLine, int atColumn) {
        return token(type, Token.DEFAULT_CHANNEL, start, stop, atLine, atColumn);
    }

    private CommonToken token(int type, int channel, int start, int stop, int atLine, int atColumn) {
        return (CommonToken) factory.create(pair, type, null, channel, start, stop, atLine, atColumn);
    }

    /**
     * The slot of the word text[from, to) in the table of spellings seen (open addressing on the characters,
     * so that a spelling seen before costs no String), added with its token type when new.
     */
    private int word(int from, int to) {
        int h = 0;
        for (int i = from; i < to; i++) {
            h = 31 * h + text[i];
        }
        int mask = wordText.length - 1;
        for (int at = (h ^ (h >>> 16)) & mask; ; at = (at + 1) & mask) {
            String w = wordText[at];
            if (w == null) {
                if (2 * (words + 1) > wordText.length) {
                    grow();
                    return word(from, to);
                }
                String spelling = new String(text, from, to - from);
                Integer keyword = KEYWORDS.get(spelling.toUpperCase(java.util.Locale.ROOT));
                wordText[at] = spelling;
                wordType[at] = keyword != null ? keyword : isIdent(from, to) ? FclLexer.IDENT : FclLexer.BAD_IDENT;
                words++;
                return at;
            }
            if (w.length() == to - from && same(w, from)) {
                return at;
            }
        }
    }

    private boolean same(String w, int from) {
        for (int k = 0; k < w.length(); k++) {
            if (w.charAt(k) != text[from + k]) {
                return false;
            }
        }
        return true;
    }

    private void grow() {
        String[] oldText = wordText;
        int[] oldType = wordType;
        wordText = new String[2 * oldText.length];
        wordType = new int[2 * oldText.length];
        int mask = wordText.length - 1;
        for (int k = 0; k < oldText.length; k++) {
            String w = oldText[k];
            if (w != null) {
                int h = w.hashCode();
                int at = (h ^ (h >>> 16)) & mask;
                while (wordText[at] != null) {
                    at = (at + 1) & mask;
                }
                wordText[at] = w;
                wordType[at] = oldType[k];
            }
        }
    }

    private void skipWhiteSpace() {
        while (pos < length) {
            char c = text[pos];
            if (c == '\n') {
                line++;
                column = 0;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\u000B') {
                column++;
            } else {
                return;
            }
            pos++;
            index++;
        }
    }

    /** Moves to {@code end} over characters that are neither line breaks nor surrogates. */
    private void advanceSimple(int end) {
        index += end - pos;
        column += end - pos;
        pos = end;
    }

    /** Moves to {@code end}, counting lines and code points. */
    private void advance(int end) {
        while (pos < end) {
            char c = text[pos];
            if (c == '\n') {
                line++;
                column = 0;
            } else {
                column++;
            }
            pos += supplementary && Character.isHighSurrogate(c) && pos + 1 < end
                    && Character.isLowSurrogate(text[pos + 1]) ? 2 : 1;
            index++;
        }
    }

    private static boolean isLetter(char c) {
        return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z';
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    private static boolean isWordChar(char c) {
        return isLetter(c) || isDigit(c) || c == '_';
    }

    /** The end of the run of letters, digits and underscores from {@code from}. */
    private int run(int from) {
        int i = from;
        while (i < length && isWordChar(text[i])) {
            i++;
        }
        return i;
    }

    /** IDENT: ([a-z] | '_' [a-z0-9]) ('_'? [a-z0-9])* over the whole run. */
    private boolean isIdent(int from, int to) {
        if (text[from] == '_' && (to - from < 2 || text[from + 1] == '_')) {
            return false;
        }
        for (int i = from + 1; i < to; i++) {
            if (text[i] == '_' && (text[i - 1] == '_' || i + 1 == to)) {
                return false;
            }
        }
        return true;
    }

    /** After a sign or a '.': a number follows when a digit does (after an optional '.' for a sign). */
    private boolean numberFollows(int at) {
        int i = at + 1;
        if (text[at] != '.' && i < length && text[i] == '.') {
            i++;    // a sign, then '.'
        }
        return digitAt(i);
    }

    /** DIGITS: [0-9] [0-9_]*, from a digit; its end. */
    private int digits(int from) {
        int i = from + 1;
        while (i < length && (isDigit(text[i]) || text[i] == '_')) {
            i++;
        }
        return i;
    }

    private boolean digitAt(int i) {
        return i < length && isDigit(text[i]);
    }

    /** The end of EXPONENT: 'E' [+-]? DIGITS at {@code at}, or -1 when there is none. */
    private int exponent(int at) {
        if (at >= length || (text[at] != 'E' && text[at] != 'e')) {
            return -1;
        }
        int i = at + 1;
        if (i < length && (text[i] == '+' || text[i] == '-')) {
            i++;
        }
        return digitAt(i) ? digits(i) : -1;
    }

    /** The number at {@code from} (known to start one): its type in the high half, its end in the low. */
    private long number(int from) {
        int i = from;
        if (text[i] == '+' || text[i] == '-') {
            i++;
        }
        if (text[i] == '.') {
            // BAD_REAL: '.' DIGITS EXPONENT?
            int end = digits(i + 1);
            int e = exponent(end);
            return pack(FclLexer.BAD_REAL, e > 0 ? e : end);
        }
        // BASED_INTEGER: [0-9]+ '#' [0-9a-z_]+ (no underscore before the '#')
        int plain = i;
        while (plain < length && isDigit(text[plain])) {
            plain++;
        }
        if (plain + 1 < length && text[plain] == '#' && isWordChar(text[plain + 1])) {
            return pack(FclLexer.BASED_INTEGER, run(plain + 1));
        }
        int end = digits(i);
        if (end + 1 < length && text[end] == '.' && isDigit(text[end + 1])) {
            int real = digits(end + 1);
            int e = exponent(real);
            return pack(FclLexer.REAL_LITERAL, e > 0 ? e : real);
        }
        int e = exponent(end);
        return e > 0 ? pack(FclLexer.BAD_REAL, e) : pack(FclLexer.INTEGER, end);
    }

    private static long pack(int type, int end) {
        return ((long) type << 32) | end;
    }

    private static Map<String, Integer> keywords() {
        Map<String, Integer> k = new HashMap<>();
        for (int type = 1; type <= FclLexer.VOCABULARY.getMaxTokenType(); type++) {
            String literal = FclLexer.VOCABULARY.getLiteralName(type);
            if (literal != null && literal.length() > 2 && Character.isLetter(literal.charAt(1))) {
                k.put(literal.substring(1, literal.length() - 1).toUpperCase(java.util.Locale.ROOT), type);
            }
        }
        return Map.copyOf(k);
    }

    @Override
    public int getLine() {
        return line;
    }

    @Override
    public int getCharPositionInLine() {
        return column;
    }

    @Override
    public CharStream getInputStream() {
        return input;
    }

    @Override
    public String getSourceName() {
        return input.getSourceName();
    }

    @Override
    public void setTokenFactory(TokenFactory<?> factory) {
        this.factory = factory;
    }

    @Override
    public TokenFactory<?> getTokenFactory() {
        return factory;
    }
}
