package org.fclcert.fuzz;

import java.math.BigDecimal;
import java.math.MathContext;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.UnaryOperator;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.iut.IutException;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Operand;
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
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;

/**
 * Reduces a disagreement to a minimal case by delta debugging on the model: it tries, greedily and again
 * after every success, fewer steps, rule blocks, rules, outputs, inputs, local variables, terms,
 * subconclusions and points; simpler conditions; the Basic Level settings (ACCU MAX, AND MIN, no ACT, no
 * RANGE, no WITH, a DEFAULT constant); and rounder numbers. A candidate is kept only when it is valid
 * (strict reader and checks), all its steps are fair, it can still be presented as the run presents programs
 * ({@code --present-as}), the implementation still deviates in the same way (the same kind; for a refusal, the
 * same message but for its numbers), it has no more degenerate shapes
 * than before ({@link #degeneracies}), and it is smaller ({@link #measure}), so the search ends.
 */
final class Shrinker {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;
    private static final CanonicalWriter WRITER = new CanonicalWriter();
    private static final Set<Feature> BASELINE = Set.of(Feature.B_FB, Feature.B_IN_TERM, Feature.B_OUT_SINGLETON,
            Feature.B_AND_MIN, Feature.B_ACCU_MAX, Feature.B_COGS, Feature.B_DEFAULT_VALUE, Feature.B_ONE_RULEBLOCK,
            Feature.B_SUBCONDITIONS, Feature.B_ONE_SUBCONCLUSION);

    /** A program with its steps; the program is one the strict reader produced. */
    record Case(Program program, List<Map<String, Double>> steps) {
        FunctionBlock block() {
            return program.functionBlocks().get(0);
        }
    }

    /** The result: the smallest case found, its deviation, and how many candidates were tried. */
    record Result(Case minimal, Deviation deviation, int tried, int accepted) {
    }

    private final IutSession session;
    private final FairnessJudge fairness;
    private final Presentation presentation;
    private final int maxTrials;
    private final Instant deadline;
    /** True once the run is stopped from outside: the shrink ends with the smallest case found so far. */
    private final java.util.function.BooleanSupplier stopped;
    private int tried;

    Shrinker(IutSession session, FairnessJudge fairness, Presentation presentation, int maxTrials, Instant deadline,
            java.util.function.BooleanSupplier stopped) {
        this.session = session;
        this.fairness = fairness;
        this.presentation = presentation;
        this.maxTrials = maxTrials;
        this.deadline = deadline;
        this.stopped = stopped;
    }

    Result shrink(Case start, Deviation deviation) throws IutException {
        Case current = truncate(start, deviation);
        String refusal = Isolation.signature(deviation);
        Deviation found = deviation;
        long size = measure(current);
        int accepted = 0;
        boolean progress = true;
        while (progress && !exhausted()) {
            progress = false;
            int degenerate = degeneracies(current.program());
            for (Case candidate : candidates(current)) {
                if (exhausted()) {
                    break;
                }
                Optional<Case> valid = validate(candidate);
                if (valid.isEmpty() || measure(valid.get()) >= size || degeneracies(valid.get().program()) > degenerate) {
                    continue;
                }
                Optional<Deviation> d = test(valid.get(), deviation.kind())
                        .filter(x -> Isolation.valueKind(x.kind()) || Isolation.signature(x).equals(refusal));
                if (d.isPresent()) {
                    current = truncate(valid.get(), d.get());
                    found = d.get();
                    size = measure(current);
                    accepted++;
                    progress = true;
                    break;
                }
            }
        }
        return new Result(current, found, tried, accepted);
    }

    private boolean exhausted() {
        return tried >= maxTrials || Instant.now().isAfter(deadline) || stopped.getAsBoolean();
    }

    /** Steps after the failing one do not matter. */
    private static Case truncate(Case c, Deviation d) {
        int keep = d.step() < 0 ? 1 : d.step() + 1;
        return c.steps().size() <= keep ? c : new Case(c.program(), List.copyOf(c.steps().subList(0, keep)));
    }

