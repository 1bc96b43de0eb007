package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Expression;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Hedge;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Term;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;
import org.fclcert.syntax.dialect.DialectReader.Giveaway;

/**
 * fuzzylite's dialect (its FCL exporter of versions 5 and 6, and its importer): {@code //} and {@code #}
 * comments, one statement per line, lower-case rule keywords, rules without {@code ;}, conclusions joined
 * by {@code and}, ACCU inside DEFUZZIFY, shapes by class name ({@link ShapeNames#FUZZYLITE}), Takagi–Sugeno
 * terms ({@code Constant}, {@code Linear}, {@code Function}), {@code Discrete}, {@code RANGE := (-inf .. inf)},
 * {@code ENABLED}, {@code LOCK}, {@code DEFAULT := nan [| NC]}, its hedges, ACCU ASUM and SUM, METHOD MM and
 * COGSS, unnamed RULEBLOCKs and verbatim engine names. An output defuzzified by a weighted average (COGS,
 * COGSS) whose ACCU is left out adds every rule's degree, which is ACCU SUM.
 */
class FuzzyliteDialect extends LibraryDialect {
    private static final DialectLexer.Style STYLE = new DialectLexer.Style(true, false, true, "fuzzylite");

    @Override
    Dialect dialect() {
        return Dialect.FUZZYLITE;
    }

    @Override
    DialectLexer.Style lexing() {
        return STYLE;
    }

    @Override
    ShapeNames.Table shapes() {
        return ShapeNames.FUZZYLITE;
    }

    @Override
    void checkKeyword(DialectParser p, Token t, String word) {
        if (!t.text().equals(word) && !t.text().equals(word.toLowerCase(Locale.ROOT))) {
            p.error(t, DialectCode.NOT_IN_DIALECT, "fuzzylite reads '" + word + "' only in upper case");
        }
    }

    @Override
    boolean infinities() {
        return true;
    }

    @Override
    boolean fuzzifyStatement(DialectParser p, Token t) {
        if (t.is("ENABLED")) {
            enabled(p);
            return true;
        }
        if (t.is("LOCK")) {
            p.error(t, DialectCode.UNSUPPORTED, "fclcert does not evaluate LOCK on an input");
            throw new DialectParser.Skip();
        }
        return false;
    }

    @Override
    boolean defuzzifyStatement(DialectParser p, Token t, DialectParser.Output out) {
        if (t.is("ACCU")) {
            Optional<Located<AccumulationMethod>> a = p.accumulation();
            if (a.isPresent()) {
                out.accumulation = a;
                p.feature(Feature.O_ACCU_IN_DEFUZZIFY, p.at(t));
            }
            return true;
        }
        if (t.is("ENABLED")) {
            enabled(p);
            return true;
        }
        if (!t.is("LOCK")) {
            return false;
        }
        p.next();
        p.expect(Kind.COLON, "':'");
        do {
            Token w = p.peek();
            String what = p.name();
            if (what.equals("PREVIOUS")) {
                out.keepPrevious = p.at(w);
                p.feature(Feature.O_LOCK_PREVIOUS, p.at(w));
            } else if (what.equals("RANGE")) {
                p.feature(Feature.O_LOCK_RANGE, p.at(w));
            } else {
                p.error(w, DialectCode.SYNTAX, "LOCK takes PREVIOUS and/or RANGE, not '" + what + "'");
            }
        } while (p.peek().kind() == Kind.COMMA && p.next() != null);
        p.expect(Kind.SEMI, "';'");
        return true;
    }

    @Override
    boolean ruleBlockStatement(DialectParser p, Token t) {
        if (t.is("ENABLED")) {
            enabled(p);
            return true;
        }
        return false;
    }

    private static void enabled(DialectParser p) {
        Token kw = p.next();
        p.expect(Kind.COLON, "':'");
        Token v = p.peek();
        String value = p.name();
        p.expect(Kind.SEMI, "';'");
        if (value.equals("FALSE") || value.equals("false")) {
            p.error(v, DialectCode.UNSUPPORTED, "fclcert does not evaluate disabled parts (ENABLED : FALSE)");
        } else if (!value.equals("TRUE") && !value.equals("true")) {
            p.error(v, DialectCode.SYNTAX, "ENABLED takes TRUE or FALSE, not '" + value + "'");
        }
        p.feature(Feature.O_ENABLED, p.at(kw));
    }

