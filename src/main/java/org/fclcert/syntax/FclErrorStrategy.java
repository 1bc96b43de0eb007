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

    /** True once any parse error has been found (reported or suppressed). */
    boolean foundErrors() {
        return reported;
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
        diagnostics.error(offending, m.code(), m.text());
        suppressThrough = endOfStatement(index);
        if (diagnostics.tooMany()) {
            throw new StopReading();
        }
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