    /**
     * The degenerate shapes in a program: vertical edges (two points of a term at one x) and terms that are 0
     * everywhere. Rounding a number or dropping a point easily makes one, and implementations differ on them
     * (fuzzylite's degree at a vertical edge, the maximum of an empty set), so a candidate that gains one could
     * keep deviating for that reason instead of the one being shrunk; the shrinker never accepts such a
     * candidate. A case that had one from the start keeps it, so a deviation on them is still found and shrunk.
     */
    static int degeneracies(Program p) {
        int n = 0;
        FunctionBlock fb = p.functionBlocks().get(0);
        List<Term> terms = new ArrayList<>();
        fb.fuzzifications().forEach(f -> terms.addAll(f.terms()));
        fb.defuzzifications().forEach(d -> terms.addAll(d.terms()));
        for (Term t : terms) {
            if (!(t.function() instanceof MembershipFunction.Points pts)) {
                continue;
            }
            List<Point> points = pts.points();
            boolean zero = true;
            for (int i = 0; i < points.size(); i++) {
                Point pt = points.get(i);
                zero &= pt.degree() instanceof Literal d && d.value() == 0;
                if (i > 0 && pt.x() instanceof Literal x && points.get(i - 1).x() instanceof Literal prev
                        && x.value() == prev.value()) {
                    n++;
                }
            }
            n += zero ? 1 : 0;
        }
        return n;
    }

    /** Smaller is simpler: the program text, the features beyond Table 8's basics, the digits of the steps. */
    static long measure(Case c) {
        long features = new FeatureDetector().detect(c.program()).features().stream().filter(f -> !BASELINE.contains(f))
                .mapToLong(f -> f == Feature.E_COG ? 3 : 4).sum();
        long steps = c.steps().stream().mapToLong(s -> s.values().stream().mapToLong(v -> Double.toString(v).length() + 2).sum()).sum();
        return WRITER.write(c.program()).length() + 10 * features + steps;
    }

    /** Written, read back strictly and checked; the steps restricted to the program's inputs. */
    static Optional<Case> validate(Case c) {
        if (c.block().ruleBlocks().isEmpty() || c.block().variables(VariableKind.OUTPUT).isEmpty()) {
            return Optional.empty();
        }
        String text;
        try {
            text = WRITER.write(c.program());
        } catch (RuntimeException e) {
            return Optional.empty();
        }
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", text);
        if (a.program().isEmpty()) {
            return Optional.empty();
        }
        Program p = a.program().get();
        Set<String> inputs = new LinkedHashSet<>();
        p.functionBlocks().get(0).variables(VariableKind.INPUT).forEach(v -> inputs.add(Names.key(v.name())));
        List<Map<String, Double>> steps = new ArrayList<>();
        for (Map<String, Double> s : c.steps()) {
            Map<String, Double> kept = new LinkedHashMap<>();
            s.forEach((k, v) -> {
                if (inputs.contains(Names.key(k))) {
                    kept.put(k, v);
                }
            });
            steps.add(kept);
        }
        return Optional.of(new Case(p, steps));
    }

    /** The deviation of the same kind on this case (presented as the run presents), if the implementation still shows it. */
    Optional<Deviation> test(Case c, DeviationKind kind) throws IutException {
        tried++;
        ReferenceProgram ref = new ReferenceProgram(c.program());
        List<Map<String, Double>> before = new ArrayList<>();
        for (Map<String, Double> step : c.steps()) {
            if (!fairness.fair(ref, before, step)) {
                return Optional.empty();
            }
            before.add(step);
        }
        List<ReferenceProgram.Step> expected;
        try {
            expected = ref.run(c.steps());
        } catch (EvaluationException e) {
            return Optional.empty();
        }
        Optional<Presentation.Sent> sent = presentation.present(c.program(), expected).sent();
        if (sent.isEmpty()) {
            return Optional.empty();
        }
        return Trial.run(session, ref, sent.get(), expected).filter(d -> d.kind() == kind);
    }

    // ---- candidates, most reducing first

