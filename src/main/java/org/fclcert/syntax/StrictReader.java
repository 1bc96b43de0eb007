package org.fclcert.syntax;

import java.util.List;
import java.util.Optional;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.ListTokenSource;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.ParseCancellationException;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.SourceLocation;

/**
 * The reader for FCL exactly as IEC 61131-7 defines it (5.4 plus the IEC 61131-3 pieces it uses).
 *
 * <p>A text without errors, written as 5.4 writes FCL, is read by the {@link DirectParser} straight into the
 * model. A text it declines goes through the stages: lex; pre-scan the tokens (lexical mistakes, nesting
 * depth, the Annex D errata); parse, first with the fast SLL prediction and, only if that fails, again with
 * full LL and error recovery (straight with LL where the direct parser declined at a syntax error, a rule
 * without its ';', where SLL could only fail); report keywords used as names; build the model. Every mistake
 * becomes a located diagnostic; the reader never throws and never prints. Thread-safe: it keeps no state between calls.
 */
public final class StrictReader implements FclReader {
    /**
     * Parentheses nested at most this deep are parsed on the caller's thread. Deeper nesting (up to
     * Limits.MAX_NESTING_DEPTH) is parsed on a thread with a large stack: the recursive-descent parser
     * and the builder use a few stack frames per level, and a caller's thread may have a small stack.
     */
    static final int SHALLOW_NESTING = 50;
    private static final long DEEP_STACK_BYTES = 64L << 20;
    /** Texts up to this many characters keep their token objects (a few MB at most), not the compact form. */
    private static final int SMALL_TEXT = 1 << 16;

    private final ReaderOptions options;
    /**
     * Whether a text, and after a syntax error its repaired tokens, are first tried by the {@link DirectParser}
     * (off only to compare the two paths in tests).
     */
    private final boolean directPath;

    /** The reader of the standard exactly. */
    public StrictReader() {
        this(ReaderOptions.STRICT);
    }

    /** The strict pipeline with the given changes (dialect readers, the Open Level reading of the corpus). */
    public StrictReader(ReaderOptions options) {
        this(options, true);
    }

    StrictReader(ReaderOptions options, boolean directPath) {
        this.options = java.util.Objects.requireNonNull(options, "options");
        this.directPath = directPath;
    }

    /** Standard FCL plus the Open Level methods that fit its syntax ({@link ReaderOptions#OPEN_LEVEL}). */
    public static StrictReader openLevel() {
        return new StrictReader(ReaderOptions.OPEN_LEVEL);
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        if (sourceName == null) {
            sourceName = "<input>";
        }
        ReaderDiagnostics diagnostics = new ReaderDiagnostics(sourceName);
        try {
            Outcome outcome = readProgram(sourceName, text, diagnostics, options, directPath);
            String body = text.startsWith("\uFEFF") ? text.substring(1) : text;
            Optional<Program> program = diagnostics.hasErrors() ? Optional.empty()
                    : outcome.program().map(p -> outcome.aroundComments() != null
                            ? CommentPlaces.attach(p, body, outcome.aroundComments()) : CommentPlaces.attach(p, body));
            return new ReadResult(program, diagnostics.finish(), outcome.repaired());
        } catch (RuntimeException | StackOverflowError e) {
            // A bug in fclcert, not in the program: still a diagnostic, never a stack trace.
            List<Diagnostic> list = List.of(Diagnostic.error(SourceLocation.of(sourceName, 1, 1),
                    SyntaxCode.INTERNAL_ERROR, "internal error of the FCL reader (" + e.getClass().getSimpleName()
                            + (e.getMessage() == null ? "" : ": " + e.getMessage()) + "); please report this"));
            return new ReadResult(Optional.empty(), list);
        }
    }

    /** The program read, and after syntax errors the program of the repaired text ({@link SyntaxRepair}). */
    private record Outcome(Optional<Program> program, Optional<Program> repaired, List<Token> aroundComments) {
        static final Outcome NONE = new Outcome(Optional.empty(), Optional.empty());

        Outcome(Optional<Program> program, Optional<Program> repaired) {
            this(program, repaired, null);
        }
    }