    @Override
    String defuzzifyStatements() {
        return "TERM, RANGE, METHOD, DEFAULT, ACCU, LOCK or END_DEFUZZIFY";
    }

    @Override
    Optional<DefuzzificationMethod> method(DialectParser p, Token w, String upper) {
        if (!w.text().equals(upper)) {
            p.error(w, DialectCode.NOT_IN_DIALECT, "fuzzylite reads methods in upper case only, not '" + w.text() + "'");
        }
        return Optional.ofNullable(switch (upper) {
            case "COG" -> DefuzzificationMethod.COG;
            case "COGS" -> DefuzzificationMethod.COGS;
            case "COGSS" -> DefuzzificationMethod.COGSS;
            case "COA" -> DefuzzificationMethod.COA;
            case "LM" -> DefuzzificationMethod.LM;
            case "RM" -> DefuzzificationMethod.RM;
            case "MM" -> {
                p.feature(Feature.O_METHOD_MM, p.at(w));
                p.warn(p.at(w), DialectCode.FIRST_PLATEAU, "fuzzylite's MM is the middle of the first plateau of"
                        + " maximum (sampled); fclcert's MoM the mean of every maximal point: they differ when the"
                        + " maximum is reached on separate intervals");
                yield DefuzzificationMethod.MOM;
            }
            default -> null;
        });
    }

    @Override
    String methodNames() {
        return "COG, COA, LM, RM, MM, COGS, COGSS";
    }

    /**
     * The word fuzzylite's FCL reads for the accumulation fclcert's tables call {@code name} ({@code SUM}: the class
     * name {@code UnboundedSum}, its FCL having no word for it); the FLL and FIS readers restate ACCU with it.
     */
    static String accumulationWord(String name) {
        return name.equals("SUM") ? "UnboundedSum" : name;
    }

    @Override
    Optional<AccumulationMethod> accumulation(String upper) {
        return Optional.ofNullable(switch (upper) {
            case "MAX" -> AccumulationMethod.MAX;
            case "BSUM" -> AccumulationMethod.BSUM;
            case "NSUM" -> AccumulationMethod.NSUM;
            // fuzzylite's FCL has no word for the unbounded sum: its importer hands an unknown name to the s-norm
            // factory, which knows the class name (fuzzylite 6.0 refuses "SUM": "SNorm <SUM> not registered")
            case "UNBOUNDEDSUM" -> AccumulationMethod.SUM;
            case "ASUM" -> AccumulationMethod.PROBOR;
            case "ESUM" -> AccumulationMethod.ESUM;
            case "HSUM" -> AccumulationMethod.HSUM;
            case "DSUM" -> AccumulationMethod.DSUM;
            case "NMAX" -> AccumulationMethod.NMAX;
            default -> null;
        });
    }

    @Override
    boolean otherActivations() {
        return true;
    }

    @Override
    String activationNames() {
        return "MIN, PROD, BDIF, EPROD, HPROD, DPROD, NMIN";
    }

    @Override
    String andNames() {
        return "MIN, PROD, BDIF, EPROD, HPROD, DPROD, NMIN";
    }

    @Override
    String orNames() {
        return "MAX, ASUM, BSUM, ESUM, HSUM, DSUM, NMAX";
    }

    @Override
    boolean hedgesInConclusions() {
        return true;
    }

    @Override
    String accumulationNames() {
        return "MAX, BSUM, NSUM, ASUM, UnboundedSum, ESUM, HSUM, DSUM, NMAX";
    }

