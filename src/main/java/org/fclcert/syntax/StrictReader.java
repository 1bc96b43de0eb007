package org.fclcert.syntax;

import java.util.List;
import java.util.Optional;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.ListTokenSource;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.ParseCancellationException;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.SourceLocation;

/**
 * The reader for FCL exactly as IEC 61131-7 defines it (5.4 plus the IEC 61131-3 pieces it uses).
 *
 * <p>Stages: lex; pre-scan the tokens (lexical mistakes, nesting depth, the Annex D errata); parse,
 * first with the fast SLL prediction and, only if that fails, again with full LL and error recovery;
 * report keywords used as names; build the model. Every mistake becomes a located diagnostic; the
 * reader never throws and never prints. Thread-safe: it keeps no state between calls.
 */
public final class StrictReader implements FclReader {
    /**
     * Parentheses nested at most this deep are parsed on the caller's thread. Deeper nesting (up to
     * Limits.MAX_NESTING_DEPTH) is parsed on a thread with a large stack: the recursive-descent parser
     * and the builder use a few stack frames per level, and a caller's thread may have a small stack.
     */
    private static final int SHALLOW_NESTING = 50;
    private static final long DEEP_STACK_BYTES = 64L << 20;

    @Override
    public ReadResult read(String sourceName, String text) {
        ReaderDiagnostics diagnostics = new ReaderDiagnostics(sourceName);
        try {
            Optional<Program> program = readProgram(sourceName, text, diagnostics);
            return new ReadResult(diagnostics.hasErrors() ? Optional.empty() : program, diagnostics.finish());
        } catch (RuntimeException | StackOverflowError e) {
            // A bug in fclcert, not in the program: still a diagnostic, never a stack trace.
            List<Diagnostic> list = List.of(Diagnostic.error(SourceLocation.of(sourceName, 1, 1),
                    SyntaxCode.INTERNAL_ERROR.code(), "internal error of the FCL reader (" + e.getClass().getSimpleName()
                            + (e.getMessage() == null ? "" : ": " + e.getMessage()) + "); please report this"));
            return new ReadResult(Optional.empty(), list);
        }
    }

    private static Optional<Program> readProgram(String sourceName, String text, ReaderDiagnostics diagnostics) {
        FclLexer lexer = new FclLexer(CharStreams.fromString(text, sourceName));
        lexer.removeErrorListeners();   // the lexer cannot fail: unknown characters are ANY tokens
        TokenPreScan.Result scan = TokenPreScan.scan(lexer, diagnostics);
        if (scan.tooDeep() || diagnostics.tooMany()) {
            return Optional.empty();    // never hand the recursive parser a nesting it may not survive
        }
        if (scan.maxDepth() <= SHALLOW_NESTING) {
            return parseAndBuild(sourceName, scan, diagnostics);
        }
        return onDeepStack(() -> parseAndBuild(sourceName, scan, diagnostics));
    }

    private static Optional<Program> parseAndBuild(String sourceName, TokenPreScan.Result scan,
            ReaderDiagnostics diagnostics) {
        Parsed parsed = parse(scan.tokens(), diagnostics);
        if (parsed.tree() == null) {
            return Optional.empty();    // stopped after too many errors
        }
        ReservedNames.check(parsed.tree(), diagnostics);
        if (!parsed.complete()) {
            return Optional.empty();    // the builder needs a tree without gaps
        }
        // lexical mistakes were repaired in the tokens, so the tree is whole: build to find the rest
        Program program = new ModelBuilder(sourceName, diagnostics).program(parsed.tree());
        return diagnostics.hasErrors() ? Optional.empty() : Optional.of(program);
    }

    private record Parsed(FclParser.ProgramContext tree, boolean complete) {
    }

    /** Runs the task on a fresh thread with a large stack and returns its result on this thread. */
    private static Optional<Program> onDeepStack(java.util.function.Supplier<Optional<Program>> task) {
        Object[] outcome = new Object[1];
        Thread worker = new Thread(null, () -> {
            try {
                outcome[0] = task.get();
            } catch (RuntimeException | StackOverflowError e) {
                outcome[0] = e;
            }
        }, "fclcert-reader", DEEP_STACK_BYTES);
        worker.start();
        boolean interrupted = false;
        while (true) {
            try {
                worker.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;   // finish the read (it is bounded), then restore the flag
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (outcome[0] instanceof RuntimeException e) {
            throw e;
        }
        if (outcome[0] instanceof StackOverflowError e) {
            throw e;
        }
        @SuppressWarnings("unchecked")
        Optional<Program> program = (Optional<Program>) outcome[0];
        return program;
    }

    /** SLL first (fast, correct for valid input); on a syntax error, full LL with recovery and messages. */
    private static Parsed parse(List<Token> tokens, ReaderDiagnostics diagnostics) {
        CommonTokenStream stream = new CommonTokenStream(new ListTokenSource(tokens));
        FclParser parser = new FclParser(stream);
        parser.removeErrorListeners();
        parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
        parser.setErrorHandler(new BailErrorStrategy());
        try {
            return new Parsed(parser.program(), true);
        } catch (ParseCancellationException e) {
            stream.seek(0);
            parser.reset();
            parser.getInterpreter().setPredictionMode(PredictionMode.LL);
            FclErrorStrategy strategy = new FclErrorStrategy(diagnostics, tokens);
            parser.setErrorHandler(strategy);
            try {
                FclParser.ProgramContext tree = parser.program();
                return new Parsed(tree, !strategy.foundErrors());
            } catch (FclErrorStrategy.StopReading stop) {
                return new Parsed(null, false);
            }
        }
    }
}
