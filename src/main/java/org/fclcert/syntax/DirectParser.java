package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.BiFunction;
import java.util.function.Supplier;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.misc.Interval;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.OptionsBlock;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * The strict reader's fast path: reads a text without errors straight from the lexer's tokens into the model,
 * with no parse tree. It takes a subset of Fcl.g4's language, FCL as the 5.4 production writes it (5.4's order
 * of items, no keyword as a name, no setting given twice, only the types, algorithms and methods the options
 * allow, rule numbers written plainly, no lexical mistake) plus the three draft forms common in real files,
 * {@code RANGE := (...)}, RANGE after the other DEFUZZIFY items and WITH after the last of several
 * subconclusions, which it warns of exactly as {@link ModelBuilder} does, through the same methods. At the
 * first token where the full pipeline (pre-scan, ANTLR parser, model builder) would say anything else, it
 * declines; the reader takes back its warnings and reads the text again that way, which gives every diagnostic.
 *
 * <p>So the grammar stays the one description of the language, and this is a shortcut through it: what this
 * reads, the full pipeline reads without errors, into an equal model and with the same warnings.
 * {@code DirectParserTest} holds the two together on the corpus, random programs and token-level mutations
 * of both. The leaves (literals, algorithm and method names) are built by the model builder's own code.
 */
final class DirectParser {
    /** Thrown to give up; preallocated and without a stack trace, since declining is a normal outcome. */
    private static final class Decline extends RuntimeException {
        private static final Decline INSTANCE = new Decline();

        private Decline() {
            super("declined", null, false, false);
        }
    }

    private final TokenSource lexer;
    private final String sourceName;
    private final ReaderOptions options;
    private final ReaderDiagnostics diagnostics;
    /** The current token (comments are skipped, after the pre-scan's check of them). */
    private Token t;
    private int type;
    /**
     * Set just before declining where the text is surely not in Fcl.g4's language: a rule whose conclusion is
     * followed by RULE or END_RULEBLOCK, not by its ';'.
     */
    private boolean surelyInvalid;
    /** Parenthesis depth exactly as {@link TokenPreScan} counts it (reset at ';' outside OPTIONS). */
    private int depth;
    private boolean inOptions;

    private DirectParser(TokenSource lexer, String sourceName, ReaderOptions options, ReaderDiagnostics diagnostics) {
        this.lexer = lexer;
        this.sourceName = sourceName;
        this.options = options;
        this.diagnostics = diagnostics;
    }

    /**
     * The program, when the text is in the subset this reads, with its warnings reported; empty when it
     * declines, when some warnings may have been reported (the caller takes them back). {@code body} is the
     * text without a byte order mark.
     */
    static Optional<Program> program(String sourceName, String body, ReaderOptions options,
            ReaderDiagnostics diagnostics) {
        return program(sourceName, new FclTokenSource(body, sourceName), options, diagnostics);
    }

    /**
     * What {@link #read} gives: a program read from a text, with the tokens {@link CommentPlaces} needs to place its
     * comments; or, when it declined ({@code program} null), whether it declined where Fcl.g4 has no way on either
     * ({@link #surelyInvalid}), so that the text has a syntax error and ANTLR's fast SLL pass would only fail.
     */
    record Read(Program program, List<Token> aroundComments, boolean surelyInvalid) {
        static final Read DECLINED = new Read(null, null, false);
        static final Read INVALID = new Read(null, null, true);

        boolean declined() {
            return program == null;
        }
    }

    /**
     * {@link #program(String, String, ReaderOptions, ReaderDiagnostics)}, keeping the tokens around the text's
     * comments as they pass, so that the comments are placed without lexing the text again.
     */
    static Read read(String sourceName, String body, ReaderOptions options, ReaderDiagnostics diagnostics) {
        DirectParser parser = new DirectParser(new FclTokenSource(body, sourceName), sourceName, options,
                diagnostics);
        try {
            parser.aroundComments = new ArrayList<>();
            return new Read(parser.program(), parser.aroundComments, false);
        } catch (RuntimeException declinedOrUnforeseen) {
            // as program(...) below; only a decline marked as such says more
            return declinedOrUnforeseen == Decline.INSTANCE && parser.surelyInvalid ? Read.INVALID : Read.DECLINED;
        }
    }

