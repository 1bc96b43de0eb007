package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.DefaultErrorStrategy;
import org.antlr.v4.runtime.ListTokenSource;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.IntervalSet;
import org.antlr.v4.runtime.misc.ParseCancellationException;
import org.fclcert.model.Program;

/**
 * After a syntax error, a program for the semantic checks only: the tokens are repaired the way a
 * compiler's reader recovers (a missing punctuation token inserted, a stray token dropped) until they
 * parse; when every error could be repaired that way and the repaired tree builds without error, the
 * model is handed to the checks so that one forgotten ';' does not hide the mistakes after it. Errors
 * that only a guess at a whole statement could repair give no program: the checks would then report
 * consequences of the guess, not of the text. The repair never changes what is reported as syntax
 * errors: those come from the first reading of the text alone.
 */
final class SyntaxRepair {
    private static final int MAX_REPAIRS = 20;

    private SyntaxRepair() {
    }

    /** The program the repaired tokens give, or empty when the errors cannot be repaired token by token. */
    static Optional<Program> program(String sourceName, List<Token> tokens, ReaderOptions options,
            ReaderDiagnostics warningsTo, boolean directPath) {
        // the tokens themselves, not copies: after the parse that reported the errors nothing else reads them,
        // and a large program's tokens are most of what the error path holds
        List<Token> current = new ArrayList<>(tokens);
        int lowestNext = 0;
        for (int attempt = 0; attempt <= MAX_REPAIRS; attempt++) {
            if (attempt > 0 && directPath && options.tokenFilter() == ReaderOptions.TokenFilter.NONE) {
                // once repaired, the tokens usually read without error: the direct parser takes them in a fraction
                // of a parse with a tree; where it declines, the attempt below decides as before
                ReaderDiagnostics scratch = new ReaderDiagnostics(sourceName);
                Optional<Program> direct = DirectParser.program(sourceName, new ListTokenSource(current), options,
                        scratch);
                if (direct.isPresent() && !scratch.hasErrors()) {
                    scratch.warnings().forEach(warningsTo::keepWarning);
                    return direct;
                }
            }
            if (attempt == 0) {
                // the tokens as read had a syntax error, so this attempt stops at it: found without a tree or a model
                // (the repair depends only on the parser's state there); should it parse to the end, the attempt below
                // is made as before
                Optional<Repair> first = firstRepair(current);
                if (first.isPresent()) {
                    Repair r = first.get();
                    if (r.index >= current.size()) {
                        return Optional.empty();
                    }
                    lowestNext = apply(r, current);
                    continue;
                }
            }
            CommonTokenStream stream = new CommonTokenStream(new ListTokenSource(current));
            FclParser parser = new FclParser(stream);
            parser.removeErrorListeners();
            parser.getInterpreter().setPredictionMode(PredictionMode.LL);
            parser.setErrorHandler(new FindRepair());
            // each attempt stops at its first mismatch, so what it completes is whole: built at once (see StrictReader)
            ReaderDiagnostics scratch = new ReaderDiagnostics(sourceName);
            ModelBuilder builder = new ModelBuilder(sourceName, scratch, options);
            builder.buildWhile(parser, () -> true);
            FclParser.ProgramContext tree;
            try {
                tree = parser.program();
            } catch (Repair r) {
                if (r.index < lowestNext || r.index >= current.size()) {
                    return Optional.empty();    // no progress: the text is not repairable token by token
                }
                lowestNext = apply(r, current);
                continue;
            } catch (ParseCancellationException | RecognitionException e) {
                return Optional.empty();
            }
            Program program = builder.program(tree);
            if (scratch.hasErrors()) {
                return Optional.empty();
            }
            scratch.warnings().forEach(warningsTo::keepWarning);
            return Optional.of(program);
        }
        return Optional.empty();
    }