    static List<Case> candidates(Case c) {
        List<Case> out = new ArrayList<>();
        FunctionBlock fb = c.block();
        List<Map<String, Double>> steps = c.steps();
        for (int i = 0; i + 1 < steps.size(); i++) {
            List<Map<String, Double>> fewer = new ArrayList<>(steps);
            fewer.remove(i);
            out.add(new Case(c.program(), fewer));
        }
        List<FunctionBlock> blocks = new ArrayList<>();
        for (int b = 0; b < fb.ruleBlocks().size(); b++) {
            int gone = b;
            blocks.add(rules(fb, (rb, i) -> rb, bs -> remove(bs, gone)));
        }
        for (int b = 1; b < fb.ruleBlocks().size(); b++) {
            blocks.add(merged(fb, b));
        }
        for (int b = 0; b < fb.ruleBlocks().size(); b++) {
            RuleBlock rb = fb.ruleBlocks().get(b);
            for (int r = 0; r < rb.rules().size() && rb.rules().size() > 1; r++) {
                blocks.add(withBlock(fb, b, withRules(rb, remove(rb.rules(), r))));
            }
        }
        for (Variable v : fb.variables(VariableKind.OUTPUT)) {
            blocks.add(withoutOutput(fb, v.name()));
        }
        for (Variable v : fb.variables(VariableKind.INPUT)) {
            blocks.add(withoutInput(fb, v.name()));
        }
        for (Variable v : fb.variables(VariableKind.LOCAL)) {
            blocks.add(withoutInput(fb, v.name()));
        }
        for (Fuzzification f : fb.fuzzifications()) {
            for (Term t : f.terms()) {
                if (f.terms().size() > 1) {
                    blocks.add(withoutInputTerm(fb, f.variable(), t.name()));
                }
            }
        }
        for (Defuzzification d : fb.defuzzifications()) {
            for (Term t : d.terms()) {
                if (d.terms().size() > 1) {
                    blocks.add(withoutOutputTerm(fb, d.variable(), t.name()));
                }
            }
        }
        for (int b = 0; b < fb.ruleBlocks().size(); b++) {
            RuleBlock rb = fb.ruleBlocks().get(b);
            for (int r = 0; r < rb.rules().size(); r++) {
                Rule rule = rb.rules().get(r);
                for (int s = 0; s < rule.conclusion().size(); s++) {
                    Subconclusion sc = rule.conclusion().get(s);
                    if (rule.conclusion().size() > 1) {
                        blocks.add(withRule(fb, b, r, new Rule(rule.name(), rule.condition(), remove(rule.conclusion(), s), rule.location())));
                    }
                    if (sc.weight().isPresent()) {
                        List<Subconclusion> parts = new ArrayList<>(rule.conclusion());
                        parts.set(s, new Subconclusion(sc.variable(), sc.term(), Optional.empty(), sc.location()));
                        blocks.add(withRule(fb, b, r, new Rule(rule.name(), rule.condition(), parts, rule.location())));
                    }
                }
                for (Condition simpler : simplerConditions(rule.condition(), termLeaves(fb))) {
                    blocks.add(withRule(fb, b, r, new Rule(rule.name(), simpler, rule.conclusion(), rule.location())));
                }
            }
        }
        // points
        for (Fuzzification f : fb.fuzzifications()) {
            for (int t = 0; t < f.terms().size(); t++) {
                for (MembershipFunction m : fewerPoints(f.terms().get(t).function())) {
                    blocks.add(withInputTerm(fb, f.variable(), t, m));
                }
            }
        }
        for (Defuzzification d : fb.defuzzifications()) {
            for (int t = 0; t < d.terms().size(); t++) {
                for (MembershipFunction m : fewerPoints(d.terms().get(t).function())) {
                    blocks.add(withOutputTerm(fb, d.variable(), t, m));
                }
            }
        }
        settings(fb, blocks);
        numbers(fb, blocks);
        for (FunctionBlock b : blocks) {
            out.add(new Case(new Program(c.program().sourceName(), List.of(b)), steps));
        }
        for (int i = 0; i < steps.size(); i++) {
            for (Map.Entry<String, Double> e : steps.get(i).entrySet()) {
                for (double v : rounder(e.getValue())) {
                    List<Map<String, Double>> changed = new ArrayList<>(steps);
                    Map<String, Double> step = new LinkedHashMap<>(steps.get(i));
                    step.put(e.getKey(), v);
                    changed.set(i, step);
                    out.add(new Case(c.program(), changed));
                }
            }
        }
        return out;
    }

