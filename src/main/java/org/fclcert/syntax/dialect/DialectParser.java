package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;

/**
 * The reading core shared by the library dialects (jFuzzyLogic, fuzzylite): a recursive-descent reader
 * of the grammar they share, asking its {@link LibraryDialect} wherever they differ. Builds the model
 * directly, records every non-standard construct as an Open Level feature where it was written, and
 * reports every mistake as a located diagnostic; after an error it skips to the end of the statement.
 * Every loop consumes a token or stops, so no text makes it hang. Rules are read by {@link DialectRuleParser},
 * terms by {@link DialectTermParser}; what remains here (a little over 700 lines) is the grammar of blocks,
 * declarations and settings the libraries share, which reads best in one place.
 */
final class DialectParser {
    static final int MAX_ERRORS = org.fclcert.model.Limits.MAX_ERRORS_PER_FILE;   // also FfllModel's cap
    static final int MAX_NESTING = 200;

    final LibraryDialect dialect;
    final String library;
    private final String source;
    private final List<Token> tokens;
    private int p;
    private final List<Diagnostic> diagnostics = new ArrayList<>();
    private final List<FeatureUse> features = new ArrayList<>();
    private int errors;
    private boolean stopped;
    private final DialectTermParser terms = new DialectTermParser(this);

    /** Thrown to leave a statement after its first error (already reported). */
    static final class Skip extends RuntimeException {
        Skip() {
            super(null, null, false, false);
        }
    }

    /** A DEFUZZIFY block being read; the dialect's statements and settings fill it in. */
    static final class Output {
        final String variable;
        final SourceLocation start;
        final List<Term> terms = new ArrayList<>();
        Optional<Range> range = Optional.empty();
        Optional<Located<DefuzzificationMethod>> method = Optional.empty();
        Optional<DefaultValue> defaultValue = Optional.empty();
        /** fuzzylite: ACCU written in the DEFUZZIFY block. */
        Optional<Located<AccumulationMethod>> accumulation = Optional.empty();
        /** fuzzylite: where LOCK : PREVIOUS or {@code DEFAULT := nan | NC} asks to keep the previous value. */
        SourceLocation keepPrevious;

        Output(String variable, SourceLocation start) {
            this.variable = variable;
            this.start = start;
        }
    }

    /** A RULEBLOCK being read. */
    static final class Block {
        final String name;
        final SourceLocation start;
        Optional<Located<AndAlgorithm>> and = Optional.empty();
        Optional<Located<OrAlgorithm>> or = Optional.empty();
        Optional<Located<ActivationMethod>> act = Optional.empty();
        Optional<Located<AccumulationMethod>> accu = Optional.empty();
        final List<Rule> rules = new ArrayList<>();
        /** "AND" or "OR": which of the two was declared last. */
        String lastOperator;

        Block(String name, SourceLocation start) {
            this.name = name;
            this.start = start;
        }
    }

    /** Where a term is declared: input terms and output terms read different forms. */
    enum TermContext { INPUT, OUTPUT }

    // the function block being read
    final List<Variable> variables = new ArrayList<>();
    final List<Fuzzification> fuzzifications = new ArrayList<>();
    final List<Defuzzification> defuzzifications = new ArrayList<>();
    final List<RuleBlock> ruleBlocks = new ArrayList<>();
    /** The DEFUZZIFY blocks as read, with what the model does not hold (fuzzylite ACCU, COGS places). */
    final List<Output> outputs = new ArrayList<>();
    /** The variable of the FUZZIFY or DEFUZZIFY block being read. */
    String openBlock = "";
    /** jFuzzyLogic: ranges written after a declaration, by variable key. */
    final java.util.Map<String, Range> declaredRanges = new java.util.HashMap<>();

    /** Where a line and column of the text read are in the file (a restatement's places are the file's, see EngineText). */
    interface Placer {
        SourceLocation at(int line, int column);
    }

    private final Placer placer;