    /**
     * The same from tokens already made, as Fcl.g4's lexer makes them (comments included, white space not), ending
     * with EOF: the one-token repair's repaired tokens ({@link SyntaxRepair}), read without a parse tree.
     */
    static Optional<Program> program(String sourceName, TokenSource tokens, ReaderOptions options,
            ReaderDiagnostics diagnostics) {
        try {
            return Optional.of(new DirectParser(tokens, sourceName, options, diagnostics).program());
        } catch (RuntimeException declinedOrUnforeseen) {
            // Decline, or something this shortcut did not foresee: either way the full pipeline decides
            return Optional.empty();
        }
    }

    // ---------------------------------------------------------------- tokens

    /**
     * When asked for ({@link #read}): every comment, the token before and the token after each, every token of
     * OPTIONS and END_OPTIONS (which tell a comment inside an OPTIONS block) and EOF, in order: what
     * {@link CommentPlaces} looks at when it walks all the tokens.
     */
    private List<Token> aroundComments;
    /** The last token that is no comment, and whether a comment came after it. */
    private Token lastToken;
    private boolean commentSince;

    /** Keeps {@link #t} in {@link #aroundComments} where CommentPlaces needs it. */
    private void keep() {
        if (type == FclLexer.COMMENT) {
            if (lastToken != null && !commentSince
                    && (aroundComments.isEmpty() || aroundComments.get(aroundComments.size() - 1) != lastToken)) {
                aroundComments.add(lastToken);
            }
            aroundComments.add(t);
            commentSince = true;
            return;
        }
        if (commentSince || type == Token.EOF || CommentPlaces.changesOptions(type)) {
            aroundComments.add(t);
        }
        commentSince = false;
        lastToken = t;
    }

    private void next() {
        while (true) {
            t = lexer.nextToken();
            type = t.getType();
            if (aroundComments != null) {
                keep();
            }
            if (type != FclLexer.COMMENT) {
                break;
            }
            // TokenPreScan reports an unterminated comment and warns of '(*' inside one
            String text = t.getText();
            if (TokenPreScan.unterminated(text) || TokenPreScan.opensInside(text)) {
                throw Decline.INSTANCE;
            }
        }
        switch (type) {
            case FclLexer.LPAREN -> {
                // the deep-nesting path (its own thread stack, the nesting limit) is the full pipeline's
                if (++depth > StrictReader.SHALLOW_NESTING) {
                    throw Decline.INSTANCE;
                }
            }
            case FclLexer.RPAREN -> depth = Math.max(0, depth - 1);
            case FclLexer.SEMI -> depth = inOptions ? depth : 0;
            default -> {
            }
        }
    }

    /** The current token, which must be of this type; then moves on. */
    private Token take(int expected) {
        if (type != expected) {
            throw Decline.INSTANCE;
        }
        Token taken = t;
        next();
        return taken;
    }

    private void skip(int expected) {
        take(expected);
    }

    private SourceLocation at(Token token) {
        return ReaderDiagnostics.location(sourceName, token);
    }

    /** A name: an identifier (a keyword there is the full pipeline's FCL-S reserved-keyword error). */
    private Token nameToken() {
        return take(FclLexer.IDENT);
    }

    private String name() {
        return nameToken().getText();
    }

    /** A word where the grammar takes an identifier or a soft keyword (types, algorithms, methods). */
    private String word() {
        if (type != FclLexer.IDENT && !Keywords.isSoft(type)) {
            throw Decline.INSTANCE;
        }
        String text = t.getText();
        next();
        return text;
    }

    // ---------------------------------------------------------------- structure

    private Program program() {
        next();
        List<FunctionBlock> blocks = new ArrayList<>();
        while (type == FclLexer.FUNCTION_BLOCK) {
            blocks.add(functionBlock());
        }
        if (type != Token.EOF || blocks.isEmpty()) {
            throw Decline.INSTANCE;
        }
        return new Program(sourceName, blocks);
    }

    /** The rank of an item in 5.4's order; an item of a lower rank than one before it is declined. */
    private static int ordered(int highest, int rank) {
        if (rank < highest) {
            throw Decline.INSTANCE;
        }
        return rank;
    }