    private static void settings(FunctionBlock fb, List<FunctionBlock> out) {
        Optional<Located<AccumulationMethod>> max = Optional.of(new Located<>(AccumulationMethod.MAX, AT));
        if (fb.ruleBlocks().stream().anyMatch(rb -> rb.accumulation().map(a -> a.value() != AccumulationMethod.MAX).orElse(false))) {
            out.add(rules(fb, (rb, i) -> new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), max, rb.rules(), rb.location()), bs -> bs));
        }
        for (int b = 0; b < fb.ruleBlocks().size(); b++) {
            RuleBlock rb = fb.ruleBlocks().get(b);
            if (rb.activation().isPresent()) {
                out.add(withBlock(fb, b, new RuleBlock(rb.name(), rb.and(), rb.or(), Optional.empty(), rb.accumulation(), rb.rules(), rb.location())));
            }
            boolean minMax = rb.and().map(a -> a.value() == AndAlgorithm.MIN).orElse(true)
                    && rb.or().map(o -> o.value() == OrAlgorithm.MAX).orElse(true);
            if (!minMax) {
                out.add(withBlock(fb, b, new RuleBlock(rb.name(), Optional.of(new Located<>(AndAlgorithm.MIN, AT)),
                        rb.or().map(o -> new Located<>(OrAlgorithm.MAX, AT)), rb.activation(), rb.accumulation(), rb.rules(), rb.location())));
            }
            if (rb.or().isPresent()) {
                Optional<Located<AndAlgorithm>> and = Optional.of(rb.and().orElse(new Located<>(rb.or().get().value().pair(), AT)));
                out.add(withBlock(fb, b, new RuleBlock(rb.name(), and, Optional.empty(), rb.activation(), rb.accumulation(), rb.rules(), rb.location())));
                // an OR declared but no longer used: AND MIN alone
                out.add(withBlock(fb, b, new RuleBlock(rb.name(), Optional.of(new Located<>(AndAlgorithm.MIN, AT)), Optional.empty(),
                        rb.activation(), rb.accumulation(), rb.rules(), rb.location())));
            }
        }
        for (int d = 0; d < fb.defuzzifications().size(); d++) {
            Defuzzification def = fb.defuzzifications().get(d);
            if (def.range().isPresent()) {
                out.add(withDefuzzification(fb, d, new Defuzzification(def.variable(), Optional.empty(), def.terms(), def.method(), def.defaultValue(), def.location())));
            }
            if (!(def.defaultValue().orElse(null) instanceof DefaultValue.Constant c && c.value().value() == 0)) {
                out.add(withDefuzzification(fb, d, new Defuzzification(def.variable(), def.range(), def.terms(), def.method(),
                        Optional.of(new DefaultValue.Constant(Literal.of(0), AT)), def.location())));
            }
            boolean points = def.terms().stream().anyMatch(t -> t.function() instanceof MembershipFunction.Points);
            if (points && def.method().map(m -> m.value() != DefuzzificationMethod.COG).orElse(false)) {
                out.add(withDefuzzification(fb, d, new Defuzzification(def.variable(), def.range(), def.terms(),
                        Optional.of(new Located<>(DefuzzificationMethod.COG, AT)), def.defaultValue(), def.location())));
            }
        }
        List<Variable> vars = fb.variables();
        for (int i = 0; i < vars.size(); i++) {
            Variable v = vars.get(i);
            if (v.initialValue().isPresent() || v.type() != DataType.REAL) {
                List<Variable> changed = new ArrayList<>(vars);
                changed.set(i, new Variable(v.name(), v.kind(), DataType.REAL, Optional.empty(), v.location()));
                out.add(new FunctionBlock(fb.name(), changed, fb.fuzzifications(), fb.defuzzifications(), fb.ruleBlocks(), fb.options(), fb.location()));
            }
        }
    }

    /** One literal at a time made rounder; variable operands made constant. */
    private static void numbers(FunctionBlock fb, List<FunctionBlock> out) {
        for (Fuzzification f : fb.fuzzifications()) {
            for (int t = 0; t < f.terms().size(); t++) {
                for (MembershipFunction m : rounderFunctions(f.terms().get(t).function())) {
                    out.add(withInputTerm(fb, f.variable(), t, m));
                }
            }
        }
        for (int d = 0; d < fb.defuzzifications().size(); d++) {
            Defuzzification def = fb.defuzzifications().get(d);
            for (int t = 0; t < def.terms().size(); t++) {
                for (MembershipFunction m : rounderFunctions(def.terms().get(t).function())) {
                    out.add(withOutputTerm(fb, def.variable(), t, m));
                }
            }
            if (def.range().isPresent()) {
                Range r = def.range().get();
                for (double v : rounder(r.min().value())) {
                    out.add(withDefuzzification(fb, d, new Defuzzification(def.variable(), Optional.of(new Range(Literal.of(v), r.max(), AT)),
                            def.terms(), def.method(), def.defaultValue(), def.location())));
                }
                for (double v : rounder(r.max().value())) {
                    out.add(withDefuzzification(fb, d, new Defuzzification(def.variable(), Optional.of(new Range(r.min(), Literal.of(v), AT)),
                            def.terms(), def.method(), def.defaultValue(), def.location())));
                }
            }
        }
        for (int b = 0; b < fb.ruleBlocks().size(); b++) {
            RuleBlock rb = fb.ruleBlocks().get(b);
            for (int r = 0; r < rb.rules().size(); r++) {
                Rule rule = rb.rules().get(r);
                for (int s = 0; s < rule.conclusion().size(); s++) {
                    Subconclusion sc = rule.conclusion().get(s);
                    List<Operand> weights = new ArrayList<>();
                    if (sc.weight().orElse(null) instanceof Literal l) {
                        for (double v : rounder(l.value())) {
                            if (v > 0 && v <= 1) {
                                weights.add(Literal.of(v));
                            }
                        }
                    } else if (sc.weight().isPresent()) {
                        weights.add(Literal.of(0.5));
                    }
                    for (Operand w : weights) {
                        List<Subconclusion> parts = new ArrayList<>(rule.conclusion());
                        parts.set(s, new Subconclusion(sc.variable(), sc.term(), Optional.of(w), sc.location()));
                        out.add(withRule(fb, b, r, new Rule(rule.name(), rule.condition(), parts, rule.location())));
                    }
                }
            }
        }
    }

    private static List<MembershipFunction> rounderFunctions(MembershipFunction m) {
        List<MembershipFunction> out = new ArrayList<>();
        if (m instanceof MembershipFunction.Singleton s) {
            if (s.value() instanceof Literal l) {
                rounder(l.value()).forEach(v -> out.add(new MembershipFunction.Singleton(Literal.of(v))));
            } else {
                out.add(new MembershipFunction.Singleton(Literal.of(0)));
            }
            return out;
        }
        if (!(m instanceof MembershipFunction.Points p)) {
            return out;
        }
        List<Point> points = p.points();
        for (int i = 0; i < points.size(); i++) {
            Point pt = points.get(i);
            List<Point> xs = new ArrayList<>();
            if (pt.x() instanceof Literal l) {
                rounder(l.value()).forEach(v -> xs.add(new Point(Literal.of(v), pt.degree(), AT)));
            } else {
                double neighbour = i > 0 && points.get(i - 1).x() instanceof Literal l ? l.value() : 0;
                xs.add(new Point(Literal.of(neighbour), pt.degree(), AT));
                if (i + 1 < points.size() && points.get(i + 1).x() instanceof Literal next) {
                    xs.add(new Point(Literal.of((neighbour + next.value()) / 2), pt.degree(), AT));
                }
            }
            if (pt.degree() instanceof Literal d) {
                for (double v : new double[] {0, 1}) {
                    if (d.value() != v) {
                        xs.add(new Point(pt.x(), Literal.of(v), AT));
                    }
                }
            } else {
                xs.add(new Point(pt.x(), Literal.of(1), AT));
            }
            for (Point changed : xs) {
                List<Point> copy = new ArrayList<>(points);
                copy.set(i, changed);
                out.add(new MembershipFunction.Points(copy));
            }
        }
        return out;
    }

    private static List<MembershipFunction> fewerPoints(MembershipFunction m) {
        List<MembershipFunction> out = new ArrayList<>();
        if (m instanceof MembershipFunction.Points p && p.points().size() > 2) {
            for (int i = 0; i < p.points().size(); i++) {
                out.add(new MembershipFunction.Points(remove(p.points(), i)));
            }
        }
        return out;
    }

    /** Integers and short decimals near v, shortest first (none when v is already as round). */
    static List<Double> rounder(double v) {
        Set<Double> out = new LinkedHashSet<>();
        out.add(0.0);
        out.add((double) Math.round(v));
        out.add(Math.round(v * 10) / 10.0);
        if (v != 0) {
            out.add(new BigDecimal(v).round(new MathContext(1)).doubleValue());
            out.add(new BigDecimal(v).round(new MathContext(2)).doubleValue());
        }
        int length = Double.toString(v).length();
        List<Double> shorter = new ArrayList<>();
        for (double x : out) {
            if (x != v && Double.toString(x).length() <= length) {
                shorter.add(x);
            }
        }
        return shorter;
    }

    /** A few {@code x IS t} subconditions of the block's inputs, to stand in for a bare variable. */
    private static List<Condition> termLeaves(FunctionBlock fb) {
        List<Condition> out = new ArrayList<>();
        for (Fuzzification f : fb.fuzzifications()) {
            for (Term t : f.terms()) {
                if (out.size() < 6) {
                    out.add(new Condition.TermSubcondition(f.variable(), t.name(), false, AT));
                }
            }
        }
        return out;
    }

    /** Block {@code b}'s rules moved into the block before it, all renumbered. */
    private static FunctionBlock merged(FunctionBlock fb, int b) {
        List<RuleBlock> blocks = new ArrayList<>(fb.ruleBlocks());
        RuleBlock into = blocks.get(b - 1);
        List<Rule> rules = new ArrayList<>(into.rules());
        rules.addAll(blocks.get(b).rules());
        List<Rule> numbered = new ArrayList<>();
        for (int i = 0; i < rules.size(); i++) {
            Rule r = rules.get(i);
            numbered.add(new Rule(Integer.toString(i + 1), r.condition(), r.conclusion(), r.location()));
        }
        blocks.set(b - 1, withRules(into, numbered));
        blocks.remove(b);
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(), blocks, fb.options(), fb.location());
    }

    private static List<Condition> simplerConditions(Condition root, List<Condition> termLeaves) {
        List<Condition> out = new ArrayList<>();
        List<Condition> nodes = ConditionTrees.nodes(root);
        for (int i = 1; i < nodes.size(); i++) {
            if (!(nodes.get(i) instanceof Condition.Parenthesized)) {
                out.add(nodes.get(i));
            }
        }
        for (int i = 0; i < nodes.size(); i++) {
            Condition n = nodes.get(i);
            if (n instanceof Condition.Not not) {
                out.add(ConditionTrees.replace(root, i, not.operand()));
            } else if (n instanceof Condition.Parenthesized p) {
                out.add(ConditionTrees.replace(root, i, p.inner()));
            } else if (n instanceof Condition.VariableSubcondition) {
                for (Condition leaf : termLeaves) {
                    out.add(ConditionTrees.replace(root, i, leaf));
                }
            } else if (n instanceof Condition.TermSubcondition t && t.negated()) {
                out.add(ConditionTrees.replace(root, i, new Condition.TermSubcondition(t.variable(), t.term(), false, t.hedges(), AT)));
            } else if (n instanceof Condition.And || n instanceof Condition.Or) {
                List<Condition> ops = ConditionTrees.children(n);
                for (int j = 0; j < ops.size(); j++) {
                    List<Condition> rest = remove(ops, j);
                    Condition c = rest.size() == 1 ? rest.get(0)
                            : n instanceof Condition.And ? new Condition.And(rest, AT) : new Condition.Or(rest, AT);
                    out.add(ConditionTrees.replace(root, i, c));
                }
            }
        }
        return out;
    }

    // ---- model edits

    private static FunctionBlock withoutOutput(FunctionBlock fb, String name) {
        List<Variable> vars = fb.variables().stream().filter(v -> !Names.same(v.name(), name)).toList();
        List<Defuzzification> defs = fb.defuzzifications().stream().filter(d -> !Names.same(d.variable(), name)).toList();
        FunctionBlock without = new FunctionBlock(fb.name(), vars, fb.fuzzifications(), defs, fb.ruleBlocks(), fb.options(), fb.location());
        return mapConclusions(without, s -> Names.same(s.variable(), name) ? null : s);
    }

    /** Without an input (or local): its FUZZIFY, its subconditions, the weights it gives. */
    private static FunctionBlock withoutInput(FunctionBlock fb, String name) {
        List<Variable> vars = fb.variables().stream().filter(v -> !Names.same(v.name(), name)).toList();
        List<Fuzzification> fuzz = fb.fuzzifications().stream().filter(f -> !Names.same(f.variable(), name)).toList();
        FunctionBlock without = new FunctionBlock(fb.name(), vars, fuzz, fb.defuzzifications(), fb.ruleBlocks(), fb.options(), fb.location());
        without = mapConditions(without, leaf -> leaf instanceof Condition.TermSubcondition t && Names.same(t.variable(), name)
                || leaf instanceof Condition.VariableSubcondition v && Names.same(v.variable(), name));
        return mapConclusions(without, s -> Names.same(s.variable(), name) ? null
                : s.weight().orElse(null) instanceof VariableRef r && Names.same(r.name(), name)
                        ? new Subconclusion(s.variable(), s.term(), Optional.empty(), s.location()) : s);
    }

    private static FunctionBlock withoutInputTerm(FunctionBlock fb, String variable, String term) {
        List<Fuzzification> fuzz = fb.fuzzifications().stream().map(f -> !Names.same(f.variable(), variable) ? f
                : new Fuzzification(f.variable(), f.terms().stream().filter(t -> !Names.same(t.name(), term)).toList(), f.location())).toList();
        FunctionBlock without = new FunctionBlock(fb.name(), fb.variables(), fuzz, fb.defuzzifications(), fb.ruleBlocks(), fb.options(), fb.location());
        return mapConditions(without, leaf -> leaf instanceof Condition.TermSubcondition t && Names.same(t.variable(), variable)
                && Names.same(t.term(), term));
    }

    private static FunctionBlock withoutOutputTerm(FunctionBlock fb, String variable, String term) {
        List<Defuzzification> defs = fb.defuzzifications().stream().map(d -> !Names.same(d.variable(), variable) ? d
                : new Defuzzification(d.variable(), d.range(), d.terms().stream().filter(t -> !Names.same(t.name(), term)).toList(),
                        d.method(), d.defaultValue(), d.location())).toList();
        FunctionBlock without = new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), defs, fb.ruleBlocks(), fb.options(), fb.location());
        return mapConclusions(without, s -> Names.same(s.variable(), variable) && s.term().map(t -> Names.same(t, term)).orElse(false) ? null : s);
    }

    /** Conditions with some leaves dropped; a rule left without a condition goes. */
    private static FunctionBlock mapConditions(FunctionBlock fb, java.util.function.Predicate<Condition> drop) {
        return rules(fb, (rb, i) -> withRules(rb, rb.rules().stream().map(r -> ConditionTrees.prune(r.condition(), drop)
                .map(c -> new Rule(r.name(), c, r.conclusion(), r.location()))).flatMap(Optional::stream).toList()), bs -> bs);
    }

    /** Subconclusions mapped (null = dropped); a rule left without a conclusion goes. */
    private static FunctionBlock mapConclusions(FunctionBlock fb, UnaryOperator<Subconclusion> f) {
        return rules(fb, (rb, i) -> withRules(rb, rb.rules().stream().map(r -> {
            List<Subconclusion> parts = r.conclusion().stream().map(f).filter(s -> s != null).toList();
            return parts.isEmpty() ? null : new Rule(r.name(), r.condition(), parts, r.location());
        }).filter(r -> r != null).toList()), bs -> bs);
    }

    /** Every rule block mapped, empty ones dropped, then the list of blocks mapped. */
    private static FunctionBlock rules(FunctionBlock fb, java.util.function.BiFunction<RuleBlock, Integer, RuleBlock> f,
            UnaryOperator<List<RuleBlock>> blocks) {
        List<RuleBlock> mapped = new ArrayList<>();
        for (int i = 0; i < fb.ruleBlocks().size(); i++) {
            mapped.add(f.apply(fb.ruleBlocks().get(i), i));
        }
        List<RuleBlock> kept = blocks.apply(mapped).stream().filter(rb -> !rb.rules().isEmpty()).toList();
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(), kept, fb.options(), fb.location());
    }

    private static FunctionBlock withBlock(FunctionBlock fb, int index, RuleBlock rb) {
        List<RuleBlock> blocks = new ArrayList<>(fb.ruleBlocks());
        blocks.set(index, rb);
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(), blocks, fb.options(), fb.location());
    }

    private static FunctionBlock withRule(FunctionBlock fb, int block, int index, Rule rule) {
        RuleBlock rb = fb.ruleBlocks().get(block);
        List<Rule> rules = new ArrayList<>(rb.rules());
        rules.set(index, rule);
        return withBlock(fb, block, withRules(rb, rules));
    }

    private static RuleBlock withRules(RuleBlock rb, List<Rule> rules) {
        return new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), rb.accumulation(), rules, rb.location());
    }

    private static FunctionBlock withDefuzzification(FunctionBlock fb, int index, Defuzzification d) {
        List<Defuzzification> defs = new ArrayList<>(fb.defuzzifications());
        defs.set(index, d);
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), defs, fb.ruleBlocks(), fb.options(), fb.location());
    }

    private static FunctionBlock withInputTerm(FunctionBlock fb, String variable, int index, MembershipFunction m) {
        List<Fuzzification> fuzz = fb.fuzzifications().stream().map(f -> {
            if (!Names.same(f.variable(), variable)) {
                return f;
            }
            List<Term> terms = new ArrayList<>(f.terms());
            terms.set(index, new Term(terms.get(index).name(), m, AT));
            return new Fuzzification(f.variable(), terms, f.location());
        }).toList();
        return new FunctionBlock(fb.name(), fb.variables(), fuzz, fb.defuzzifications(), fb.ruleBlocks(), fb.options(), fb.location());
    }

    private static FunctionBlock withOutputTerm(FunctionBlock fb, String variable, int index, MembershipFunction m) {
        for (int d = 0; d < fb.defuzzifications().size(); d++) {
            Defuzzification def = fb.defuzzifications().get(d);
            if (Names.same(def.variable(), variable)) {
                List<Term> terms = new ArrayList<>(def.terms());
                terms.set(index, new Term(terms.get(index).name(), m, AT));
                return withDefuzzification(fb, d, new Defuzzification(def.variable(), def.range(), terms, def.method(),
                        def.defaultValue(), def.location()));
            }
        }
        return fb;
    }

    private static <T> List<T> remove(List<T> list, int index) {
        List<T> out = new ArrayList<>(list);
        out.remove(index);
        return out;
    }
}
