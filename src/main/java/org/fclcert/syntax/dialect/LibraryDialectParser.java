package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Hedge;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;

/**
 * The recursive-descent reader shared by the jFuzzyLogic and fuzzylite dialects (they overlap in most
 * of the grammar; where they differ, {@link #fuzzylite} says which is read). Builds the model directly,
 * records every non-standard construct as an Open Level feature where it was written, and reports
 * every mistake as a located diagnostic; after an error it skips to the end of the statement.
 * Every loop consumes a token or stops, so no text makes it hang.
 */
final class LibraryDialectParser {
    private static final int MAX_ERRORS = 25;
    static final int MAX_NESTING = 200;

    private final String source;
    private final boolean fuzzylite;
    private final String library;
    private final List<Token> tokens;
    private int p;
    private final List<Diagnostic> diagnostics = new ArrayList<>();
    private final List<FeatureUse> features = new ArrayList<>();
    private int errors;
    private boolean stopped;

    /** Thrown to leave a statement after its first error (already reported). */
    private static final class Skip extends RuntimeException {
        Skip() {
            super(null, null, false, false);
        }
    }

    private LibraryDialectParser(String source, boolean fuzzylite, DialectLexer lexer) {
        this.source = source;
        this.fuzzylite = fuzzylite;
        this.library = fuzzylite ? "fuzzylite" : "jFuzzyLogic";
        this.tokens = lexer.tokens;
        for (DialectLexer.Problem pr : lexer.problems) {
            error(pr.line(), pr.column(), pr.code(), pr.message());
        }
        for (DialectLexer.Comment c : lexer.comments) {
            features.add(new FeatureUse(Feature.O_COMMENT_STYLE, at(c.line(), c.column())));
        }
    }

    static org.fclcert.syntax.ReadResult read(String source, String text, boolean fuzzylite) {
        String name = source == null ? "<input>" : source;
        LibraryDialectParser parser = null;
        try {
            parser = new LibraryDialectParser(name, fuzzylite, DialectLexer.lex(text == null ? "" : text, fuzzylite));
            Program program = parser.program();
            List<Diagnostic> list = parser.sorted();
            boolean failed = list.stream().anyMatch(Diagnostic::isError);
            return new org.fclcert.syntax.ReadResult(failed ? Optional.empty() : Optional.of(program), list);
        } catch (RuntimeException | StackOverflowError e) {
            List<Diagnostic> list = new ArrayList<>(parser == null ? List.of() : parser.diagnostics);
            list.add(Diagnostic.error(SourceLocation.of(name, 1, 1), org.fclcert.syntax.SyntaxCode.INTERNAL_ERROR,
                    "internal error of the " + (fuzzylite ? "fuzzylite" : "jFuzzyLogic") + " reader ("
                            + e.getClass().getSimpleName() + "); please report this"));
            return new org.fclcert.syntax.ReadResult(Optional.empty(), list);
        }
    }

    private List<Diagnostic> sorted() {
        List<Diagnostic> list = new ArrayList<>(diagnostics);
        list.sort(java.util.Comparator.comparing(Diagnostic::location));
        return list;
    }

    // ---------------------------------------------------------------- diagnostics and tokens

    private SourceLocation at(int line, int column) {
        return SourceLocation.of(source, line, column);
    }

    private SourceLocation at(Token t) {
        return at(t.line(), t.column());
    }