    private DialectParser(String source, LibraryDialect dialect, DialectLexer lexer, Placer placer) {
        this.source = source;
        this.placer = placer;
        this.dialect = dialect;
        this.library = dialect.library();
        this.tokens = lexer.tokens;
        // after the last END_FUNCTION_BLOCK the libraries read nothing, characters they could not lex included
        Token end = tokens.stream().filter(t -> t.is("END_FUNCTION_BLOCK")).reduce((a, b) -> b).orElse(null);
        for (DialectLexer.Problem pr : lexer.problems) {
            if (end == null || pr.line() < end.line() || pr.line() == end.line() && pr.column() < end.column()) {
                error(pr.line(), pr.column(), pr.code(), pr.message());
            }
        }
        for (DialectLexer.Comment c : lexer.comments) {
            features.add(new FeatureUse(Feature.O_COMMENT_STYLE, at(c.line(), c.column())));
        }
    }

    /** Reads a text in the dialect; an internal error becomes a located diagnostic (FCL-S999), never an exception. */
    static ReadResult read(String source, String text, LibraryDialect dialect) {
        return read(source, text, dialect, null);
    }

    /** The same, every place of the model and of the diagnostics put where {@code placer} says (none: as written). */
    static ReadResult read(String source, String text, LibraryDialect dialect, Placer placer) {
        String name = source == null ? "<input>" : source;
        DialectParser parser = null;
        try {
            parser = new DialectParser(name, dialect, DialectLexer.lex(text == null ? "" : text, dialect.lexing()),
                    placer);
            Program program = parser.program();
            List<Diagnostic> list = new ArrayList<>(parser.diagnostics);
            list.sort(Comparator.comparing(Diagnostic::location));
            boolean failed = list.stream().anyMatch(Diagnostic::isError);
            return new ReadResult(failed ? Optional.empty() : Optional.of(program), list);
        } catch (RuntimeException | StackOverflowError e) {
            List<Diagnostic> list = new ArrayList<>(parser == null ? List.of() : parser.diagnostics);
            list.add(internalError(name, dialect.library() + " reader", e));
            return new ReadResult(Optional.empty(), list);
        }
    }

    /** The diagnostic of a reader's own bug (FCL-S999): located at the top of the file, asking for a report. */
    static Diagnostic internalError(String source, String what, Throwable e) {
        return Diagnostic.error(SourceLocation.of(source, 1, 1), org.fclcert.syntax.SyntaxCode.INTERNAL_ERROR,
                "internal error of the " + what + " (" + e.getClass().getSimpleName()
                        + (e.getMessage() == null ? "" : ": " + e.getMessage()) + "); please report this");
    }

    // ---------------------------------------------------------------- diagnostics and tokens

    SourceLocation at(int line, int column) {
        return placer == null ? SourceLocation.of(source, line, column) : placer.at(line, column);
    }

    SourceLocation at(Token t) {
        return at(t.line(), t.column());
    }

    void error(int line, int column, DialectCode code, String message) {
        if (stopped) {
            return;
        }
        if (++errors > MAX_ERRORS) {
            diagnostics.add(Diagnostic.error(at(line, column), DialectCode.TOO_MANY_ERRORS,
                    "more than " + MAX_ERRORS + " errors; the rest are not reported"));
            stopped = true;
            return;
        }
        diagnostics.add(Diagnostic.error(at(line, column), code, message));
    }

    void error(Token t, DialectCode code, String message) {
        error(t.line(), t.column(), code, message);
    }

    void warn(SourceLocation where, DialectCode code, String message) {
        diagnostics.add(Diagnostic.warning(where, code, message));
    }

    void feature(Feature f, SourceLocation where) {
        features.add(new FeatureUse(f, where));
    }

    Token peek() {
        return tokens.get(p);
    }

    Token peek(int ahead) {
        return tokens.get(Math.min(tokens.size() - 1, p + ahead));
    }

    Token next() {
        Token t = tokens.get(p);
        if (t.kind() != Kind.EOF) {
            p++;
        }
        return t;
    }

    static String describe(Token t) {
        return t.kind() == Kind.EOF ? "the end of the text" : "'" + t.text() + "'";
    }