    private FunctionBlock functionBlock() {
        Token start = take(FclLexer.FUNCTION_BLOCK);
        String name = name();
        List<Variable> variables = new ArrayList<>();
        List<Fuzzification> fuzzifications = new ArrayList<>();
        List<Defuzzification> defuzzifications = new ArrayList<>();
        List<RuleBlock> ruleBlocks = new ArrayList<>();
        List<OptionsBlock> optionsBlocks = new ArrayList<>();
        int rank = 0;
        while (type != FclLexer.END_FUNCTION_BLOCK) {
            switch (type) {
                case FclLexer.VAR_INPUT, FclLexer.VAR_OUTPUT -> {
                    rank = ordered(rank, 0);
                    varSection(variables);
                }
                case FclLexer.VAR -> {
                    rank = ordered(rank, 1);
                    varSection(variables);
                }
                case FclLexer.FUZZIFY -> {
                    rank = ordered(rank, 2);
                    fuzzifications.add(fuzzification());
                }
                case FclLexer.DEFUZZIFY -> {
                    rank = ordered(rank, 3);
                    defuzzifications.add(defuzzification());
                }
                case FclLexer.RULEBLOCK -> {
                    rank = ordered(rank, 4);
                    ruleBlocks.add(ruleBlock());
                }
                case FclLexer.OPTIONS -> {
                    rank = ordered(rank, 5);
                    optionsBlocks.add(optionsBlock());
                }
                default -> throw Decline.INSTANCE;
            }
        }
        next();
        return new FunctionBlock(name, variables, fuzzifications, defuzzifications, ruleBlocks, optionsBlocks,
                at(start));
    }

    private void varSection(List<Variable> into) {
        VariableKind kind = switch (type) {
            case FclLexer.VAR_INPUT -> VariableKind.INPUT;
            case FclLexer.VAR_OUTPUT -> VariableKind.OUTPUT;
            default -> VariableKind.LOCAL;
        };
        next();
        while (type != FclLexer.END_VAR) {
            declaration(kind, into);
        }
        next();
    }

    private void declaration(VariableKind kind, List<Variable> into) {
        List<Token> names = new ArrayList<>(2);
        names.add(nameToken());
        while (type == FclLexer.COMMA) {
            next();
            names.add(nameToken());
        }
        skip(FclLexer.COLON);
        DataType dataType = DataType.byKeyword(word()).orElseThrow(() -> Decline.INSTANCE);
        Optional<Literal> initial = Optional.empty();
        if (type == FclLexer.ASSIGN) {
            next();
            initial = Optional.of(literal());
        }
        skip(FclLexer.SEMI);
        for (Token n : names) {
            into.add(new Variable(n.getText(), kind, dataType, initial, at(n)));
        }
    }

    private Fuzzification fuzzification() {
        Token start = take(FclLexer.FUZZIFY);
        String name = name();
        List<Term> terms = new ArrayList<>();
        while (type == FclLexer.TERM) {
            terms.add(term());
        }
        skip(FclLexer.END_FUZZIFY);
        return new Fuzzification(name, terms, at(start));
    }

    private Term term() {
        Token start = take(FclLexer.TERM);
        String name = name();
        skip(FclLexer.ASSIGN);
        MembershipFunction function;
        if (type == FclLexer.LPAREN) {
            List<Point> points = new ArrayList<>();
            points.add(point());
            while (type == FclLexer.LPAREN || type == FclLexer.COMMA) {
                if (type == FclLexer.COMMA) {
                    next();
                }
                points.add(point());
            }
            function = new MembershipFunction.Points(points);
        } else {
            function = new MembershipFunction.Singleton(operand());
        }
        skip(FclLexer.SEMI);
        return new Term(name, function, at(start));
    }

    private Point point() {
        Token start = take(FclLexer.LPAREN);
        Operand x = operand();
        skip(FclLexer.COMMA);
        Operand y = operand();
        skip(FclLexer.RPAREN);
        return new Point(x, y, at(start));
    }

    private Defuzzification defuzzification() {
        Token start = take(FclLexer.DEFUZZIFY);
        String name = name();
        Optional<Range> range = Optional.empty();
        List<Term> terms = new ArrayList<>();
        Optional<Located<DefuzzificationMethod>> method = Optional.empty();
        Optional<DefaultValue> defaultValue = Optional.empty();
        int rank = 0;
        while (type != FclLexer.END_DEFUZZIFY) {
            switch (type) {
                case FclLexer.RANGE -> {
                    Token rangeStart = t;
                    range = Optional.of(range(range));
                    if (rank > 0) {
                        // after the other items: the draft's order when it is the block's last item
                        if (type != FclLexer.END_DEFUZZIFY) {
                            throw Decline.INSTANCE;
                        }
                        ModelBuilder.rangeLast(rangeStart, diagnostics, options);
                    }
                }
                case FclLexer.TERM -> {
                    rank = ordered(rank, 1);
                    terms.add(term());
                }
                case FclLexer.METHOD -> {
                    rank = ordered(rank, 2);
                    method = Optional.of(method(method));
                }
                case FclLexer.DEFAULT -> {
                    rank = ordered(rank, 3);
                    defaultValue = Optional.of(defaultValue(defaultValue));
                }
                default -> throw Decline.INSTANCE;   // END_FUZZIFY here is the draft's spelling
            }
        }
        next();
        return new Defuzzification(name, range, terms, method, defaultValue, at(start));
    }

