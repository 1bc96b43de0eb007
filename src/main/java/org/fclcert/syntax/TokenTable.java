package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.misc.Pair;

/**
 * The pre-scanned tokens of one text, kept compactly: per token its type, start and stop (code-point indices,
 * as ANTLR counts), and per line where it starts — about nine bytes a token where a CommonToken in a list
 * takes some sixty, which matters for a program of millions of tokens (issue 18). {@link #token(int)} makes
 * the CommonToken again, equal in every field to the one that was added; identifiers keep their shared text.
 * Every token must come from the same token source, in order. Tokens a dialect's filter rewrote may carry
 * texts the source text does not hold: a table {@link #keepingTokens()} keeps such tokens as they are.
 */
final class TokenTable {
    static {
        // token types are kept in a byte: a grammar of more than 127 token types needs a wider array
        if (FclLexer.VOCABULARY.getMaxTokenType() > Byte.MAX_VALUE) {
            throw new IllegalStateException("Fcl.g4 has more token types than TokenTable keeps in a byte");
        }
    }

    /** The tokens themselves, when kept ({@link #keepingTokens()}); null in the compact form. */
    private final List<Token> kept;
    private Pair<TokenSource, CharStream> source;
    private byte[] types = new byte[256];
    private int[] starts = new int[256];
    /** The stop index (-1 for the EOF of an empty text), or for an identifier -2 - the index of its spelling in {@link #words}. */
    private int[] stops = new int[256];
    private int count;
    private final List<String> words = new ArrayList<>();
    private final Map<String, Integer> wordIds = new IdentityHashMap<>();
    /** Lines that hold tokens, ascending, and the index at which each starts. */
    private int[] lines = new int[64];
    private int[] lineStarts = new int[64];
    private int lineCount;
    private int lastLine;

    /** The compact form. */
    TokenTable() {
        this.kept = null;
    }

    private TokenTable(List<Token> kept) {
        this.kept = kept;
    }

    /** A table that keeps the token objects themselves (for tokens a filter may have made up). */
    static TokenTable keepingTokens() {
        return new TokenTable(new ArrayList<>());
    }

    /** The same, sized for about {@code expected} tokens (no copies of a growing list). */
    static TokenTable keepingTokens(int expected) {
        return new TokenTable(new ArrayList<>(expected));
    }

    /** Whether the token objects themselves are kept ({@link #keepingTokens()}). */
    boolean keepsTokens() {
        return kept != null;
    }

    int size() {
        return kept != null ? kept.size() : count;
    }

    /** Appends a token (of the default channel). */
    void add(Token t) {
        if (kept != null) {
            kept.add(t);
            return;
        }
        if (count == types.length) {
            int n = 2 * count;
            types = Arrays.copyOf(types, n);
            starts = Arrays.copyOf(starts, n);
            stops = Arrays.copyOf(stops, n);
        }
        count++;
        set(count - 1, t);
    }

    /** Replaces the last token. */
    void setLast(Token t) {
        if (kept != null) {
            kept.set(kept.size() - 1, t);
            return;
        }
        set(count - 1, t);
    }

    private void set(int i, Token t) {
        if (source == null) {
            source = new Pair<>(t.getTokenSource(), t.getInputStream());
        }
        types[i] = (byte) t.getType();
        starts[i] = t.getStartIndex();
        stops[i] = t.getStopIndex();
        if (t.getType() == FclLexer.IDENT && t instanceof CommonToken c && text(c) != null
                && t.getStopIndex() - t.getStartIndex() + 1 == text(c).length()) {
            String w = text(c);
            Integer id = wordIds.get(w);
            if (id == null) {
                id = words.size();
                words.add(w);
                wordIds.put(w, id);
            }
            stops[i] = -2 - id;
        }
        int line = t.getLine();
        if (lineCount == 0 || lines[lineCount - 1] < line) {
            if (lineCount == lines.length) {
                lines = Arrays.copyOf(lines, 2 * lineCount);
                lineStarts = Arrays.copyOf(lineStarts, 2 * lineCount);
            }
            lines[lineCount] = line;
            lineStarts[lineCount++] = t.getStartIndex() - t.getCharPositionInLine();
        }
    }

    /** The text the lexer gave the token (identifiers carry their shared spelling), else null. */
    private static String text(CommonToken c) {
        return c.getText();
    }

    /** The type of token i. */
    int type(int i) {
        return kept != null ? kept.get(i).getType() : types[i];
    }

    /** Token i: made anew (equal in type, channel, start, stop, line, column and text), or the one kept. */
    Token token(int i) {
        if (kept != null) {
            Token t = kept.get(i);
            if (t instanceof org.antlr.v4.runtime.WritableToken w) {
                w.setTokenIndex(i);
            }
            return t;
        }
        int stop = stops[i];
        String word = stop < -1 ? words.get(-2 - stop) : null;
        int start = starts[i];
        CommonToken t = new CommonToken(source, types[i], Token.DEFAULT_CHANNEL, start,
                word != null ? start + word.length() - 1 : stop);
        int at = lineAt(start);
        t.setLine(lines[at]);
        t.setCharPositionInLine(start - lineStarts[at]);
        t.setTokenIndex(i);
        if (word != null) {
            t.setText(word);
        }
        return t;
    }

    /** The entry of the line holding the token starting at index {@code start}: the last line starting at or before it. */
    private int lineAt(int start) {
        int c = lastLine;      // tokens are asked for mostly in order: try the line of the last one first
        if (lineStarts[c] <= start && (c + 1 == lineCount || lineStarts[c + 1] > start)) {
            return c;
        }
        if (c + 1 < lineCount && lineStarts[c + 1] <= start && (c + 2 == lineCount || lineStarts[c + 2] > start)) {
            lastLine = c + 1;
            return c + 1;
        }
        int lo = 0;
        int hi = lineCount - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (lineStarts[mid] <= start) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        lastLine = lo;
        return lo;
    }

    /** Every token (the paths after a syntax error, which need them all). */
    List<Token> toList() {
        if (kept != null) {
            return kept;
        }
        List<Token> all = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            all.add(token(i));
        }
        return all;
    }

    TokenSource tokenSource() {
        if (kept != null) {
            return kept.isEmpty() ? null : kept.get(0).getTokenSource();
        }
        return source == null ? null : source.a;
    }
}