    Skip fail(Token t, String expected) {
        error(t, DialectCode.SYNTAX, "expected " + expected + " but found " + describe(t));
        return new Skip();
    }

    boolean isKeyword(Token t, String word) {
        return t.is(word);
    }

    Token expectKeyword(String word) {
        Token t = peek();
        if (!isKeyword(t, word)) {
            throw fail(t, "'" + word + "'");
        }
        dialect.checkKeyword(this, t, word);
        return next();
    }

    Token expect(Kind kind, String what) {
        Token t = peek();
        if (t.kind() != kind) {
            throw fail(t, what);
        }
        return next();
    }

    /** Skips to just after the next ';' or to a word that starts a statement or block. */
    private void recover(int from) {
        if (p == from) {
            next();
        }
        while (peek().kind() != Kind.EOF) {
            Token t = peek();
            if (t.kind() == Kind.SEMI) {
                next();
                return;
            }
            if (t.kind() == Kind.WORD && STATEMENT_START.contains(t.text().toUpperCase(Locale.ROOT))) {
                return;
            }
            next();
        }
    }

    private static final Set<String> STATEMENT_START = Set.of("FUNCTION_BLOCK",
            "END_FUNCTION_BLOCK", "VAR_INPUT", "VAR_OUTPUT", "VAR", "END_VAR", "FUZZIFY", "END_FUZZIFY", "DEFUZZIFY",
            "END_DEFUZZIFY", "RULEBLOCK", "END_RULEBLOCK", "TERM", "RANGE", "METHOD", "DEFAULT", "ACCU", "ACT", "AND", "OR",
            "RULE", "ENABLED", "LOCK", "OPTIONS");

    String name() {
        Token t = peek();
        if (t.kind() != Kind.WORD) {
            throw fail(t, "a name");
        }
        dialect.checkName(this, t);
        return next().text();
    }

    Literal number(boolean infinityAllowed) {
        Token t = peek();
        if (t.kind() == Kind.WORD && (t.text().equals("nan") || t.text().equals("inf"))
                || t.kind() == Kind.NUMBER && t.text().endsWith("inf")) {
            next();
            if (!dialect.infinities() || !infinityAllowed) {
                error(t, DialectCode.BAD_NUMBER, "'" + t.text() + "' is not a number here");
                return new Literal(0, true, at(t));
            }
            double v = t.text().equals("nan") ? Double.NaN : t.text().startsWith("-") ? Double.NEGATIVE_INFINITY
                    : Double.POSITIVE_INFINITY;
            return new Literal(v, false, at(t));
        }
        if (t.kind() != Kind.NUMBER) {
            throw fail(t, "a number");
        }
        next();
        String text = t.text();
        try {
            double v = Double.parseDouble(text);
            boolean integral = !text.contains(".") && !text.contains("e") && !text.contains("E");
            if (!Double.isFinite(v)) {
                error(t, DialectCode.BAD_NUMBER, "'" + text + "' is out of range");
                v = 0;
            }
            return new Literal(v, integral, at(t));
        } catch (NumberFormatException e) {
            return new Literal(0, true, at(t));   // the lexer has reported it
        }
    }

    // ---------------------------------------------------------------- program and function block

    private Program program() {
        List<FunctionBlock> blocks = new ArrayList<>();
        while (peek().kind() != Kind.EOF && !stopped) {
            int from = p;
            if (isKeyword(peek(), "FUNCTION_BLOCK")) {
                blocks.add(functionBlock());
            } else if (!blocks.isEmpty()) {
                Token t = peek();
                warn(at(t), DialectCode.TOLERATED, "text after END_FUNCTION_BLOCK (" + describe(t) + "): "
                        + library + " ignores it; a standard program ends with its last function block");
                feature(Feature.O_TRAILING_TEXT, at(t));
                while (peek().kind() != Kind.EOF && !isKeyword(peek(), "FUNCTION_BLOCK")) {
                    next();
                }
            } else {
                error(peek(), DialectCode.SYNTAX, "text outside FUNCTION_BLOCK ... END_FUNCTION_BLOCK: "
                        + describe(peek()));
                while (peek().kind() != Kind.EOF && !isKeyword(peek(), "FUNCTION_BLOCK")) {
                    next();
                }
            }
            if (p == from) {
                next();
            }
        }
        if (blocks.isEmpty() && errors == 0) {
            error(peek(), DialectCode.SYNTAX, "the text holds no FUNCTION_BLOCK");
        }
        return new Program(source, blocks, features);
    }