    /** A setting given a second time is the full pipeline's FCL-S error. */
    private static void once(Optional<?> previous) {
        if (previous.isPresent()) {
            throw Decline.INSTANCE;
        }
    }

    private Range range(Optional<Range> previous) {
        once(previous);
        Token start = take(FclLexer.RANGE);
        if (type == FclLexer.ASSIGN) {
            ModelBuilder.rangeAssignment(t, diagnostics, options);
            next();
        }
        skip(FclLexer.LPAREN);
        Literal min = literal();
        skip(FclLexer.DOTDOT);
        Literal max = literal();
        skip(FclLexer.RPAREN);
        skip(FclLexer.SEMI);
        return new Range(min, max, at(start));
    }

    private Located<DefuzzificationMethod> method(Optional<?> previous) {
        once(previous);
        Token start = take(FclLexer.METHOD);
        skip(FclLexer.COLON);
        DefuzzificationMethod method = ModelBuilder.method(word(), options).orElseThrow(() -> Decline.INSTANCE);
        skip(FclLexer.SEMI);
        return new Located<>(method, at(start));
    }

    private DefaultValue defaultValue(Optional<?> previous) {
        once(previous);
        Token start = take(FclLexer.DEFAULT);
        skip(FclLexer.ASSIGN);
        DefaultValue value;
        if (type == FclLexer.NC) {
            next();
            value = new DefaultValue.NoChange(at(start));
        } else {
            value = new DefaultValue.Constant(literal(), at(start));
        }
        skip(FclLexer.SEMI);
        return value;
    }

    private RuleBlock ruleBlock() {
        Token start = take(FclLexer.RULEBLOCK);
        String name = name();
        Optional<Located<AndAlgorithm>> and = Optional.empty();
        Optional<Located<OrAlgorithm>> or = Optional.empty();
        Optional<Located<ActivationMethod>> act = Optional.empty();
        Optional<Located<AccumulationMethod>> accu = Optional.empty();
        List<Rule> rules = new ArrayList<>();
        int rank = 0;
        while (type != FclLexer.END_RULEBLOCK) {
            switch (type) {
                case FclLexer.AND -> {
                    rank = ordered(rank, 0);
                    and = setting(and, AndAlgorithm.class);
                }
                case FclLexer.OR -> {
                    rank = ordered(rank, 0);
                    or = setting(or, OrAlgorithm.class);
                }
                case FclLexer.ACT -> {
                    rank = ordered(rank, 1);
                    act = setting(act, ActivationMethod.class);
                }
                case FclLexer.ACCU -> {
                    rank = ordered(rank, 2);
                    accu = setting(accu, AccumulationMethod.class);
                }
                case FclLexer.RULE -> {
                    rank = ordered(rank, 3);
                    rules.add(rule());
                }
                default -> throw Decline.INSTANCE;
            }
        }
        next();
        return new RuleBlock(name, and, or, act, accu, rules, at(start));
    }

    /** {@code AND : MIN;}, {@code ACT : PROD;} and the like, given once, naming a standard algorithm. */
    private <E extends Enum<E>> Optional<Located<E>> setting(Optional<Located<E>> previous, Class<E> kind) {
        once(previous);
        Token start = t;
        next();
        skip(FclLexer.COLON);
        E value = ModelBuilder.standardAlgorithm(kind, word()).orElseThrow(() -> Decline.INSTANCE);
        skip(FclLexer.SEMI);
        return Optional.of(new Located<>(value, at(start)));
    }

    private Rule rule() {
        Token start = take(FclLexer.RULE);
        // a rule number with a sign, digit separators or leading zeros, or a rule named by an identifier,
        // gets a diagnostic from the full pipeline
        if (type != FclLexer.INTEGER || !ModelBuilder.plainNumber(t.getText())) {
            throw Decline.INSTANCE;
        }
        String name = t.getText();
        next();
        skip(FclLexer.COLON);
        skip(FclLexer.IF);
        Condition condition = condition();
        skip(FclLexer.THEN);
        List<Subconclusion> conclusion = conclusion();
        if (type != FclLexer.SEMI) {
            // Fcl.g4's fuzzyRule ends 'THEN conclusion SEMI', and a conclusion read up to here can go on only with
            // ',', IS, WITH or a name or number after WITH (which conclusion() would have taken): RULE and
            // END_RULEBLOCK, keywords that are never names, leave the grammar no way on, so the text has a syntax
            // error whatever follows. (This parser takes a subset of the grammar, token by token the same way, and
            // sees the tokens the pre-scan would hand the grammar: it declines at any token the pre-scan changes.)
            surelyInvalid = type == FclLexer.RULE || type == FclLexer.END_RULEBLOCK;
            throw Decline.INSTANCE;
        }
        next();
        return new Rule(name, condition, conclusion, at(start));
    }