    /**
     * The repair of the first mismatch of the tokens, parsed as each attempt parses them but without building the parse
     * tree or the model; empty when they parse to the end, or when the mismatch has no one-token repair is also
     * answered by the attempt (which then fails the same way).
     */
    private static Optional<Repair> firstRepair(List<Token> tokens) {
        FclParser parser = new FclParser(new CommonTokenStream(new ListTokenSource(tokens)));
        parser.removeErrorListeners();
        parser.getInterpreter().setPredictionMode(PredictionMode.LL);
        parser.setErrorHandler(new FindRepair());
        parser.setBuildParseTree(false);
        try {
            parser.program();
        } catch (Repair r) {
            return Optional.of(r);
        } catch (ParseCancellationException | RecognitionException e) {
            return Optional.empty();
        }
        return Optional.empty();
    }

    /** A token of the given type placed just after the default-channel token before {@code index}. */
    /** Applies one repair to the tokens; the first index a later repair may touch (no going back: progress). */
    private static int apply(Repair r, List<Token> tokens) {
        if (r.insert == 0) {
            tokens.remove(r.index);
            return r.index;
        }
        tokens.add(r.index, conjured(r.insert, tokens, r.index));
        return r.index + 1;
    }

    private static Token conjured(int type, List<Token> tokens, int index) {
        String literal = FclParser.VOCABULARY.getLiteralName(type);
        CommonToken t = new CommonToken(type, literal.substring(1, literal.length() - 1));
        Token before = null;
        for (int i = index - 1; i >= 0 && before == null; i--) {
            if (tokens.get(i).getChannel() == Token.DEFAULT_CHANNEL) {
                before = tokens.get(i);
            }
        }
        Token at = before != null ? before : tokens.get(index);
        t.setLine(at.getLine());
        t.setCharPositionInLine(at.getCharPositionInLine() + (before != null ? before.getText().length() : 0));
        return t;
    }

    /** The first error found, as a repair: insert a token of type {@code insert}, or (0) delete the token. */
    private static final class Repair extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final transient int index;
        final transient int insert;

        Repair(int index, int insert) {
            super(null, null, false, false);
            this.index = index;
            this.insert = insert;
        }
    }

    /** Stops at the first mismatch and names the one-token repair for it, if there is one. */
    private static final class FindRepair extends DefaultErrorStrategy {
        private static final int[] PUNCTUATION = {FclLexer.SEMI, FclLexer.ASSIGN, FclLexer.COLON, FclLexer.COMMA,
            FclLexer.RPAREN, FclLexer.LPAREN, FclLexer.DOTDOT};

        @Override
        public void sync(Parser recognizer) {
            // no recovery in loops: a mismatch surfaces at the token match or the prediction
        }

        @Override
        public Token recoverInline(Parser recognizer) {
            Token current = recognizer.getCurrentToken();
            IntervalSet expected = recognizer.getExpectedTokens();
            int missing = missingPunctuation(expected);
            if (missing != 0 && singleTokenInsertion(recognizer)) {
                throw new Repair(current.getTokenIndex(), missing);
            }
            if (current.getType() != Token.EOF && expected.contains(recognizer.getInputStream().LA(2))) {
                throw new Repair(current.getTokenIndex(), 0);
            }
            throw new ParseCancellationException("not repairable by one token");
        }

        @Override
        public void recover(Parser recognizer, RecognitionException e) {
            throw new ParseCancellationException(e);
        }

        @Override
        public void reportError(Parser recognizer, RecognitionException e) {
            // the first reading reported everything
        }

        @Override
        protected void reportMissingToken(Parser recognizer) {
            // only asked whether insertion would fit
        }

        /** ';' when it may stand here, else the one punctuation token expected; 0 when none fits. */
        private static int missingPunctuation(IntervalSet expected) {
            if (expected.contains(FclLexer.SEMI)) {
                return FclLexer.SEMI;
            }
            if (expected.size() == 1) {
                for (int p : PUNCTUATION) {
                    if (expected.contains(p)) {
                        return p;
                    }
                }
            }
            return 0;
        }
    }
}