    @Override
    Optional<MembershipFunction> specialTerm(DialectParser p, Token t, DialectParser.TermContext where) {
        switch (t.text()) {
            case "Discrete" -> {
                List<Point> pts = new ArrayList<>();
                while (p.peek().kind() == Kind.NUMBER) {
                    Token x = p.peek();
                    Literal xv = p.number(false);
                    Literal yv = p.number(false);
                    pts.add(new Point(xv, yv, p.at(x)));
                }
                p.feature(Feature.O_SHAPE_DISCRETE, p.at(t));
                return Optional.of(new MembershipFunction.Points(pts));
            }
            case "Constant" -> {
                Token v = p.peek();
                Literal value = p.number(false);
                return Optional.of(tsTerm(p, t, where, new Expression.Number(value.value()), "Constant " + v.text()));
            }
            case "Linear" -> {
                List<Token> written = new ArrayList<>();
                while (p.peek().kind() == Kind.NUMBER) {
                    written.add(p.peek());
                    p.number(false);
                }
                return Optional.of(linear(p, t, where, written));
            }
            case "Function" -> {
                if (p.peek().kind() != Kind.EXPRESSION) {
                    throw p.fail(p.peek(), "a formula");
                }
                return Optional.of(computed(p, t, p.next(), where, "Function"));
            }
            default -> {
                return Optional.empty();
            }
        }
    }

    /** fuzzylite's Linear: one coefficient per input in declaration order, then an optional constant. */
    private static MembershipFunction linear(DialectParser p, Token t, DialectParser.TermContext where, List<Token> c) {
        List<Variable> inputs = p.variables.stream().filter(v -> v.kind() == VariableKind.INPUT).toList();
        if (c.size() != inputs.size() && c.size() != inputs.size() + 1) {
            p.error(t, DialectCode.SYNTAX, "a Linear term takes one coefficient per input (" + inputs.size()
                    + ") and an optional constant, not " + c.size() + " numbers");
            throw new DialectParser.Skip();
        }
        Expression e = new Expression.Number(c.size() > inputs.size() ? Double.parseDouble(c.get(inputs.size()).text()) : 0);
        for (int i = inputs.size() - 1; i >= 0; i--) {
            if (Double.parseDouble(c.get(i).text()) == 0) {
                continue;                   // 0 · x adds nothing (and keeps a constant Linear a constant)
            }
            e = new Expression.Binary('+', new Expression.Binary('*',
                    new Expression.Number(Double.parseDouble(c.get(i).text())),
                    new Expression.Variable(inputs.get(i).name())), e);
        }
        StringBuilder written = new StringBuilder("Linear");
        c.forEach(x -> written.append(' ').append(x.text()));
        return tsTerm(p, t, where, e, written.toString());
    }

    /** A {@code Function} / {@code function} term: its formula over the variables declared so far. */
    static MembershipFunction computed(DialectParser p, Token t, Token formula, DialectParser.TermContext where,
            String word) {
        Set<String> names = new LinkedHashSet<>();
        p.variables.forEach(v -> names.add(v.name()));
        try {
            return tsTerm(p, t, where, ExpressionParser.parse(formula.text(), names), word + " " + formula.text());
        } catch (IllegalArgumentException e) {
            p.error(formula, DialectCode.SYNTAX, "the formula '" + formula.text() + "': " + e.getMessage());
            throw new DialectParser.Skip();
        }
    }

    private static MembershipFunction tsTerm(DialectParser p, Token t, DialectParser.TermContext where, Expression e,
            String written) {
        if (where == DialectParser.TermContext.INPUT) {
            p.error(t, DialectCode.UNSUPPORTED, "a " + t.text() + " term in an input: fclcert evaluates Takagi-Sugeno"
                    + " terms only as output terms");
            throw new DialectParser.Skip();
        }
        p.feature(Feature.O_TAKAGI_SUGENO, p.at(t));
        return new MembershipFunction.Computed(e, written);
    }

    @Override
    boolean oneLineStatements() {
        return true;
    }

    @Override
    boolean lowerCaseRuleKeywords() {
        return true;
    }

    @Override
    Optional<Hedge> hedge(Token h) {
        for (Hedge x : Hedge.values()) {
            if (h.text().equals(x.word())) {
                return Optional.of(x);
            }
        }
        return Optional.empty();
    }

