package org.fclcert.syntax;

import java.util.List;
import org.antlr.v4.runtime.DefaultErrorStrategy;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.misc.IntervalSet;

/**
 * ANTLR's recovery (single-token insertion and deletion, resynchronisation on follow sets), but
 * every report goes through {@link SyntaxMessages}, which turns the parser's state into a plain
 * sentence with a stable code. After the first error of a statement, further errors up to the end of
 * that statement are not reported: they are almost always consequences of the first.
 */
final class FclErrorStrategy extends DefaultErrorStrategy {
    private final ReaderDiagnostics diagnostics;
    private final List<Token> tokens;
    private int suppressThrough = -1;
    private boolean reported;

    /** Thrown to stop parsing a text with more errors than worth reporting. */
    static final class StopReading extends RuntimeException {
        private static final long serialVersionUID = 1L;

        StopReading() {
            super("too many syntax errors", null, false, false);
        }
    }

    FclErrorStrategy(ReaderDiagnostics diagnostics, List<Token> tokens) {
        this.diagnostics = diagnostics;
        this.tokens = tokens;
    }

    /**
     * True once the parser had to recover from an error (reported or suppressed): the tree may then
     * have gaps. Keywords read as names are repairs, not recoveries: the tree stays whole.
     */
    boolean recovered() {
        return reported;
    }

    /**
     * A keyword standing where a name is expected and followed by what follows a name ({@code TERM
     * term := ...}, {@code VAR_INPUT options : REAL;}) was meant as a name: report it once, read it
     * as an identifier, and go on as if it were one, so that the rest of the statement is still read.
     */
    @Override
    public void sync(Parser recognizer) throws RecognitionException {
        if (!inErrorRecoveryMode(recognizer) && keywordMeantAsName(recognizer)) {
            return;
        }
        super.sync(recognizer);
    }

    @Override
    public Token recoverInline(Parser recognizer) throws RecognitionException {
        if (!inErrorRecoveryMode(recognizer) && keywordMeantAsName(recognizer)) {
            Token name = recognizer.getCurrentToken();
            reportMatch(recognizer);
            recognizer.consume();
            return name;
        }
        return super.recoverInline(recognizer);
    }

    private boolean keywordMeantAsName(Parser recognizer) {
        Token t = recognizer.getCurrentToken();
        if (!Keywords.isKeyword(t.getType()) || !(t instanceof org.antlr.v4.runtime.CommonToken token)
                || recognizer.getContext() instanceof FclParser.WordContext
                || recognizer.getContext() instanceof FclParser.TypeNameContext) {
            return false;
        }
        // cheap tests first: this runs at every keyword of the text (sync), and the full expected set walks the
        // parser's whole context; the state's own next tokens are a subset of it, cached by the ATN
        int next = recognizer.getInputStream().LA(2);
        if (!SyntaxMessages.followsName(next)
                || recognizer.getATN().nextTokens(recognizer.getATN().states.get(recognizer.getState()))
                        .contains(t.getType())) {
            return false;
        }
        IntervalSet expected = recognizer.getExpectedTokens();
        if (expected.contains(t.getType()) || !expected.contains(FclLexer.IDENT)) {
            return false;
        }
        boolean recoveredBefore = reported;
        report(recognizer, t, expected);
        reported = recoveredBefore;
        token.setType(FclLexer.IDENT);
        return true;
    }

    @Override
    public void reportError(Parser recognizer, RecognitionException e) {
        if (inErrorRecoveryMode(recognizer)) {
            return;
        }
        beginErrorCondition(recognizer);
        Token offending = e.getOffendingToken() != null ? e.getOffendingToken() : recognizer.getCurrentToken();
        IntervalSet expected = e.getExpectedTokens();
        report(recognizer, offending, expected == null ? new IntervalSet() : expected);
    }

    @Override
    protected void reportUnwantedToken(Parser recognizer) {
        if (inErrorRecoveryMode(recognizer)) {
            return;
        }
        beginErrorCondition(recognizer);
        report(recognizer, recognizer.getCurrentToken(), getExpectedTokens(recognizer));
    }

    @Override
    protected void reportMissingToken(Parser recognizer) {
        if (inErrorRecoveryMode(recognizer)) {
            return;
        }
        beginErrorCondition(recognizer);
        report(recognizer, recognizer.getCurrentToken(), getExpectedTokens(recognizer));
    }

    private void report(Parser recognizer, Token offending, IntervalSet expected) {
        reported = true;
        int index = offending.getTokenIndex();
        if (index >= 0 && index <= suppressThrough
                || offending.getType() == Token.EOF && diagnostics.endOfTextExplained()) {
            return;
        }
        SyntaxMessages.Message m = SyntaxMessages.describe(recognizer.getContext(), offending, expected, tokens);
        Token before = semicolonMissing(expected) ? lineEndBefore(index, offending) : null;
        if (before != null) {
            // a forgotten ';' is a mistake of the line that lacks it: point there, as a compiler does
            diagnostics.error(diagnostics.at(before.getLine(), before.getCharPositionInLine() + before.getText().length()
                    + 1), m.code(), m.text() + (offending.getType() == Token.EOF ? "" : " on line " + offending.getLine()));
        } else {
            diagnostics.error(offending, m.code(), m.text());
        }
        suppressThrough = endOfStatement(index);
        if (diagnostics.tooMany()) {
            throw new StopReading();
        }
    }

    /** ';' could end the statement here and no block's END_ keyword could: a statement lacks its ';'. */
    private static boolean semicolonMissing(IntervalSet expected) {
        if (!expected.contains(FclLexer.SEMI)) {
            return false;
        }
        for (int type : expected.toList()) {
            String name = FclLexer.VOCABULARY.getSymbolicName(type);
            if (name != null && name.startsWith("END_")) {
                return false;
            }
        }
        return true;
    }

    /**
     * The last token on the default channel before {@code index}, when it ends a line before the one
     * {@code offending} is on: the place where a missing ';' belongs. Null otherwise.
     */
    private Token lineEndBefore(int index, Token offending) {
        if (index <= 0 || index > tokens.size()) {
            return null;
        }
        for (int i = index - 1; i >= 0; i--) {
            Token t = tokens.get(i);
            if (t.getChannel() == Token.DEFAULT_CHANNEL) {
                boolean earlierLine = offending.getType() == Token.EOF || t.getLine() < offending.getLine();
                return earlierLine && t.getText() != null && t.getText().indexOf('\n') < 0 ? t : null;
            }
        }
        return null;
    }

    /**
     * The index of the ';' ending the statement at {@code index}, or of the keyword starting the next
     * statement (an error found there is about the unfinished statement before it).
     */
    private int endOfStatement(int index) {
        if (index < 0) {
            return -1;
        }
        for (int i = index; i < tokens.size(); i++) {
            int type = tokens.get(i).getType();
            if (type == FclLexer.SEMI) {
                return i;
            }
            if (i > index && (Keywords.isStructural(type) || type == Token.EOF)) {
                return i;
            }
        }
        return tokens.size() - 1;
    }
}