    /** The name after FUNCTION_BLOCK or RULEBLOCK, when on its line; otherwise {@code unnamed} (recorded). */
    private String blockName(Token keyword, String unnamed) {
        Token t = peek();
        if (t.kind() == Kind.WORD && t.line() == keyword.line() && !STATEMENT_START.contains(t.text())) {
            next();
            if (t.text().matches("[A-Za-z_][A-Za-z0-9_]*")) {
                dialect.checkName(this, t);
                return t.text();
            }
            String fixed = t.text().replaceAll("[^A-Za-z0-9_]+", "_");
            warn(at(t), DialectCode.TOLERATED, library + " takes the block name '" + t.text() + "' as written;"
                    + " a standard name is an identifier, so fclcert reads it as '" + fixed + "'");
            feature(Feature.O_BLOCK_NAME_VERBATIM, at(t));
            return fixed;
        }
        feature(Feature.O_UNNAMED_BLOCK, at(keyword));
        return unnamed;
    }

    private FunctionBlock functionBlock() {
        Token start = expectKeyword("FUNCTION_BLOCK");
        String fbName = blockName(start, "function_block");
        variables.clear();
        fuzzifications.clear();
        defuzzifications.clear();
        ruleBlocks.clear();
        outputs.clear();
        declaredRanges.clear();
        while (!stopped) {
            Token t = peek();
            int from = p;
            try {
                if (t.kind() == Kind.EOF) {
                    error(t, DialectCode.SYNTAX, "the text ends inside FUNCTION_BLOCK " + fbName
                            + " (END_FUNCTION_BLOCK missing)");
                    break;
                } else if (isKeyword(t, "END_FUNCTION_BLOCK")) {
                    expectKeyword("END_FUNCTION_BLOCK");
                    break;
                } else if (isKeyword(t, "VAR_INPUT") || isKeyword(t, "VAR_OUTPUT")) {
                    varSection();
                } else if (isKeyword(t, "VAR")) {
                    error(t, DialectCode.NOT_IN_DIALECT, library + " has no VAR section (local variables)");
                    skipBlock("END_VAR");
                } else if (isKeyword(t, "OPTIONS")) {
                    error(t, DialectCode.NOT_IN_DIALECT, library + " has no OPTIONS block");
                    skipBlock("END_OPTIONS");
                } else if (isKeyword(t, "FUZZIFY")) {
                    fuzzify();
                } else if (isKeyword(t, "DEFUZZIFY")) {
                    defuzzify();
                } else if (isKeyword(t, "RULEBLOCK")) {
                    ruleBlock();
                } else {
                    throw fail(t, "VAR_INPUT, VAR_OUTPUT, FUZZIFY, DEFUZZIFY, RULEBLOCK or END_FUNCTION_BLOCK");
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        FunctionBlock fb = new FunctionBlock(fbName, variables, fuzzifications, defuzzifications, ruleBlocks,
                List.of(), at(start));
        return dialect.finishFunctionBlock(this, fb);
    }

    private void skipBlock(String end) {
        next();
        while (peek().kind() != Kind.EOF && !isKeyword(peek(), end) && !isKeyword(peek(), "END_FUNCTION_BLOCK")) {
            next();
        }
        if (isKeyword(peek(), end)) {
            next();
        }
    }

    private void varSection() {
        Token kw = next();
        VariableKind kind = kw.is("VAR_INPUT") ? VariableKind.INPUT : VariableKind.OUTPUT;
        while (!stopped) {
            Token t = peek();
            int from = p;
            if (isKeyword(t, "END_VAR")) {
                next();
                return;
            }
            if (t.kind() == Kind.EOF || isKeyword(t, "END_FUNCTION_BLOCK") || isKeyword(t, "FUZZIFY")
                    || isKeyword(t, "DEFUZZIFY") || isKeyword(t, "RULEBLOCK") || isKeyword(t, "VAR_INPUT")
                    || isKeyword(t, "VAR_OUTPUT")) {
                error(t, DialectCode.SYNTAX, "END_VAR missing before " + describe(t));
                return;
            }
            try {
                if (isKeyword(t, "RANGE") && dialect.rangeAfterDeclaration() && !variables.isEmpty()) {
                    // jFuzzyLogic: 'x : REAL; RANGE := (lo .. hi);' gives the variable declared before it a range
                    Variable last = variables.get(variables.size() - 1);
                    range().ifPresent(r -> declaredRanges.put(org.fclcert.model.Names.key(last.name()), r));
                    feature(Feature.O_DECLARATION_RANGE, at(t));
                    continue;
                }
                Token nameToken = peek();
                String n = name();
                if (peek().kind() == Kind.COMMA) {
                    error(peek(), DialectCode.NOT_IN_DIALECT, library + " declares one variable per declaration");
                    throw new Skip();
                }
                expect(Kind.COLON, "':'");
                Token type = peek();
                String typeName = name();
                Optional<DataType> dt = DataType.byKeyword(typeName);
                if (dt.isEmpty()) {
                    error(type, DialectCode.SYNTAX, "'" + typeName + "' is not an elementary numeric type");
                }
                if (peek().kind() == Kind.ASSIGN) {
                    error(peek(), DialectCode.NOT_IN_DIALECT, library + " rejects initial values");
                    throw new Skip();
                }
                expect(Kind.SEMI, "';'");
                variables.add(new Variable(n, kind, dt.orElse(DataType.REAL), Optional.empty(), at(nameToken)));
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
    }

    // ---------------------------------------------------------------- FUZZIFY / DEFUZZIFY

    private void fuzzify() {
        Token start = expectKeyword("FUZZIFY");
        String variable = name();
        openBlock = variable;
        List<Term> terms = new ArrayList<>();
        Optional<Range> declaredRange = Optional.empty();
        while (!stopped) {
            Token t = peek();
            int from = p;
            if (endOfBlock(t, "END_FUZZIFY")) {
                break;
            }
            try {
                if (isKeyword(t, "TERM")) {
                    terms.add(this.terms.term(TermContext.INPUT));
                } else if (isKeyword(t, "RANGE") && !dialect.rangeInFuzzify()) {
                    error(t, DialectCode.NOT_IN_DIALECT, library + " takes no RANGE in FUZZIFY (only in DEFUZZIFY);"
                            + " give the input's RANGE after its declaration in VAR_INPUT");
                    throw new Skip();
                } else if (isKeyword(t, "RANGE")) {
                    // an input's RANGE has no effect on evaluation; kept for the conversion to standard FCL
                    declaredRange = range();
                    feature(Feature.O_INPUT_RANGE, at(t));
                } else if (!dialect.fuzzifyStatement(this, t)) {
                    throw fail(t, "TERM, RANGE or END_FUZZIFY");
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        if (declaredRange.isEmpty()) {
            // jFuzzyLogic gives an input's RANGE after its declaration in VAR_INPUT, not here
            declaredRange = Optional.ofNullable(declaredRanges.get(org.fclcert.model.Names.key(variable)));
        }
        fuzzifications.add(new Fuzzification(variable, Repeated.terms(this, variable, terms, dialect.firstOfRepeatedTerms()),
                at(start), declaredRange));
    }

    /** Whether the block ends at t: at its {@code end} keyword (consumed), or where that is missing (reported). */
    boolean endOfBlock(Token t, String end) {
        if (isKeyword(t, end)) {
            next();
            return true;
        }
        if (t.kind() == Kind.EOF || isKeyword(t, "END_FUNCTION_BLOCK") || isKeyword(t, "FUZZIFY")
                || isKeyword(t, "DEFUZZIFY") || isKeyword(t, "RULEBLOCK")) {
            error(t, DialectCode.SYNTAX, end + " missing before " + describe(t));
            return true;
        }
        return false;
    }

    /** RANGE := (lo .. hi); both libraries need the ':='. */
    Optional<Range> range() {
        Token kw = next();
        if (peek().kind() != Kind.ASSIGN) {
            error(peek(), DialectCode.NOT_IN_DIALECT, library + " needs ':=' after RANGE");
            throw new Skip();
        }
        next();
        expect(Kind.LPAREN, "'('");
        Literal lo = number(true);
        expect(Kind.DOTDOT, "'..'");
        Literal hi = number(true);
        expect(Kind.RPAREN, "')'");
        expect(Kind.SEMI, "';'");
        if (Double.isNaN(lo.value()) || Double.isNaN(hi.value())) {
            error(kw, DialectCode.BAD_NUMBER, "a RANGE needs numbers, not nan");
            return Optional.empty();
        }
        if (Double.isInfinite(lo.value()) || Double.isInfinite(hi.value())) {
            feature(Feature.O_INFINITE_RANGE, at(kw));
            return Optional.empty();
        }
        return Optional.of(new Range(lo, hi, at(kw)));
    }

    private void defuzzify() {
        Token start = expectKeyword("DEFUZZIFY");
        Output out = new Output(name(), at(start));
        openBlock = out.variable;
        while (!stopped) {
            Token t = peek();
            int from = p;
            if (endOfBlock(t, "END_DEFUZZIFY")) {
                break;
            }
            try {
                if (isKeyword(t, "TERM")) {
                    out.terms.add(terms.term(TermContext.OUTPUT));
                } else if (isKeyword(t, "RANGE")) {
                    out.range = range();
                } else if (isKeyword(t, "METHOD")) {
                    out.method = Optional.of(method());
                } else if (isKeyword(t, "DEFAULT")) {
                    out.defaultValue = Optional.of(defaultValue(out));
                } else if (!dialect.defuzzifyStatement(this, t, out)) {
                    throw fail(t, dialect.defuzzifyStatements());
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        List<Term> distinct = new ArrayList<>(Repeated.terms(this, out.variable, out.terms, dialect.firstOfRepeatedTerms()));
        out.terms.clear();
        out.terms.addAll(distinct);
        dialect.finishOutput(this, out);
        outputs.add(out);
        defuzzifications.add(new Defuzzification(out.variable, out.range, out.terms, out.method, out.defaultValue,
                out.start));
    }

    private Located<DefuzzificationMethod> method() {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token w = peek();
        String word = name();
        expect(Kind.SEMI, "';'");
        Optional<DefuzzificationMethod> m = dialect.method(this, w, word.toUpperCase(Locale.ROOT));
        if (m.isEmpty()) {
            error(w, DialectCode.SYNTAX, "'" + word + "' is not a method of " + library + " that fclcert reads ("
                    + dialect.methodNames() + ")");
            throw new Skip();
        }
        return new Located<>(m.get(), at(kw));
    }

    /** {@code DEFAULT := value;}, {@code NC}, and in dialects with nan also {@code nan | NC} (keep the previous value). */
    private DefaultValue defaultValue(Output out) {
        Token kw = next();
        expect(Kind.ASSIGN, "':='");
        Token v = peek();
        if (v.is("NC")) {
            next();
            expect(Kind.SEMI, "';'");
            return new DefaultValue.NoChange(at(kw));
        }
        Literal value = number(true);
        if (peek().kind() == Kind.BAR && dialect.infinities()) {
            next();
            Token nc = peek();
            if (!nc.is("NC")) {
                throw fail(nc, "'NC' after '|'");
            }
            next();
            expect(Kind.SEMI, "';'");
            out.keepPrevious = at(nc);
            feature(Feature.O_LOCK_PREVIOUS, at(nc));
            return new DefaultValue.Constant(value, at(kw));
        }
        expect(Kind.SEMI, "';'");
        if (Double.isInfinite(value.value())) {
            error(v, DialectCode.BAD_NUMBER, "a DEFAULT of " + v.text() + " is not evaluated by fclcert");
        }
        if (Double.isNaN(value.value())) {
            feature(Feature.O_DEFAULT_NAN, at(v));
        }
        return new DefaultValue.Constant(value, at(kw));
    }

    /** (x, y) (x, y) ...: the points of a term. */
    List<Point> points() {
        return terms.points();
    }

    // ---------------------------------------------------------------- RULEBLOCK

    Optional<Located<AccumulationMethod>> accumulation() {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token w = peek();
        String word = name();
        expect(Kind.SEMI, "';'");
        Optional<AccumulationMethod> m = dialect.accumulation(word.toUpperCase(Locale.ROOT));
        if (m.isEmpty()) {
            error(w, DialectCode.UNSUPPORTED, "'" + word + "' is not an accumulation fclcert reads in " + library
                    + " (" + dialect.accumulationNames() + ")");
            return Optional.empty();
        }
        if (m.get() == AccumulationMethod.NSUM) {
            warn(at(w), DialectCode.NSUM_AS_BSUM, library + " computes NSUM as BSUM; fclcert divides by the"
                    + " largest sum (Table 5), which differs once the sum exceeds 1");
        }
        return Optional.of(new Located<>(m.get(), at(kw)));
    }

    private void ruleBlock() {
        Token start = expectKeyword("RULEBLOCK");
        Block block = new Block(blockName(start, "ruleblock" + (ruleBlocks.size() + 1)), at(start));
        DialectRuleParser rules = new DialectRuleParser(this);
        while (!stopped) {
            Token t = peek();
            int from = p;
            if (endOfBlock(t, "END_RULEBLOCK")) {
                break;
            }
            try {
                if (isKeyword(t, "AND") && peek(1).kind() == Kind.COLON) {
                    block.and = Optional.of(new Located<>(algorithm(AndAlgorithm.class, dialect.andNames()), at(t)));
                    block.lastOperator = "AND";
                } else if (isKeyword(t, "OR") && peek(1).kind() == Kind.COLON) {
                    block.or = Optional.of(new Located<>(algorithm(OrAlgorithm.class, dialect.orNames()), at(t)));
                    block.lastOperator = "OR";
                } else if (isKeyword(t, "ACT")) {
                    Token w = peek(2);
                    ActivationMethod act = algorithm(ActivationMethod.class, dialect.activationNames());
                    if (!act.standard() && !dialect.otherActivations()) {
                        error(w, DialectCode.UNSUPPORTED, "'" + w.text() + "' is not an algorithm " + library
                                + " reads for ACT (" + dialect.activationNames() + ")");
                    }
                    block.act = Optional.of(new Located<>(act, at(t)));
                } else if (isKeyword(t, "ACCU")) {
                    block.accu = accumulation();
                } else if (isKeyword(t, "RULE")) {
                    Rule r = rules.rule();
                    if (r != null) {
                        block.rules.add(r);
                    }
                } else if (!dialect.ruleBlockStatement(this, t)) {
                    throw fail(t, "AND, OR, ACT, ACCU, RULE or END_RULEBLOCK");
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        dialect.finishRuleBlock(this, block);
        ruleBlocks.add(new RuleBlock(block.name, block.and, block.or, block.act, block.accu,
                Repeated.rules(this, rules.relabelled(block.rules)),
                block.start));
    }


    private <E extends Enum<E>> E algorithm(Class<E> type, String allowed) {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token w = peek();
        String word = name();
        expect(Kind.SEMI, "';'");
        String upper = word.toUpperCase(Locale.ROOT);
        if (type == OrAlgorithm.class) {
            upper = dialect.orAlgorithm(upper);
        } else if (type == AndAlgorithm.class) {
            upper = dialect.andAlgorithm(upper);
        }
        for (E value : type.getEnumConstants()) {
            if (value.name().equals(upper)) {
                return value;
            }
        }
        error(w, DialectCode.UNSUPPORTED, "'" + word + "' is not an algorithm fclcert reads for "
                + kw.text().toUpperCase(Locale.ROOT) + " (" + allowed + ")");
        throw new Skip();
    }
}