    private static Outcome readProgram(String sourceName, String text, ReaderDiagnostics diagnostics,
            ReaderOptions options, boolean directPath) {
        // a byte order mark is an encoding artefact, not text: columns on line 1 count without it
        String body = text.startsWith("\uFEFF") ? text.substring(1) : text;
        DirectParser.Read direct = null;
        if (directPath && options.tokenFilter() == ReaderOptions.TokenFilter.NONE) {
            // most texts have no error: read those without a parse tree, the rest as below
            ReaderDiagnostics.Mark mark = diagnostics.mark();
            // its tokens around the comments are kept, so that placing the comments needs no second lexing
            direct = DirectParser.read(sourceName, body, options, diagnostics);
            if (!direct.declined()) {
                return new Outcome(Optional.of(direct.program()), Optional.empty(), direct.aroundComments());
            }
            diagnostics.rollback(mark);
        }
        // where the direct parser declined at a syntax error (a rule's ';' missing), ANTLR's SLL pass could only fail
        boolean sll = direct == null || !direct.surelyInvalid();
        // Fcl.g4's lexer rules, hand-written (FclTokenSource): the same tokens, several times faster
        FclTokenSource lexer = new FclTokenSource(body, sourceName);
        TokenSource source = lexer;
        // the compact table pays off for large texts (issue 18); a small text's tokens are kept as the lexer
        // made them, rather than made a second time when the parser asks for them
        // (FCL averages five or more characters a token: the corpus's densest files have five)
        TokenTable table = body.length() <= SMALL_TEXT ? TokenTable.keepingTokens(body.length() / 5 + 16)
                : new TokenTable();
        if (options.tokenFilter() != ReaderOptions.TokenFilter.NONE) {
            List<Token> lexed = new java.util.ArrayList<>();
            Token t;
            do {
                t = lexer.nextToken();
                lexed.add(t);
            } while (t.getType() != Token.EOF);
            source = new ListTokenSource(options.tokenFilter().filter(lexed, diagnostics.asReport()));
            table = TokenTable.keepingTokens();   // a dialect's filter may make up tokens: keep them as made
        }
        TokenPreScan.Result scan = TokenPreScan.scan(source, diagnostics, table);
        if (scan.tooDeep() || diagnostics.tooMany()) {
            return Outcome.NONE;    // never hand the recursive parser a nesting it may not survive
        }
        if (scan.maxDepth() <= SHALLOW_NESTING) {
            return parseAndBuild(sourceName, scan, diagnostics, options, directPath, sll);
        }
        return onDeepStack(() -> parseAndBuild(sourceName, scan, diagnostics, options, directPath, sll));
    }

    private static Outcome parseAndBuild(String sourceName, TokenPreScan.Result scan,
            ReaderDiagnostics diagnostics, ReaderOptions options, boolean directPath, boolean sll) {
        ReservedNames reservedNames = new ReservedNames();
        ModelBuilder builder = new ModelBuilder(sourceName, diagnostics, options);
        Parsed parsed = parse(scan.tokens(), diagnostics, reservedNames, builder, sll);
        reservedNames.report(diagnostics);
        if (parsed.tree() == null) {
            return Outcome.NONE;    // stopped after too many errors
        }
        if (!parsed.complete()) {
            // the builder needs a tree without gaps: the semantic checks get the repaired text's, if any
            // its warnings (W1nn) stay reported alongside the errors: they hold of the text the reader recovered
            return new Outcome(Optional.empty(), SyntaxRepair.program(sourceName, parsed.tokens(), options,
                    diagnostics, directPath));
        }
        // lexical mistakes were repaired in the tokens, so the tree is whole: build to find the rest
        Program program = builder.program(parsed.tree());
        return new Outcome(diagnostics.hasErrors() ? Optional.empty() : Optional.of(program), Optional.empty());
    }

    /** The tree, whether it is whole, and after a syntax error every token (which the repair needs). */
    private record Parsed(FclParser.ProgramContext tree, boolean complete, List<Token> tokens) {
    }

    /** Runs the task on a fresh thread with a large stack and returns its result on this thread. */
    private static <T> T onDeepStack(java.util.function.Supplier<T> task) {
        Object[] outcome = new Object[1];
        Thread worker = new Thread(null, () -> {
            try {
                outcome[0] = task.get();
            } catch (Throwable e) {   // handed to the caller's thread, never printed by this one
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
        if (outcome[0] instanceof Error e) {
            throw e;   // a StackOverflowError becomes FCL-S999 in read(); an OutOfMemoryError stays one
        }
        @SuppressWarnings("unchecked")
        T result = (T) outcome[0];
        return result;
    }

    /**
     * SLL first (fast, correct for valid input); on a syntax error, full LL with recovery and messages. Without
     * {@code sll} (the direct parser found a syntax error), only the second: the first pass would fail and its
     * diagnostics and early-built parts be taken back, so the outcome is the same.
     */
    private static Parsed parse(TokenTable table, ReaderDiagnostics diagnostics, ReservedNames reservedNames,
            ModelBuilder builder, boolean sll) {
        if (sll) {
            FclParser parser = new FclParser(new TableTokenStream(table));
            parser.removeErrorListeners();
            parser.keywordName = reservedNames;
            parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
            parser.setErrorHandler(new BailErrorStrategy());
            // this pass stops at the first error, so every rule, item and declaration it completes is whole:
            // build each at once and drop its subtree, so that a large program's trees are never all held
            builder.buildWhile(parser, () -> true);
            ReaderDiagnostics.Mark mark = diagnostics.mark();
            try {
                return new Parsed(parser.program(), true, List.of());
            } catch (ParseCancellationException e) {
                diagnostics.rollback(mark);   // the second pass reports everything again
                builder.forgetEarly();        // what the first pass built belongs to its abandoned tree
                reservedNames.reset();
            }
        }
        List<Token> tokens = table.toList();
        FclParser parser = new FclParser(new CommonTokenStream(new ListTokenSource(tokens)));
        parser.removeErrorListeners();
        parser.keywordName = reservedNames;
        parser.getInterpreter().setPredictionMode(PredictionMode.LL);
        FclErrorStrategy strategy = new FclErrorStrategy(diagnostics, tokens);
        parser.setErrorHandler(strategy);
        // what this pass completes before its first recovery is whole too (a large program with a
        // mistake near its end then holds little more tree than one without)
        builder.buildWhile(parser, () -> !strategy.recovered());
        try {
            FclParser.ProgramContext tree = parser.program();
            return new Parsed(tree, !strategy.recovered(), tokens);
        } catch (FclErrorStrategy.StopReading stop) {
            return new Parsed(null, false, tokens);
        }
    }
}