    // Table 6 as the grammar writes it: OR of ANDs of factors, each level a list.
    private Condition condition() {
        return operands(FclLexer.OR, this::conjunction, Condition.Or::new);
    }

    private Condition conjunction() {
        return operands(FclLexer.AND, this::factor, Condition.And::new);
    }

    /** One operand, or several joined by the operator, made into one condition where it starts. */
    private Condition operands(int operator, Supplier<Condition> operand,
            BiFunction<List<Condition>, SourceLocation, Condition> joined) {
        Token start = t;
        Condition first = operand.get();
        if (type != operator) {
            return first;
        }
        List<Condition> operands = new ArrayList<>();
        operands.add(first);
        while (type == operator) {
            next();
            operands.add(operand.get());
        }
        return joined.apply(operands, at(start));
    }

    private Condition factor() {
        Token start = t;
        boolean negated = type == FclLexer.NOT;
        if (negated) {
            next();
        }
        Condition inner;
        if (type == FclLexer.LPAREN) {
            Token open = t;
            next();
            Condition nested = condition();
            skip(FclLexer.RPAREN);
            inner = new Condition.Parenthesized(nested, at(open));
        } else {
            inner = subcondition();
        }
        return negated ? new Condition.Not(inner, at(start)) : inner;
    }

    private Condition subcondition() {
        Token variable = nameToken();
        if (type != FclLexer.IS) {
            return new Condition.VariableSubcondition(variable.getText(), at(variable));
        }
        next();
        boolean negated = type == FclLexer.NOT;
        if (negated) {
            next();
        }
        return new Condition.TermSubcondition(variable.getText(), name(), negated, at(variable));
    }

    private List<Subconclusion> conclusion() {
        List<Subconclusion> subconclusions = new ArrayList<>(1);
        Token with = subconclusion(subconclusions);
        while (type == FclLexer.COMMA) {
            next();
            with = subconclusion(subconclusions);
        }
        if (subconclusions.size() > 1 && with != null) {
            ModelBuilder.withAfterLastSubconclusion(with, diagnostics);
        }
        return subconclusions;
    }

    /** Adds the subconclusion; gives its WITH token, if it has one. */
    private Token subconclusion(List<Subconclusion> into) {
        Token variable = nameToken();
        Optional<String> term = Optional.empty();
        if (type == FclLexer.IS) {
            next();
            term = Optional.of(name());
        }
        Token with = null;
        Optional<Operand> weight = Optional.empty();
        if (type == FclLexer.WITH) {
            with = t;
            next();
            weight = Optional.of(operand());
        }
        into.add(new Subconclusion(variable.getText(), term, weight, at(variable)));
        return with;
    }

    /** OPTIONS ... END_OPTIONS, kept verbatim; tokens inside are the manufacturer's and go unchecked. */
    private OptionsBlock optionsBlock() {
        Token start = t;
        inOptions = true;
        next();
        while (type != FclLexer.END_OPTIONS) {
            if (type == FclLexer.END_OPTION || type == FclLexer.END_FUNCTION_BLOCK || type == Token.EOF) {
                throw Decline.INSTANCE;
            }
            next();
        }
        Token end = t;
        inOptions = false;
        next();
        int from = start.getStopIndex() + 1;
        int to = end.getStartIndex() - 1;
        String content = to < from ? "" : start.getInputStream().getText(Interval.of(from, to));
        return new OptionsBlock(content.strip(), at(start));
    }

    // ---------------------------------------------------------------- leaves

    private Operand operand() {
        if (type == FclLexer.IDENT) {
            Token name = t;
            next();
            return new VariableRef(name.getText(), at(name));
        }
        return literal();
    }

    /** A number without the pre-scan's objections (digit groups, based digits, exponents). */
    private Literal literal() {
        if (type != FclLexer.INTEGER && type != FclLexer.REAL_LITERAL && type != FclLexer.BASED_INTEGER
                || NumberSyntax.problem(type, t.getText()).isPresent()) {
            throw Decline.INSTANCE;
        }
        Literal literal = ModelBuilder.literal(t, at(t));
        next();
        return literal;
    }
}