    private void error(int line, int column, DialectCode code, String message) {
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

    private void error(Token t, DialectCode code, String message) {
        error(t.line(), t.column(), code, message);
    }

    private void warn(SourceLocation where, DialectCode code, String message) {
        diagnostics.add(Diagnostic.warning(where, code, message));
    }

    private void feature(Feature f, SourceLocation where) {
        features.add(new FeatureUse(f, where));
    }

    private Token peek() {
        return tokens.get(p);
    }

    private Token peek(int ahead) {
        return tokens.get(Math.min(tokens.size() - 1, p + ahead));
    }

    private Token next() {
        Token t = tokens.get(p);
        if (t.kind() != Kind.EOF) {
            p++;
        }
        return t;
    }

    private static String describe(Token t) {
        return t.kind() == Kind.EOF ? "the end of the text" : "'" + t.text() + "'";
    }

    private Skip fail(Token t, String expected) {
        error(t, DialectCode.SYNTAX, "expected " + expected + " but found " + describe(t));
        return new Skip();
    }

    /** A keyword: any case in jFuzzyLogic; in fuzzylite block keywords are upper case. */
    private boolean isKeyword(Token t, String word) {
        return t.is(word);
    }

    private Token expectKeyword(String word) {
        Token t = peek();
        if (!isKeyword(t, word)) {
            throw fail(t, "'" + word + "'");
        }
        if (fuzzylite && !t.text().equals(word) && !t.text().equals(word.toLowerCase(Locale.ROOT))) {
            error(t, DialectCode.NOT_IN_DIALECT, "fuzzylite reads '" + word + "' only in upper case");
        }
        return next();
    }

    private Token expect(Kind kind, String what) {
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

    private static final java.util.Set<String> STATEMENT_START = java.util.Set.of("FUNCTION_BLOCK",
            "END_FUNCTION_BLOCK", "VAR_INPUT", "VAR_OUTPUT", "VAR", "END_VAR", "FUZZIFY", "END_FUZZIFY", "DEFUZZIFY",
            "END_DEFUZZIFY", "RULEBLOCK", "END_RULEBLOCK", "TERM", "RANGE", "METHOD", "DEFAULT", "ACCU", "ACT", "AND", "OR",
            "RULE", "ENABLED", "LOCK", "OPTIONS");

    private String name() {
        Token t = peek();
        if (t.kind() != Kind.WORD) {
            throw fail(t, "a name");
        }
        if (!fuzzylite && t.text().startsWith("_")) {
            error(t, DialectCode.NOT_IN_DIALECT, "jFuzzyLogic rejects names starting with '_'");
        }
        return next().text();
    }

    private Literal number(boolean infinityAllowed) {
        Token t = peek();
        if (t.kind() == Kind.WORD && (t.text().equals("nan") || t.text().equals("inf"))
                || t.kind() == Kind.NUMBER && t.text().endsWith("inf")) {
            next();
            if (!fuzzylite || !infinityAllowed) {
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

    private final List<Variable> variables = new ArrayList<>();
    private final List<Fuzzification> fuzzifications = new ArrayList<>();
    private final List<Defuzzification> defuzzifications = new ArrayList<>();
    private final List<RuleBlock> ruleBlocks = new ArrayList<>();
    /** fuzzylite: the ACCU written in each DEFUZZIFY block, by output key. */
    private final Map<String, Located<AccumulationMethod>> outputAccu = new HashMap<>();
    /** fuzzylite: METHOD COGS locations by output key (for FCL-W306). */
    private final Map<String, SourceLocation> cogs = new HashMap<>();
    /** Defuzzify data not in the model: LOCK RANGE and the range, for FCL-W305/W306 checks. */

    private FunctionBlock functionBlock() {
        Token start = expectKeyword("FUNCTION_BLOCK");
        String fbName = "";
        try {
            fbName = name();
        } catch (Skip s) {
            recover(p);
        }
        variables.clear();
        fuzzifications.clear();
        defuzzifications.clear();
        ruleBlocks.clear();
        outputAccu.clear();
        cogs.clear();
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
        List<RuleBlock> blocks = fuzzylite ? moveAccumulations(ruleBlocks) : ruleBlocks;
        FunctionBlock fb = new FunctionBlock(fbName, variables, fuzzifications, defuzzifications, blocks, List.of(),
                at(start));
        if (!fuzzylite) {
            CaseSensitivity.warn(fb, this::warn);
        } else {
            cogsPerRule(fb);
        }
        return fb;
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
                    || isKeyword(t, "DEFUZZIFY") || isKeyword(t, "RULEBLOCK")) {
                error(t, DialectCode.SYNTAX, "END_VAR missing before " + describe(t));
                return;
            }
            try {
                Token nameToken = peek();
                String n = name();
                if (peek().kind() == Kind.COMMA) {
                    error(peek(), DialectCode.NOT_IN_DIALECT, library
                            + " declares one variable per declaration");
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
                    terms.add(term());
                } else if (isKeyword(t, "RANGE")) {
                    // an input's RANGE has no effect on evaluation; kept for the conversion to standard FCL
                    declaredRange = range();
                    feature(Feature.O_INPUT_RANGE, at(t));
                } else if (isKeyword(t, "ENABLED") && fuzzylite) {
                    enabled();
                } else if (isKeyword(t, "LOCK") && fuzzylite) {
                    error(t, DialectCode.UNSUPPORTED, "fclcert does not evaluate LOCK on an input");
                    throw new Skip();
                } else {
                    throw fail(t, "TERM, RANGE or END_FUZZIFY");
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        fuzzifications.add(new Fuzzification(variable, terms, at(start), declaredRange));
    }

    /** Whether the block ends at t: at its {@code end} keyword (consumed), or where that is missing (reported). */
    private boolean endOfBlock(Token t, String end) {
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

    private void enabled() {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token v = peek();
        String value = name();
        expect(Kind.SEMI, "';'");
        if (value.equals("FALSE") || value.equals("false")) {
            error(v, DialectCode.UNSUPPORTED, "fclcert does not evaluate disabled parts (ENABLED : FALSE)");
        } else if (!value.equals("TRUE") && !value.equals("true")) {
            error(v, DialectCode.SYNTAX, "ENABLED takes TRUE or FALSE, not '" + value + "'");
        }
        feature(Feature.O_ENABLED, at(kw));
    }

    /** RANGE := (lo .. hi); both libraries need the ':='. */
    private Optional<Range> range() {
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
        String variable = name();
        List<Term> terms = new ArrayList<>();
        Optional<Range> range = Optional.empty();
        Optional<Located<DefuzzificationMethod>> method = Optional.empty();
        Optional<DefaultValue> defaultValue = Optional.empty();
        boolean lockPrevious = false;
        SourceLocation lockAt = null;
        while (!stopped) {
            Token t = peek();
            int from = p;
            if (endOfBlock(t, "END_DEFUZZIFY")) {
                break;
            }
            try {
                if (isKeyword(t, "TERM")) {
                    terms.add(term());
                } else if (isKeyword(t, "RANGE")) {
                    range = range();
                } else if (isKeyword(t, "METHOD")) {
                    method = Optional.of(method());
                    if (method.get().value() == DefuzzificationMethod.COGS) {
                        cogs.put(Names.key(variable), method.get().location());
                    }
                } else if (isKeyword(t, "DEFAULT")) {
                    defaultValue = Optional.of(defaultValue());
                } else if (isKeyword(t, "ACCU")) {
                    Optional<Located<AccumulationMethod>> a = accumulation();
                    if (!fuzzylite) {
                        error(t, DialectCode.NOT_IN_DIALECT, "jFuzzyLogic takes ACCU in the RULEBLOCK");
                    } else if (a.isPresent()) {
                        outputAccu.put(Names.key(variable), a.get());
                        feature(Feature.O_ACCU_IN_DEFUZZIFY, at(t));
                    }
                } else if (isKeyword(t, "ENABLED") && fuzzylite) {
                    enabled();
                } else if (isKeyword(t, "LOCK") && fuzzylite) {
                    next();
                    expect(Kind.COLON, "':'");
                    do {
                        Token w = peek();
                        String what = name();
                        if (what.equals("PREVIOUS")) {
                            lockPrevious = true;
                            lockAt = at(w);
                            feature(Feature.O_LOCK_PREVIOUS, at(w));
                        } else if (what.equals("RANGE")) {
                            feature(Feature.O_LOCK_RANGE, at(w));
                        } else {
                            error(w, DialectCode.SYNTAX, "LOCK takes PREVIOUS and/or RANGE, not '" + what + "'");
                        }
                    } while (peek().kind() == Kind.COMMA && next() != null);
                    expect(Kind.SEMI, "';'");
                } else {
                    throw fail(t, "TERM, RANGE, METHOD, DEFAULT" + (fuzzylite ? ", ACCU, LOCK" : "") + " or END_DEFUZZIFY");
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        if (lockPrevious) {
            warn(lockAt, DialectCode.LOCK_PREVIOUS, "LOCK : PREVIOUS is read as DEFAULT NC: fuzzylite keeps the"
                    + " previous result but gives the DEFAULT before the first one, fclcert the initial value (0)");
            defaultValue = Optional.of(new DefaultValue.NoChange(lockAt));
        }
        if (!fuzzylite) {
            if (method.isEmpty()) {
                warn(at(start), DialectCode.SUPPLIED_SETTING, "no METHOD: jFuzzyLogic uses CoG, and so does fclcert");
                feature(Feature.O_IMPLICIT_SETTING, at(start));
                method = Optional.of(new Located<>(DefuzzificationMethod.COG, at(start)));
            }
            if (defaultValue.isEmpty()) {
                warn(at(start), DialectCode.SUPPLIED_SETTING,
                        "no DEFAULT: jFuzzyLogic keeps the previous value when no rule fires; read as DEFAULT NC");
                feature(Feature.O_IMPLICIT_SETTING, at(start));
                defaultValue = Optional.of(new DefaultValue.NoChange(at(start)));
            }
        }
        defuzzifications.add(new Defuzzification(variable, range, terms, method, defaultValue, at(start)));
    }

    private Located<DefuzzificationMethod> method() {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token w = peek();
        String word = name();
        expect(Kind.SEMI, "';'");
        String upper = word.toUpperCase(Locale.ROOT);
        if (fuzzylite && !word.equals(upper)) {
            error(w, DialectCode.NOT_IN_DIALECT, "fuzzylite reads methods in upper case only, not '" + word + "'");
        }
        DefuzzificationMethod m;
        switch (upper) {
            case "COG" -> m = DefuzzificationMethod.COG;
            case "COGS" -> m = DefuzzificationMethod.COGS;
            case "COA" -> m = DefuzzificationMethod.COA;
            case "LM" -> m = DefuzzificationMethod.LM;
            case "RM" -> m = DefuzzificationMethod.RM;
            case "MM" -> {
                m = DefuzzificationMethod.MOM;
                feature(Feature.O_METHOD_MM, at(w));
            }
            case "COGF" -> {
                if (fuzzylite) {
                    throw unknownMethod(w, word);
                }
                m = DefuzzificationMethod.COG;
                feature(Feature.O_METHOD_COGF, at(w));
            }
            case "COGSS" -> {
                if (!fuzzylite) {
                    throw unknownMethod(w, word);
                }
                m = DefuzzificationMethod.COGSS;
            }
            default -> throw unknownMethod(w, word);
        }
        return new Located<>(m, at(kw));
    }

    private Skip unknownMethod(Token w, String word) {
        error(w, DialectCode.SYNTAX, "'" + word + "' is not a method of " + library + " that fclcert reads ("
                + (fuzzylite ? "COG, COA, LM, RM, MM, COGS, COGSS" : "COG, COGF, COGS, COA, LM, RM, MM") + ")");
        return new Skip();
    }

    private DefaultValue defaultValue() {
        Token kw = next();
        expect(Kind.ASSIGN, "':='");
        Token v = peek();
        if (v.is("NC")) {
            next();
            expect(Kind.SEMI, "';'");
            return new DefaultValue.NoChange(at(kw));
        }
        Literal value = number(true);
        expect(Kind.SEMI, "';'");
        if (Double.isInfinite(value.value())) {
            error(v, DialectCode.BAD_NUMBER, "a DEFAULT of " + v.text() + " is not evaluated by fclcert");
        }
        if (Double.isNaN(value.value())) {
            feature(Feature.O_DEFAULT_NAN, at(v));
        }
        return new DefaultValue.Constant(value, at(kw));
    }

    // ---------------------------------------------------------------- terms

    private Term term() {
        Token kw = next();
        String termName = name();
        expect(Kind.ASSIGN, "':='");
        MembershipFunction f = membershipFunction();
        Token end = expect(Kind.SEMI, "';' after the term");
        if (fuzzylite && end.line() != kw.line()) {
            error(end, DialectCode.STATEMENT_SPANS_LINES, "fuzzylite reads a TERM from one line;"
                    + " this one continues on line " + end.line());
        }
        return new Term(termName, f, at(kw));
    }

    private MembershipFunction membershipFunction() {
        Token t = peek();
        if (t.kind() == Kind.LPAREN) {
            return new MembershipFunction.Points(points());
        }
        if (t.kind() == Kind.NUMBER) {
            return new MembershipFunction.Singleton(number(false));
        }
        if (t.kind() != Kind.WORD) {
            throw fail(t, "points, a number or a membership-function name");
        }
        next();
        if (!fuzzylite && t.is("singletons")) {
            List<Point> pts = points();
            if (pts.size() != 1 || ((Literal) pts.get(0).degree()).value() != 1) {
                error(t, DialectCode.UNSUPPORTED, "fclcert reads 'singletons' only as one singleton (x, 1)");
                throw new Skip();
            }
            feature(Feature.O_SHAPE_SINGLETONS, at(t));
            return new MembershipFunction.Singleton(pts.get(0).x());
        }
        if (!fuzzylite && t.is("singleton")) {
            return new MembershipFunction.Singleton(number(false));
        }
        if (fuzzylite && t.text().equals("Discrete")) {
            List<Point> pts = new ArrayList<>();
            while (peek().kind() == Kind.NUMBER) {
                Token x = peek();
                Literal xv = number(false);
                Literal yv = number(false);
                pts.add(new Point(xv, yv, at(x)));
            }
            feature(Feature.O_SHAPE_DISCRETE, at(t));
            return new MembershipFunction.Points(pts);
        }
        Optional<ShapeKind> kind = fuzzylite ? fuzzyliteShape(t.text()) : jfuzzylogicShape(t.text());
        if (kind.isEmpty()) {
            boolean known = fuzzylite && FUZZYLITE_UNSUPPORTED.contains(t.text());
            error(t, known ? DialectCode.UNSUPPORTED : DialectCode.UNKNOWN_SHAPE, known
                    ? "fclcert does not evaluate fuzzylite's '" + t.text() + "' terms"
                    : "'" + t.text() + "' is not a membership function of " + library);
            throw new Skip();
        }
        List<Literal> written = new ArrayList<>();
        while (peek().kind() == Kind.NUMBER) {
            written.add(number(false));
        }
        return new MembershipFunction.NamedShape(kind.get(), canonical(kind.get(), written));
    }

    private static final java.util.Set<String> FUZZYLITE_UNSUPPORTED = java.util.Set.of("Constant", "Linear",
            "Function", "Spike", "Concave", "Binary", "Aggregated", "Activated");

    private static Optional<ShapeKind> fuzzyliteShape(String word) {
        return Optional.ofNullable(switch (word) {
            case "Triangle" -> ShapeKind.TRIANGLE;
            case "Trapezoid" -> ShapeKind.TRAPEZOID;
            case "Rectangle" -> ShapeKind.RECTANGLE;
            case "Ramp" -> ShapeKind.RAMP;
            case "Gaussian" -> ShapeKind.GAUSSIAN;
            case "GaussianProduct" -> ShapeKind.GAUSSIAN_PRODUCT;
            case "Bell" -> ShapeKind.BELL;
            case "Sigmoid" -> ShapeKind.SIGMOID;
            case "SigmoidDifference" -> ShapeKind.SIGMOID_DIFFERENCE;
            case "SigmoidProduct" -> ShapeKind.SIGMOID_PRODUCT;
            case "Cosine" -> ShapeKind.COSINE;
            case "SShape" -> ShapeKind.S_SHAPE;
            case "ZShape" -> ShapeKind.Z_SHAPE;
            case "PiShape" -> ShapeKind.PI_SHAPE;
            default -> null;
        });
    }

    private static Optional<ShapeKind> jfuzzylogicShape(String word) {
        return Optional.ofNullable(switch (word.toLowerCase(Locale.ROOT)) {
            case "trian" -> ShapeKind.TRIANGLE;
            case "trape" -> ShapeKind.TRAPEZOID;
            case "gauss" -> ShapeKind.GAUSSIAN;
            case "gauss2" -> ShapeKind.GAUSSIAN_PRODUCT;
            case "gbell" -> ShapeKind.BELL;
            case "sigm" -> ShapeKind.SIGMOID;
            case "dsigm" -> ShapeKind.SIGMOID_DIFFERENCE;
            case "cosine" -> ShapeKind.COSINE;
            default -> null;
        });
    }

    /**
     * The parameters as written, in fclcert's canonical order. fuzzylite writes the canonical order;
     * jFuzzyLogic writes gbell (width, slope, center), sigm (gain, center), dsigm (gain1, center1,
     * gain2, center2) and cosine (width, center). A wrong count is kept as written (FCL-C040 reports it).
     */
    private List<Literal> canonical(ShapeKind kind, List<Literal> w) {
        if (fuzzylite || w.size() != kind.arity()) {
            return w;
        }
        return switch (kind) {
            case BELL -> List.of(w.get(2), w.get(0), w.get(1));
            case SIGMOID -> List.of(w.get(1), w.get(0));
            case SIGMOID_DIFFERENCE -> List.of(w.get(1), w.get(0), w.get(2), w.get(3));
            case COSINE -> List.of(w.get(1), w.get(0));
            default -> w;
        };
    }

    /** (x, y) (x, y) ...; no commas between the points (both libraries reject them). */
    private List<Point> points() {
        List<Point> pts = new ArrayList<>();
        while (peek().kind() == Kind.LPAREN) {
            Token open = next();
            Literal x = number(false);
            expect(Kind.COMMA, "',' between x and degree");
            Literal y = number(false);
            expect(Kind.RPAREN, "')'");
            pts.add(new Point(x, y, at(open)));
            if (peek().kind() == Kind.COMMA) {
                error(peek(), DialectCode.NOT_IN_DIALECT, library + " rejects ',' between points");
                next();
            }
        }
        return pts;
    }

    // ---------------------------------------------------------------- RULEBLOCK

    private Optional<Located<AccumulationMethod>> accumulation() {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token w = peek();
        String word = name();
        expect(Kind.SEMI, "';'");
        String upper = word.toUpperCase(Locale.ROOT);
        AccumulationMethod m = switch (upper) {
            case "MAX" -> AccumulationMethod.MAX;
            case "BSUM" -> AccumulationMethod.BSUM;
            case "NSUM" -> AccumulationMethod.NSUM;
            case "SUM" -> AccumulationMethod.SUM;
            case "PROBOR" -> fuzzylite ? null : AccumulationMethod.PROBOR;
            case "ASUM" -> fuzzylite ? AccumulationMethod.PROBOR : null;
            default -> null;
        };
        if (m == null) {
            error(w, DialectCode.UNSUPPORTED, "'" + word + "' is not an accumulation fclcert reads in " + library
                    + " (" + (fuzzylite ? "MAX, BSUM, NSUM, ASUM, SUM" : "MAX, BSUM, NSUM, PROBOR, SUM") + ")");
            return Optional.empty();
        }
        if (m == AccumulationMethod.NSUM) {
            warn(at(w), DialectCode.NSUM_AS_BSUM, library + " computes NSUM as BSUM; fclcert divides by the"
                    + " largest sum (Table 5), which differs once the sum exceeds 1");
        }
        return Optional.of(new Located<>(m, at(kw)));
    }

    private void ruleBlock() {
        Token start = expectKeyword("RULEBLOCK");
        String blockName = name();
        Optional<Located<AndAlgorithm>> and = Optional.empty();
        Optional<Located<OrAlgorithm>> or = Optional.empty();
        Optional<Located<ActivationMethod>> act = Optional.empty();
        Optional<Located<AccumulationMethod>> accu = Optional.empty();
        List<Rule> rules = new ArrayList<>();
        String lastOperator = null;
        while (!stopped) {
            Token t = peek();
            int from = p;
            if (endOfBlock(t, "END_RULEBLOCK")) {
                break;
            }
            try {
                if (isKeyword(t, "AND") && peek(1).kind() == Kind.COLON) {
                    and = Optional.of(new Located<>(algorithm(AndAlgorithm.class, "MIN, PROD, BDIF"), at(t)));
                    lastOperator = "AND";
                } else if (isKeyword(t, "OR") && peek(1).kind() == Kind.COLON) {
                    or = Optional.of(new Located<>(algorithm(OrAlgorithm.class, "MAX, ASUM, BSUM"), at(t)));
                    lastOperator = "OR";
                } else if (isKeyword(t, "ACT")) {
                    act = Optional.of(new Located<>(algorithm(ActivationMethod.class, "MIN, PROD"), at(t)));
                } else if (isKeyword(t, "ACCU")) {
                    accu = accumulation();
                } else if (isKeyword(t, "ENABLED") && fuzzylite) {
                    enabled();
                } else if (isKeyword(t, "RULE")) {
                    Rule r = rule();
                    if (r != null) {
                        rules.add(r);
                    }
                } else {
                    throw fail(t, "AND, OR, ACT, ACCU, RULE or END_RULEBLOCK");
                }
            } catch (Skip s) {
                recover(from);
            }
            if (p == from) {
                next();
            }
        }
        if (!fuzzylite) {
            if (and.isPresent() && or.isPresent() && and.get().value().pair() != or.get().value()) {
                boolean orLast = "OR".equals(lastOperator);
                SourceLocation later = orLast ? or.get().location() : and.get().location();
                String effective = orLast ? "AND as " + or.get().value().pair() : "OR as " + and.get().value().pair();
                warn(later, DialectCode.COUPLED_AND_OR, "jFuzzyLogic couples AND and OR: the later declaration"
                        + " makes it evaluate " + effective + "; fclcert reads AND " + and.get().value() + " and OR "
                        + or.get().value() + " as written");
            }
            if (accu.isEmpty()) {
                warn(at(start), DialectCode.SUPPLIED_SETTING,
                        "no ACCU: jFuzzyLogic accumulates by a plain sum; read as ACCU SUM");
                feature(Feature.O_IMPLICIT_SETTING, at(start));
                accu = Optional.of(new Located<>(AccumulationMethod.SUM, at(start)));
            }
        }
        ruleBlocks.add(new RuleBlock(blockName, and, or, act, accu, rules, at(start)));
    }

    private <E extends Enum<E>> E algorithm(Class<E> type, String allowed) {
        Token kw = next();
        expect(Kind.COLON, "':'");
        Token w = peek();
        String word = name();
        expect(Kind.SEMI, "';'");
        String upper = word.toUpperCase(Locale.ROOT);
        if (type == OrAlgorithm.class && upper.equals("PROBOR") && !fuzzylite) {
            upper = "ASUM";
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

    // ---------------------------------------------------------------- rules

    /** fuzzylite: the line the current rule is on; tokens on later lines end it. 0 outside rules. */
    private int ruleLine;

    /** The next token of the current rule, or EOF-like null when fuzzylite's rule line has ended. */
    private Token ruleToken() {
        Token t = peek();
        return fuzzylite && ruleLine > 0 && t.line() != ruleLine ? null : t;
    }

    private boolean ruleWord(String word) {
        Token t = ruleToken();
        if (t == null || !t.is(word)) {
            return false;
        }
        if (fuzzylite && !t.text().equals(word.toLowerCase(Locale.ROOT))) {
            error(t, DialectCode.NOT_IN_DIALECT, "fuzzylite silently drops a rule that writes '" + t.text()
                    + "': its rule keywords are lower case ('" + word.toLowerCase(Locale.ROOT) + "')");
        }
        return true;
    }

    private Token ruleExpectWord(String word) {
        if (!ruleWord(word)) {
            throw ruleFail("'" + (fuzzylite ? word.toLowerCase(Locale.ROOT) : word) + "'");
        }
        return next();
    }

    private Skip ruleFail(String expected) {
        Token t = ruleToken();
        if (t == null) {
            error(peek(), DialectCode.STATEMENT_SPANS_LINES, "fuzzylite reads a rule from one line; expected "
                    + expected + " before the end of line " + ruleLine);
            return new Skip();
        }
        return fail(t, expected);
    }

    private Rule rule() {
        Token kw = next();
        ruleLine = kw.line();
        try {
            Token n = ruleToken();
            String ruleName;
            if (n != null && n.kind() == Kind.NUMBER) {
                next();
                ruleName = n.text().replaceFirst("^[+]?0*(?=\\d)", "");
            } else if (n != null && n.kind() == Kind.WORD) {
                ruleName = next().text();
            } else {
                throw ruleFail("a rule number or name");
            }
            Token colon = ruleToken();
            if (colon == null || colon.kind() != Kind.COLON) {
                throw ruleFail("':'");
            }
            next();
            ruleExpectWord("IF");
            Condition condition = orCondition(0);
            ruleExpectWord("THEN");
            List<Subconclusion> conclusion = conclusion();
            Token end = ruleToken();
            if (end != null && end.kind() == Kind.SEMI) {
                next();
            } else if (fuzzylite && end == null) {
                feature(Feature.O_RULE_WITHOUT_SEMICOLON, at(kw));
            } else if (end == null || end.kind() == Kind.EOF) {
                throw fail(peek(), "';' at the end of the rule");
            } else {
                throw fail(end, "';' at the end of the rule");
            }
            return new Rule(ruleName, condition, conclusion, at(kw));
        } finally {
            ruleLine = 0;
        }
    }

    private Condition orCondition(int depth) {
        Token first = ruleToken();
        List<Condition> operands = new ArrayList<>();
        operands.add(andCondition(depth));
        while (ruleWord("OR")) {
            next();
            Token at = ruleToken();
            Condition operand = andCondition(depth);
            if (!fuzzylite && operand instanceof Condition.And && at != null) {
                warn(at(at), DialectCode.AND_OR_PRIORITY, "jFuzzyLogic reads '... OR " + at.text()
                        + " AND ...' as '(... OR ...) AND ...' (one priority, left to right); fclcert binds AND"
                        + " tighter (Table 6)");
            }
            operands.add(operand);
        }
        return operands.size() == 1 ? operands.get(0) : new Condition.Or(operands, at(first));
    }

    private Condition andCondition(int depth) {
        Token first = ruleToken();
        List<Condition> operands = new ArrayList<>();
        operands.add(factor(depth));
        while (ruleWord("AND")) {
            next();
            operands.add(factor(depth));
        }
        return operands.size() == 1 ? operands.get(0) : new Condition.And(operands, at(first));
    }

    private Condition factor(int depth) {
        Token t = ruleToken();
        if (t == null) {
            throw ruleFail("a condition");
        }
        if (depth > MAX_NESTING) {
            error(t, DialectCode.UNSUPPORTED, "parentheses nested deeper than " + MAX_NESTING);
            throw new Skip();
        }
        if (!fuzzylite && t.is("NOT")) {
            next();
            Condition inner = factor(depth + 1);
            return new Condition.Not(inner, at(t));
        }
        if (t.kind() == Kind.LPAREN) {
            next();
            Condition inner = orCondition(depth + 1);
            Token close = ruleToken();
            if (close == null || close.kind() != Kind.RPAREN) {
                throw ruleFail("')'");
            }
            next();
            return new Condition.Parenthesized(inner, at(t));
        }
        if (t.kind() != Kind.WORD) {
            throw ruleFail("a subcondition 'variable IS term'");
        }
        String variable = next().text();
        if (!ruleWord("IS")) {
            error(t, DialectCode.NOT_IN_DIALECT, library + " does not take a bare variable as a condition;"
                    + " write 'variable " + (fuzzylite ? "is" : "IS") + " term'");
            throw new Skip();
        }
        next();
        List<Hedge> hedges = new ArrayList<>();
        boolean negated = false;
        while (true) {
            Token h = ruleToken();
            if (h == null || h.kind() != Kind.WORD) {
                throw ruleFail("a term");
            }
            Optional<Hedge> hedge = hedge(h);
            if (hedge.isEmpty()) {
                break;
            }
            next();
            if (hedge.get() == Hedge.NOT && hedges.isEmpty() && !negated) {
                negated = true;             // the standard's IS NOT
            } else {
                hedges.add(hedge.get());
            }
            if (hedge.get() == Hedge.ANY) {
                if (negated || hedges.size() > 1) {
                    error(h, DialectCode.UNSUPPORTED, "fclcert reads 'any' only alone ('" + variable + " is any')");
                    throw new Skip();
                }
                return new Condition.TermSubcondition(variable, "", false, hedges, at(t));
            }
        }
        String term = next().text();
        return new Condition.TermSubcondition(variable, term, negated, hedges, at(t));
    }

    /** A hedge word: fuzzylite's six (lower case); jFuzzyLogic writes NOT only (as IS NOT). */
    private Optional<Hedge> hedge(Token h) {
        if (!fuzzylite) {
            return h.is("NOT") ? Optional.of(Hedge.NOT) : Optional.empty();
        }
        for (Hedge x : Hedge.values()) {
            if (h.text().equals(x.word())) {
                return Optional.of(x);
            }
        }
        return Optional.empty();
    }

    private List<Subconclusion> conclusion() {
        List<Token> starts = new ArrayList<>();
        List<String[]> parts = new ArrayList<>();
        while (true) {
            Token v = ruleToken();
            if (v == null || v.kind() != Kind.WORD) {
                throw ruleFail("a subconclusion 'variable IS term'");
            }
            next();
            if (!ruleWord("IS")) {
                error(v, DialectCode.NOT_IN_DIALECT, library + " does not take a bare variable as a conclusion;"
                        + " write 'variable " + (fuzzylite ? "is" : "IS") + " term'");
                throw new Skip();
            }
            next();
            Token term = ruleToken();
            if (term == null || term.kind() != Kind.WORD) {
                throw ruleFail("a term");
            }
            if (fuzzylite && hedge(term).isPresent()) {
                error(term, DialectCode.UNSUPPORTED, "fclcert does not evaluate hedges in conclusions");
                throw new Skip();
            }
            next();
            starts.add(v);
            parts.add(new String[] {v.text(), term.text()});
            Token sep = ruleToken();
            if (fuzzylite && sep != null && sep.is("and")) {
                feature(Feature.O_CONCLUSION_AND, at(sep));
                ruleWord("AND");
                next();
            } else if (!fuzzylite && sep != null && sep.kind() == Kind.COMMA) {
                next();
            } else {
                break;
            }
        }
        Optional<org.fclcert.model.Operand> weight = Optional.empty();
        if (ruleWord("WITH")) {
            next();
            Token w = ruleToken();
            if (w == null || w.kind() != Kind.NUMBER) {
                if (w != null && w.kind() == Kind.WORD) {
                    error(w, DialectCode.NOT_IN_DIALECT, library + " takes a number after WITH, not a variable");
                    throw new Skip();
                }
                throw ruleFail("a weight");
            }
            weight = Optional.of(number(false));
        }
        // the library weighs the whole rule: every subconclusion carries the weight
        List<Subconclusion> out = new ArrayList<>();
        for (int i = 0; i < parts.size(); i++) {
            out.add(new Subconclusion(parts.get(i)[0], Optional.of(parts.get(i)[1]), weight, at(starts.get(i))));
        }
        return out;
    }

    // ---------------------------------------------------------------- fuzzylite post-processing

    /** fuzzylite's ACCU per output, moved to the rule blocks concluding the outputs (the model keeps ACCU there). */
    private List<RuleBlock> moveAccumulations(List<RuleBlock> blocks) {
        List<RuleBlock> out = new ArrayList<>();
        for (RuleBlock rb : blocks) {
            Map<String, Located<AccumulationMethod>> seen = new LinkedHashMap<>();
            for (Rule r : rb.rules()) {
                for (Subconclusion s : r.conclusion()) {
                    Located<AccumulationMethod> a = outputAccu.get(Names.key(s.variable()));
                    if (a != null) {
                        seen.putIfAbsent(Names.key(s.variable()), a);
                    }
                }
            }
            Optional<Located<AccumulationMethod>> accu = rb.accumulation();
            for (Located<AccumulationMethod> a : seen.values()) {
                if (accu.isPresent() && accu.get().value() != a.value()) {
                    error(a.location().line(), a.location().column(), DialectCode.ACCUMULATION_CONFLICT,
                            "ACCU " + a.value() + " differs from ACCU " + accu.get().value() + " of another output"
                                    + " concluded by rule block '" + rb.name() + "'; fclcert holds one ACCU per rule block");
                } else if (accu.isEmpty()) {
                    accu = Optional.of(a);
                }
            }
            out.add(new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), accu, rb.rules(), rb.location()));
        }
        return out;
    }

    /** FCL-W306 when a singleton term of a COGS output is concluded by more than one rule. */
    private void cogsPerRule(FunctionBlock fb) {
        for (Map.Entry<String, SourceLocation> e : cogs.entrySet()) {
            Map<String, Integer> count = new HashMap<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                for (Rule r : rb.rules()) {
                    for (Subconclusion s : r.conclusion()) {
                        if (Names.key(s.variable()).equals(e.getKey())) {
                            count.merge(Names.key(s.term().orElse("")), 1, Integer::sum);
                        }
                    }
                }
            }
            if (count.values().stream().anyMatch(c -> c > 1)) {
                warn(e.getValue(), DialectCode.COGS_PER_RULE, "fuzzylite's COGS counts every rule's degree"
                        + " separately; here a term is concluded by several rules, so fuzzylite's result differs from"
                        + " fclcert's (which accumulates per term first, Table 5)");
            }
        }
    }
}
