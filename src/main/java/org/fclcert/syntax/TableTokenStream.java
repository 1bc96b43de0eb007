package org.fclcert.syntax;

import org.antlr.v4.runtime.RuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.TokenStream;
import org.antlr.v4.runtime.misc.Interval;

/**
 * The parser's view of a {@link TokenTable}: random access by index. From a compact table each token is made
 * when the parser first looks at it and held in a small ring, so that the lookahead the parser is working on
 * is the same object each time it asks. Unlike a buffered token stream it keeps no token the parser has moved
 * past: those the parse tree still refers to live on with the tree, the rest are garbage (a large program
 * never has all its tokens as objects at once).
 */
final class TableTokenStream implements TokenStream {
    private static final int RING = 512;

    private final TokenTable table;
    /** Null when the table keeps its token objects: then there is nothing to make, and no ring to set up per read. */
    private final Token[] ring;
    private final int[] ringIndex;
    private int p;

    TableTokenStream(TokenTable table) {
        this.table = table;
        if (table.keepsTokens()) {
            ring = null;
            ringIndex = null;
        } else {
            ring = new Token[RING];
            ringIndex = new int[RING];
            java.util.Arrays.fill(ringIndex, -1);
        }
    }

    @Override
    public Token get(int i) {
        if (i < 0 || i >= table.size()) {
            throw new IndexOutOfBoundsException("token index " + i + " out of range 0.." + (table.size() - 1));
        }
        if (ring == null) {
            return table.token(i);
        }
        int slot = i & (RING - 1);
        if (ringIndex[slot] != i) {
            ring[slot] = table.token(i);
            ringIndex[slot] = i;
        }
        return ring[slot];
    }

    @Override
    public Token LT(int k) {
        if (k == 0) {
            return null;
        }
        int i = k > 0 ? p + k - 1 : p + k;
        if (i < 0) {
            return null;
        }
        return get(Math.min(i, table.size() - 1));    // past the end: the EOF token again
    }

    /** The type of LT(k), from the table: no token is made for a look at its type. */
    @Override
    public int LA(int k) {
        int i = k > 0 ? p + k - 1 : p + k;
        return k == 0 || i < 0 ? Token.INVALID_TYPE : table.type(Math.min(i, table.size() - 1));
    }

    @Override
    public void consume() {
        if (table.type(p) == Token.EOF) {
            throw new IllegalStateException("cannot consume EOF");
        }
        p++;
    }

    @Override
    public int mark() {
        return 0;       // every token stays reachable by index: nothing to hold
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
        p = Math.max(0, Math.min(index, table.size() - 1));
    }

    @Override
    public int size() {
        return table.size();
    }

    @Override
    public String getSourceName() {
        TokenSource s = table.tokenSource();
        return s == null ? UNKNOWN_SOURCE_NAME : s.getSourceName();
    }

    @Override
    public TokenSource getTokenSource() {
        return table.tokenSource();
    }

    @Override
    public String getText(Interval interval) {
        int from = Math.max(0, interval.a);
        int to = Math.min(table.size() - 1, interval.b);
        StringBuilder s = new StringBuilder();
        for (int i = from; i <= to; i++) {
            Token t = get(i);
            if (t.getType() == Token.EOF) {
                break;
            }
            s.append(t.getText());
        }
        return s.toString();
    }

    @Override
    public String getText() {
        return getText(Interval.of(0, table.size() - 1));
    }

    @Override
    public String getText(RuleContext ctx) {
        return getText(ctx.getSourceInterval());
    }

    @Override
    public String getText(Token start, Token stop) {
        return start == null || stop == null ? "" : getText(Interval.of(start.getTokenIndex(), stop.getTokenIndex()));
    }
}