    @Override
    boolean conclusionSeparator(DialectParser p, Token t) {
        if (!t.is("and")) {
            return false;
        }
        if (!t.text().equals("and")) {
            p.error(t, DialectCode.NOT_IN_DIALECT, "fuzzylite silently drops a rule that writes '" + t.text()
                    + "': its rule keywords are lower case ('and')");
        }
        p.feature(Feature.O_CONCLUSION_AND, p.at(t));
        return true;
    }

    @Override
    void finishOutput(DialectParser p, DialectParser.Output out) {
        tsukamoto(p, out);
        emptyRangeOfAWeightedAverage(p, out);
        if (out.keepPrevious != null) {
            p.warn(out.keepPrevious, DialectCode.LOCK_PREVIOUS, "keeping the previous value is read as DEFAULT NC:"
                    + " fuzzylite keeps the previous result but gives the DEFAULT before the first one, fclcert the"
                    + " initial value (0)");
            out.defaultValue = Optional.of(new DefaultValue.NoChange(out.keepPrevious));
        }
    }

    /**
     * fuzzylite's weighted averages infer their kind from the output's first term: a monotonic shape (Ramp,
     * Sigmoid, SShape, ZShape, Concave) makes COGS Tsukamoto's method, each term inverted at its degree. Read as
     * {@link DefuzzificationMethod#TSUKAMOTO} when every term is monotonic; fuzzylite's 6.0 inverses of SShape,
     * ZShape and Concave are wrong on part of their range (fixed in 7), which FCL-W312 says at the term.
     */
    private static void tsukamoto(DialectParser p, DialectParser.Output out) {
        if (out.method.isEmpty() || out.terms.isEmpty() || !monotonicShape(out.terms.get(0))) {
            return;
        }
        Located<DefuzzificationMethod> m = out.method.get();
        if (m.value() != DefuzzificationMethod.COGS) {
            if (m.value() == DefuzzificationMethod.COGSS) {
                p.error(m.location().line(), m.location().column(), DialectCode.UNSUPPORTED, "COGSS on the monotonic"
                        + " terms of '" + out.variable + "' is fuzzylite's weighted sum of Tsukamoto points, which"
                        + " fclcert does not evaluate (COGS, their weighted average, it does)");
            }
            return;
        }
        for (Term t : out.terms) {
            if (!monotonicShape(t)) {
                p.error(t.location().line(), t.location().column(), DialectCode.UNSUPPORTED, "term '" + t.name()
                        + "' of '" + out.variable + "' is not monotonic: fuzzylite's COGS here is Tsukamoto's method"
                        + " (its first term is monotonic), which inverts every term at its degree");
                return;
            }
        }
        out.method = Optional.of(new Located<>(DefuzzificationMethod.TSUKAMOTO, m.location()));
        List<String> wrong = new ArrayList<>();
        for (Term t : out.terms) {
            ShapeKind k = ((MembershipFunction.NamedShape) t.function()).kind();
            if (k == ShapeKind.S_SHAPE || k == ShapeKind.Z_SHAPE || k == ShapeKind.CONCAVE) {
                wrong.add("'" + t.name() + "'");
            }
        }
        if (!wrong.isEmpty()) {
            p.warn(m.location(), DialectCode.TSUKAMOTO_INVERSE, "fuzzylite 6.0 inverts SShape (above degree 0.5),"
                    + " ZShape (below 0.5) and Concave terms wrongly in Tsukamoto's method (fixed in fuzzylite 7), here "
                    + String.join(", ", wrong) + " of '" + out.variable + "'; fclcert inverts them exactly");
        }
    }

    /**
     * {@code RANGE := (0 .. 0)} on an output defuzzified by a weighted average of singletons or Takagi–Sugeno terms
     * (fuzzylite's importer of Matlab files writes it): fuzzylite never uses that RANGE, the standard wants min &lt;
     * max (FCL-C023). Read without it, with FCL-W308.
     */
    private static void emptyRangeOfAWeightedAverage(DialectParser p, DialectParser.Output out) {
        boolean average = out.method.map(m -> m.value() == DefuzzificationMethod.COGS
                || m.value() == DefuzzificationMethod.COGSS).orElse(false);
        if (average && out.range.isPresent() && !(out.range.get().min().value() < out.range.get().max().value())
                && out.terms.stream().allMatch(t -> t.function() instanceof MembershipFunction.Singleton
                        || t.function() instanceof MembershipFunction.Computed)) {
            p.warn(out.range.get().location(), DialectCode.TOLERATED, "RANGE of '" + out.variable + "' is empty:"
                    + " fuzzylite's weighted average never uses it, so it is left out; the standard wants the minimum"
                    + " below the maximum (5.2.3)");
            out.range = Optional.empty();
        }
    }

    private static boolean monotonicShape(Term t) {
        return t.function() instanceof MembershipFunction.NamedShape s && s.kind().monotonic();
    }

    @Override
    void finishRuleBlock(DialectParser p, DialectParser.Block b) {
        if (b.and.isPresent() && b.or.isPresent() && b.and.get().value().pair() != b.or.get().value()) {
            p.warn(b.start, DialectCode.TOLERATED, "AND: " + b.and.get().value() + " with OR: " + b.or.get().value()
                    + ": fuzzylite evaluates each as written, and so does fclcert here; the standard pairs them"
                    + " (Table 3: with AND: " + b.and.get().value() + " goes OR: " + b.and.get().value().pair() + ")");
            p.feature(Feature.O_UNPAIRED_OPERATORS, b.start);
        }
    }

    @Override
    FunctionBlock finishFunctionBlock(DialectParser p, FunctionBlock fb) {
        List<RuleBlock> blocks = moveAccumulations(p, fb.ruleBlocks());
        FunctionBlock out = new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(),
                blocks, fb.options(), fb.location());
        cogsPerRule(p, out);
        outputConditions(p, out);
        weights(p, out);
        return out;
    }

    /** FCL-W310 at each weighted rule whose weight fclcert applies after ACT MIN to a fuzzy-set output. */
    private static void weights(DialectParser p, FunctionBlock fb) {
        for (RuleBlock rb : fb.ruleBlocks()) {
            // fuzzylite activates by T(term, weight x degree): the same as fclcert's weight x T(term, degree) for PROD only
            boolean notProd = rb.activation().map(a -> a.value() != org.fclcert.model.ActivationMethod.PROD).orElse(true);
            String act = rb.activation().map(a -> a.value().name()).orElse("MIN");
            for (Rule r : rb.rules()) {
                for (Subconclusion s : r.conclusion()) {
                    boolean weighted = s.weight().map(w -> !(w instanceof Literal l) || l.value() != 1).orElse(false);
                    boolean fuzzySet = fb.defuzzification(s.variable()).map(d -> d.method().map(m -> m.value()
                            != DefuzzificationMethod.TSUKAMOTO).orElse(true) && d.terms().stream().anyMatch(t ->
                            !(t.function() instanceof MembershipFunction.Singleton)
                                    && !(t.function() instanceof MembershipFunction.Computed))).orElse(false);
                    if (weighted && !s.hedges().isEmpty()) {
                        p.warn(s.location(), DialectCode.WEIGHT_BEFORE_ACTIVATION, "rule " + r.name() + ": fuzzylite"
                                + " hedges the weighted degree of '" + s.variable() + "', h(weight x degree); fclcert"
                                + " weighs the hedged degree, weight x h(degree), so the results differ");
                    } else if (notProd && weighted && fuzzySet) {
                        p.warn(s.location(), DialectCode.WEIGHT_BEFORE_ACTIVATION, "rule " + r.name() + ": fuzzylite"
                                + " activates '" + s.variable() + "' by " + act + "(term, weight x degree); fclcert"
                                + " weighs the activated set, weight x " + act + "(term, degree), so the results differ");
                    }
                }
            }
        }
    }

    /**
     * 'output is term' in a condition: fuzzylite takes the degree the term has reached in the output's fuzzy set
     * so far in this evaluation (the rules before, accumulated by the output's ACCU); an Open Level reading the
     * evaluator follows, recorded where written.
     */
    private static void outputConditions(DialectParser p, FunctionBlock fb) {
        Set<String> outputs = new java.util.HashSet<>();
        fb.variables().stream().filter(v -> v.kind() == VariableKind.OUTPUT).forEach(v -> outputs.add(Names.key(v.name())));
        for (RuleBlock rb : fb.ruleBlocks()) {
            for (Rule r : rb.rules()) {
                walk(r.condition(), c -> {
                    if (c instanceof org.fclcert.model.Condition.TermSubcondition t && !t.any()
                            && outputs.contains(Names.key(t.variable())) && fb.defuzzification(t.variable())
                            .map(d -> d.terms().stream().anyMatch(x -> Names.same(x.name(), t.term()))).orElse(false)) {
                        p.feature(Feature.O_OUTPUT_CONDITION, t.location());
                    }
                });
            }
        }
    }

    private static void walk(org.fclcert.model.Condition c, java.util.function.Consumer<org.fclcert.model.Condition> f) {
        f.accept(c);
        if (c instanceof org.fclcert.model.Condition.And a) {
            a.operands().forEach(x -> walk(x, f));
        } else if (c instanceof org.fclcert.model.Condition.Or o) {
            o.operands().forEach(x -> walk(x, f));
        } else if (c instanceof org.fclcert.model.Condition.Not n) {
            walk(n.operand(), f);
        } else if (c instanceof org.fclcert.model.Condition.Parenthesized q) {
            walk(q.inner(), f);
        }
    }

    private static boolean weightedAverage(DialectParser.Output o) {
        return o.method.map(m -> m.value() == DefuzzificationMethod.COGS || m.value() == DefuzzificationMethod.COGSS
                || m.value() == DefuzzificationMethod.TSUKAMOTO).orElse(false);
    }

    /**
     * fuzzylite's ACCU per output, moved to the rule blocks concluding the outputs (the model keeps ACCU there);
     * a block concluding only weighted-average outputs without ACCU gets SUM, fuzzylite's sum over the rules.
     */
    private static List<RuleBlock> moveAccumulations(DialectParser p, List<RuleBlock> blocks) {
        Map<String, DialectParser.Output> byKey = new HashMap<>();
        p.outputs.forEach(o -> byKey.put(Names.key(o.variable), o));
        List<RuleBlock> out = new ArrayList<>();
        for (RuleBlock rb : blocks) {
            Map<String, Located<AccumulationMethod>> seen = new LinkedHashMap<>();
            boolean allWeighted = !rb.rules().isEmpty();
            for (Rule r : rb.rules()) {
                for (Subconclusion s : r.conclusion()) {
                    DialectParser.Output o = byKey.get(Names.key(s.variable()));
                    allWeighted &= o != null && weightedAverage(o);
                    if (o != null && o.accumulation.isPresent()) {
                        seen.putIfAbsent(Names.key(s.variable()), o.accumulation.get());
                    }
                }
            }
            Optional<Located<AccumulationMethod>> accu = rb.accumulation();
            for (Located<AccumulationMethod> a : seen.values()) {
                if (accu.isPresent() && accu.get().value() != a.value()) {
                    p.error(a.location().line(), a.location().column(), DialectCode.ACCUMULATION_CONFLICT,
                            "ACCU " + a.value() + " differs from ACCU " + accu.get().value() + " of another output"
                                    + " concluded by rule block '" + rb.name() + "'; fclcert holds one ACCU per rule block");
                } else if (accu.isEmpty()) {
                    accu = Optional.of(a);
                }
            }
            if (accu.isEmpty() && allWeighted) {
                p.warn(rb.location(), DialectCode.SUPPLIED_SETTING, "no ACCU: fuzzylite's weighted average adds the"
                        + " degree of every rule; read as ACCU SUM");
                p.feature(Feature.O_IMPLICIT_SETTING, rb.location());
                accu = Optional.of(new Located<>(AccumulationMethod.SUM, rb.location()));
            }
            out.add(new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), accu, rb.rules(), rb.location()));
        }
        return out;
    }

    /** FCL-W306 when a term of a weighted-average output is concluded by several rules and not summed. */
    private static void cogsPerRule(DialectParser p, FunctionBlock fb) {
        for (DialectParser.Output o : p.outputs) {
            if (!weightedAverage(o) || o.method.get().value() == DefuzzificationMethod.COGSS) {
                continue;
            }
            Map<String, Integer> count = new HashMap<>();
            boolean summed = true;
            for (RuleBlock rb : fb.ruleBlocks()) {
                for (Rule r : rb.rules()) {
                    for (Subconclusion s : r.conclusion()) {
                        if (Names.same(s.variable(), o.variable)) {
                            count.merge(Names.key(s.term().orElse("")), 1, Integer::sum);
                            summed &= rb.accumulation().map(a -> a.value() == AccumulationMethod.SUM).orElse(false);
                        }
                    }
                }
            }
            if (!summed && count.values().stream().anyMatch(c -> c > 1)) {
                SourceLocation at = o.method.get().location();
                p.warn(at, DialectCode.COGS_PER_RULE, "fuzzylite's COGS counts every rule's degree"
                        + " separately" + (o.method.get().value() == DefuzzificationMethod.TSUKAMOTO ? " (and inverts"
                        + " each term at each rule's degree)" : "") + "; here a term is concluded by several rules, so"
                        + " fuzzylite's result differs from fclcert's (which accumulates per term first, Table 5)");
            }
        }
    }

    /**
     * fuzzylite's giveaways: its class names after ':=' (3), {@code #} comments (2), hedges after {@code is}
     * (2), ENABLED / LOCK (3), nan / inf (3), COGSS (3), ACCU inside DEFUZZIFY (2: FFLL misplaces it too),
     * rules without ';' (1 each rule), RULEBLOCK without a name (1); lower-case rule keywords are standard
     * FCL, so they only support other evidence (weight 0, see {@link DialectReaders.Evidence#weight}).
     */
    @Override
    List<Giveaway> giveaways(Giveaways.Scan scan) {
        List<Giveaway> out = new ArrayList<>();
        scan.comments("#").forEach(line -> out.add(new Giveaway("'#' comment", line, 2)));
        List<Token> t = scan.tokens();
        boolean inDefuzzify = false;
        for (int i = 0; i < t.size(); i++) {
            Token tok = t.get(i);
            Token prev = i > 0 ? t.get(i - 1) : null;
            Token next = i + 1 < t.size() ? t.get(i + 1) : tok;
            if (tok.is("DEFUZZIFY")) {
                inDefuzzify = true;
            } else if (tok.is("END_DEFUZZIFY")) {
                inDefuzzify = false;
            }
            if (tok.kind() != Kind.WORD && tok.kind() != Kind.NUMBER) {
                continue;
            }
            String w = tok.text();
            boolean afterAssign = prev != null && prev.kind() == Kind.ASSIGN;
            if (afterAssign && shapes().known(w)) {
                out.add(new Giveaway("shape '" + w + "'", tok.line(), 3));
            } else if (prev != null && prev.text().equals("is") && hedge(tok).filter(h -> h != Hedge.NOT).isPresent()) {
                out.add(new Giveaway("hedge '" + w + "'", tok.line(), 2));
            } else if ((w.equals("ENABLED") || w.equals("LOCK")) && next.kind() == Kind.COLON) {
                out.add(new Giveaway("'" + w + "'", tok.line(), 3));
            } else if (w.equals("nan") || w.endsWith("inf") && (tok.kind() == Kind.NUMBER || w.equals("inf"))) {
                out.add(new Giveaway("'" + w + "'", tok.line(), 3));
            } else if (prev != null && prev.kind() == Kind.COLON && w.equals("COGSS")) {
                out.add(new Giveaway("METHOD COGSS", tok.line(), 3));
            } else if (inDefuzzify && w.equals("ACCU")) {
                out.add(new Giveaway("ACCU inside DEFUZZIFY", tok.line(), 2));
            } else if (w.equals("RULE") && Giveaways.ruleWithoutSemicolon(t, i)) {
                out.add(new Giveaway("rule without ';'", tok.line(), 1));
            } else if (w.equals("if") && prev != null && prev.kind() == Kind.COLON) {
                out.add(new Giveaway("lower-case rule keywords", tok.line(), 0));
            } else if (w.equals("RULEBLOCK") && (next.line() != tok.line())) {
                out.add(new Giveaway("RULEBLOCK without a name", tok.line(), 1));
            }
        }
        return out;
    }
}
