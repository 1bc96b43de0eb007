package org.fclcert.write;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.Locale;
import java.util.Set;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.BlockIndex;
import org.fclcert.model.Condition;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Hedge;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Severity;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Term;

/**
 * Turns a program a dialect reader produced into a program of standard FCL (IEC 61131-7 as the strict reader
 * reads it), saying for each non-standard construct whether it converted exactly, approximately (with the
 * largest error) or not at all. {@code fclcert convert} writes the result with the {@link CanonicalWriter}.
 *
 * <p>The conversion is a list of {@link ConstructConversion}s ({@link #CONVERSIONS}), one per kind of
 * construct, applied in order; each rewrites what it knows and reports a {@link Finding} per construct. To
 * teach the converter a new construct, add a conversion to that list, or a case to {@link #convertTerm} for a
 * new kind of membership function. docs/dialects.md, "Conversion to standard FCL", lists what converts how.
 */
public final class StandardConversion {

    /**
     * How to convert: {@code approximatePoints} is the number of equally spaced points a curved membership
     * function (Gaussian, bell, ...) is approximated by, over its variable's RANGE (0: do not approximate;
     * curves are then not expressible).
     */
    public record Options(int approximatePoints) {
        public static final Options DEFAULT = new Options(0);
        /**
         * Most points a curve is approximated by (10 000): every term gets that many points and a
         * bound of its error, so 10^6 took minutes and then the heap; a finer approximation adds nothing
         * an implementation could tell apart.
         */
        public static final int MAX_APPROXIMATE_POINTS = 10_000;

        public Options {
            if (approximatePoints != 0 && (approximatePoints < 2 || approximatePoints > MAX_APPROXIMATE_POINTS)) {
                throw new IllegalArgumentException("approximatePoints must be 0 or 2.." + MAX_APPROXIMATE_POINTS
                        + ", got " + approximatePoints);
            }
        }
    }

    /** How a construct converted. */
    public sealed interface Kind {
        /** Standard FCL says exactly the same. */
        record Exact() implements Kind {
        }

        /** Standard FCL says nearly the same: {@code maxError} is the largest membership error. */
        record Approximated(double maxError) implements Kind {
        }

        /** Standard FCL cannot say it; {@code replacement} says what the converted program has in its place. */
        record NotExpressible(String replacement) implements Kind {
        }
    }

    /** One construct of the original program and how it converted. */
    public record Finding(String construct, SourceLocation location, Kind kind, String message) {
        /**
         * This finding as a diagnostic: {@link ConversionCode#APPROXIMATED} (a warning) or
         * {@link ConversionCode#NOT_EXPRESSIBLE} (an error, a warning when {@code lossyAllowed}); none for an
         * exact conversion, which is a note.
         */
        public Optional<Diagnostic> diagnostic(boolean lossyAllowed) {
            if (kind instanceof Kind.Approximated a) {
                return Optional.of(Diagnostic.of(location, ConversionCode.APPROXIMATED, construct + ": approximated,"
                        + " largest membership error at most " + upTo3Digits(a.maxError()) + ": " + message));
            }
            if (kind instanceof Kind.NotExpressible) {
                return Optional.of(new Diagnostic(location, lossyAllowed ? Severity.WARNING : Severity.ERROR,
                        ConversionCode.NOT_EXPRESSIBLE, construct + " is not expressible in standard FCL: " + message));
            }
            return Optional.empty();
        }
    }

    /** The bound rounded up to 3 significant digits, so that the printed number is still a bound. */
    static String upTo3Digits(double bound) {
        if (!Double.isFinite(bound) || bound == 0) {
            return Double.toString(bound);
        }
        return new java.math.BigDecimal(bound).round(new java.math.MathContext(3, java.math.RoundingMode.UP))
                .stripTrailingZeros().toString();
    }

    /** The standard program and the findings, in source order. */
    public record Result(Program program, List<Finding> findings) {
        public Result {
            findings = List.copyOf(findings);
        }

        /** True when the converted program means exactly what the original does. */
        public boolean exact() {
            return findings.stream().allMatch(f -> f.kind() instanceof Kind.Exact);
        }

        /**
         * True when every construct converted exactly or approximately (with its largest error stated), none
         * is not expressible: what {@code fclcert convert} writes without {@code --allow-lossy}.
         */
        public boolean expressible() {
            return findings.stream().noneMatch(f -> f.kind() instanceof Kind.NotExpressible);
        }
    }

    /** One kind of construct: rewrites it to standard FCL in the program, adding a finding per use. */
    public interface ConstructConversion {
        Program apply(Program program, Options options, List<Finding> findings);
    }

    /** The conversions, applied in this order. */
    static final List<ConstructConversion> CONVERSIONS = List.of(
            StandardConversion::dialectSyntax,
            StandardConversion::terms,
            StandardConversion::hedges,
            StandardConversion::accumulations,
            StandardConversion::methods,
            StandardConversion::defaults,
            StandardConversion::reservedNames);

    /** Reader-recorded constructs another conversion judges (their finding comes from there). */
    private static final Set<Feature> JUDGED_ELSEWHERE = Set.of(Feature.O_DEFAULT_NAN, Feature.O_TAKAGI_SUGENO,
            Feature.O_UNPAIRED_OPERATORS);

    public Result convert(Program program) {
        return convert(program, Options.DEFAULT);
    }

    public Result convert(Program program, Options options) {
        List<Finding> findings = new ArrayList<>();
        Program p = program;
        for (ConstructConversion c : CONVERSIONS) {
            p = c.apply(p, options, findings);
        }
        findings.sort(Comparator.comparing(Finding::location));
        // with nothing converted the blocks are the ones read, and the comments still stand where they were found;
        // a converted program's comments would name elements the conversion replaced, so they are left out (said)
        return new Result(new Program(p.sourceName(), p.functionBlocks())
                .withComments(findings.isEmpty() ? program.comments() : List.of()), findings);
    }

    // ---------------------------------------------------------------- the conversions

    /**
     * Names that are keywords of standard FCL (a dialect reader may give them: an unnamed block is
     * {@code function_block}, jFuzzyLogic names a rule {@code BSUM}): the canonical writer writes each with
     * {@link org.fclcert.syntax.ReservedWords#SUFFIX} at every use; listed here, once per name, as exact.
     */
    private static Program reservedNames(Program program, Options options, List<Finding> findings) {
        for (org.fclcert.model.FunctionBlock fb : program.functionBlocks()) {
            Set<String> seen = new java.util.HashSet<>();
            java.util.function.BiConsumer<String, SourceLocation> check = (name, at) -> {
                if (org.fclcert.syntax.ReservedWords.isReserved(name)
                        && seen.add(name.toUpperCase(java.util.Locale.ROOT))) {
                    findings.add(new Finding("reserved name", at, new Kind.Exact(), "'" + name + "' is a keyword of"
                            + " standard FCL (Table 7): written as '" + org.fclcert.syntax.ReservedWords.unreserved(name)
                            + "' at every use"));
                }
            };
            check.accept(fb.name(), fb.location());
            fb.variables().forEach(v -> check.accept(v.name(), v.location()));
            fb.fuzzifications().forEach(f -> f.terms().forEach(t -> check.accept(t.name(), t.location())));
            fb.defuzzifications().forEach(d -> d.terms().forEach(t -> check.accept(t.name(), t.location())));
            fb.ruleBlocks().forEach(rb -> {
                check.accept(rb.name(), rb.location());
                rb.rules().forEach(r -> check.accept(r.name(), r.location()));
            });
        }
        return program;
    }

    /**
     * Constructs a dialect reader already expressed in the standard model (a term-only subcondition is a
     * 'variable IS term', ACCUM is ACCU, ...): the model is standard, so each converts exactly.
     */
    private static Program dialectSyntax(Program program, Options options, List<Finding> findings) {
        for (FeatureUse u : program.dialectFeatures()) {
            if (JUDGED_ELSEWHERE.contains(u.feature())) {
                continue;
            }
            if (u.feature() == Feature.O_HEDGE_IN_CONCLUSION) {
                findings.add(new Finding(u.feature().id(), u.location(), new Kind.NotExpressible("left out"),
                        "a hedge in a conclusion (applied to the rule's degree): standard conclusions have none"));
                continue;
            }
            if (u.feature() == Feature.O_OUTPUT_CONDITION || u.feature() == Feature.O_OUTPUT_VALUE_CONDITION) {
                findings.add(new Finding(u.feature().id(), u.location(), new Kind.NotExpressible("kept as read"),
                        "a condition on an output's term (" + (u.feature() == Feature.O_OUTPUT_CONDITION ? "the degree"
                        + " it has reached so far" : "its degree at the output's value when the evaluation begins")
                        + "): standard conditions read inputs only (5.2.4)"));
                continue;
            }
            findings.add(new Finding(u.feature().id(), u.location(), new Kind.Exact(),
                    DialectSyntaxText.standardForm(u.feature())));
        }
        return unpairedOperators(program, findings);
    }

    /**
     * AND and OR outside Table 3 (fuzzylite): the one of the two no rule of the block uses is left out (exact);
     * a block whose rules use both has no standard spelling.
     */
    private static Program unpairedOperators(Program program, List<Finding> findings) {
        program = otherNorms(program, findings);
        Set<SourceLocation> at = new java.util.TreeSet<>();     // by place: SourceLocation.equals ignores it
        program.dialectFeatures().stream().filter(u -> u.feature() == Feature.O_UNPAIRED_OPERATORS)
                .forEach(u -> at.add(u.location()));
        if (at.isEmpty()) {
            return program;
        }
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<RuleBlock> rbs = new ArrayList<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                if (!at.contains(rb.location())) {
                    rbs.add(rb);
                    continue;
                }
                boolean usesAnd = rb.rules().stream().anyMatch(r -> uses(r.condition(), true));
                boolean usesOr = rb.rules().stream().anyMatch(r -> uses(r.condition(), false));
                String id = Feature.O_UNPAIRED_OPERATORS.id();
                if (!usesOr) {
                    findings.add(new Finding(id, rb.location(), new Kind.Exact(), "rule block '" + rb.name()
                            + "': OR is left out (no rule uses it)"));
                    rbs.add(new RuleBlock(rb.name(), rb.and(), Optional.empty(), rb.activation(), rb.accumulation(),
                            rb.rules(), rb.location()));
                } else if (!usesAnd) {
                    findings.add(new Finding(id, rb.location(), new Kind.Exact(), "rule block '" + rb.name()
                            + "': AND is left out (no rule uses it)"));
                    rbs.add(new RuleBlock(rb.name(), Optional.empty(), rb.or(), rb.activation(), rb.accumulation(),
                            rb.rules(), rb.location()));
                } else {
                    findings.add(new Finding(id, rb.location(), new Kind.NotExpressible("the pair of its AND"),
                            "rule block '" + rb.name() + "' uses AND " + rb.and().get().value() + " and OR "
                                    + rb.or().get().value() + ", which standard FCL only pairs as Table 3 says"));
                    rbs.add(new RuleBlock(rb.name(), rb.and(), rb.and().map(a -> new Located<>(a.value().pair(),
                            rb.or().get().location())), rb.activation(), rb.accumulation(), rb.rules(), rb.location()));
                }
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(), rbs,
                    fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }

    /**
     * AND / OR outside Table 3 (Einstein, Hamacher, drastic, nilpotent): not expressible; MIN / MAX written. ACT
     * by a t-norm outside Table 4: MIN written, exact where the block activates singletons only.
     */
    private static Program otherNorms(Program program, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        boolean changed = false;
        for (FunctionBlock fb : program.functionBlocks()) {
            BlockIndex names = BlockIndex.of(fb);
            List<RuleBlock> rbs = new ArrayList<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                var and = rb.and();
                var or = rb.or();
                if (and.isPresent() && !and.get().value().standard()) {
                    findings.add(new Finding(Feature.O_OTHER_NORM.id(), and.get().location(),
                            new Kind.NotExpressible("AND : MIN"), "AND " + and.get().value() + " of rule block "
                                    + rb.name() + " is not an algorithm of Table 3"));
                    and = Optional.of(new Located<>(org.fclcert.model.AndAlgorithm.MIN, and.get().location()));
                    changed = true;
                }
                if (or.isPresent() && !or.get().value().standard()) {
                    findings.add(new Finding(Feature.O_OTHER_NORM.id(), or.get().location(),
                            new Kind.NotExpressible("OR : MAX"), "OR " + or.get().value() + " of rule block "
                                    + rb.name() + " is not an algorithm of Table 3"));
                    or = Optional.of(new Located<>(org.fclcert.model.OrAlgorithm.MAX, or.get().location()));
                    changed = true;
                }
                var act = rb.activation();
                if (act.isPresent() && !act.get().value().standard()) {
                    // on singletons every t-norm gives the rule's degree: T(d, 1) = d
                    boolean exact = concludesOnlySingletons(names, rb);
                    findings.add(new Finding(Feature.O_ACT_OTHER_NORM.id(), act.get().location(), exact ? new Kind.Exact()
                            : new Kind.NotExpressible("ACT : MIN"), "ACT " + act.get().value() + " of rule block "
                            + rb.name() + (exact ? " written as MIN: it activates singletons only" : " is not an"
                            + " algorithm of Table 4")));
                    act = Optional.of(new Located<>(org.fclcert.model.ActivationMethod.MIN, act.get().location()));
                    changed = true;
                }
                rbs.add(new RuleBlock(rb.name(), and, or, act, rb.accumulation(), rb.rules(), rb.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(), rbs,
                    fb.options(), fb.location()));
        }
        return changed ? new Program(program.sourceName(), blocks, program.dialectFeatures()) : program;
    }

    private static boolean uses(Condition c, boolean and) {
        if (and ? c instanceof Condition.And : c instanceof Condition.Or) {
            return true;
        }
        if (c instanceof Condition.And a) {
            return a.operands().stream().anyMatch(x -> uses(x, and));
        }
        if (c instanceof Condition.Or o) {
            return o.operands().stream().anyMatch(x -> uses(x, and));
        }
        if (c instanceof Condition.Not n) {
            return uses(n.operand(), and);
        }
        if (c instanceof Condition.Parenthesized p) {
            return uses(p.inner(), and);
        }
        return false;
    }

    /** Every term's membership function in a form of 5.2.2 (points or a singleton). */
    private static Program terms(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<Fuzzification> fuzzifications = new ArrayList<>();
            for (Fuzzification f : fb.fuzzifications()) {
                fuzzifications.add(new Fuzzification(f.variable(), convertTerms(f.terms(), f.declaredRange(),
                        "input " + f.variable(), options, findings), f.location()));
            }
            List<Defuzzification> defuzzifications = new ArrayList<>();
            for (Defuzzification d : fb.defuzzifications()) {
                defuzzifications.add(new Defuzzification(d.variable(), d.range(),
                        convertTerms(d.terms(), d.range(), "output " + d.variable(), options, findings), d.method(),
                        d.defaultValue(), d.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fuzzifications, defuzzifications,
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }

    private static List<Term> convertTerms(List<Term> terms, Optional<Range> range, String owner, Options options,
            List<Finding> findings) {
        List<Term> out = new ArrayList<>(terms.size());
        for (Term t : terms) {
            out.add(convertTerm(t, range, owner, options, findings));
        }
        return out;
    }

    /**
     * One term. Points and singletons are standard already. A named shape: triangle, trapezoid, rectangle and
     * ramp are their exact points ({@link ShapePoints#exact}, finding Exact); a curve, with
     * {@code options.approximatePoints() > 0} and a finite interval (the output's RANGE; an input's RANGE as
     * the dialect wrote it in FUZZIFY), becomes the polyline of {@link ShapePoints#approximate} over it with
     * an {@link Kind.Approximated} finding carrying the proven largest membership error on that interval;
     * otherwise it is not expressible (and kept, so only {@code --allow-lossy} writes the program, with the
     * curve replaced by the points of its value at the interval's ends or at its special points).
     */
    static Term convertTerm(Term t, Optional<Range> range, String owner, Options options, List<Finding> findings) {
        MembershipFunction f = t.function();
        if (f instanceof MembershipFunction.Points || f instanceof MembershipFunction.Singleton) {
            return t;
        }
        if (f instanceof MembershipFunction.NamedShape shape) {
            String id = shape.kind().featureId();
            Optional<List<Point>> exact = ShapePoints.exact(shape);
            if (exact.isPresent()) {
                findings.add(new Finding(id, t.location(), new Kind.Exact(), "term '" + t.name() + "' of " + owner
                        + " written as its points " + pointsText(exact.get())));
                return new Term(t.name(), new MembershipFunction.Points(exact.get()), t.location());
            }
            Optional<double[]> interval = range.map(r -> new double[] {r.min().value(), r.max().value()})
                    .filter(i -> Double.isFinite(i[0]) && Double.isFinite(i[1]) && i[0] < i[1]);
            int n = options.approximatePoints() > 0 ? options.approximatePoints() : 64;
            double[] over = interval.orElse(null);
            ShapePoints.Approximation a = over == null ? null : ShapePoints.approximate(shape, over[0], over[1], n);
            if (options.approximatePoints() > 0 && a != null && Double.isFinite(a.maxError())) {
                findings.add(new Finding(id, t.location(), new Kind.Approximated(a.maxError()), "term '" + t.name()
                        + "' of " + owner + " written as " + a.points().size() + " points over [" + num(over[0])
                        + ", " + num(over[1]) + "] (outside it the points continue flat)"));
                return new Term(t.name(), new MembershipFunction.Points(a.points()), t.location());
            }
            String why = options.approximatePoints() == 0
                    ? "standard FCL has only points and singletons; --approximate-points N approximates it"
                    : over == null ? owner + " has no finite RANGE to approximate over"
                            + (owner.startsWith("input") ? " (give it a RANGE := (lo .. hi);: fuzzylite's in its FUZZIFY block,"
                                    + " jFuzzyLogic's after its declaration in VAR_INPUT)" : "")
                    : "its slope is unbounded, so no error bound holds for points";
            if (a == null) {
                a = ShapePoints.approximate(shape, fallbackLo(shape), fallbackHi(shape), 2);
            }
            findings.add(new Finding(id, t.location(), new Kind.NotExpressible("points approximating it"),
                    "term '" + t.name() + "' of " + owner + " is a " + shape.kind().name().toLowerCase(Locale.ROOT).replace('_', ' ') + " curve: " + why));
            return new Term(t.name(), new MembershipFunction.Points(a.points()), t.location());
        }
        if (f instanceof MembershipFunction.Computed computed) {
            String id = org.fclcert.model.Feature.O_TAKAGI_SUGENO.id();
            if (computed.value().variables().isEmpty()) {
                double v = computed.value().evaluate(name -> 0);
                findings.add(new Finding(id, t.location(), new Kind.Exact(), "term '" + t.name() + "' of " + owner
                        + " (" + computed.written() + ") written as the singleton " + num(v)));
                return new Term(t.name(), new MembershipFunction.Singleton(org.fclcert.model.Literal.of(v)), t.location());
            }
            findings.add(new Finding(id, t.location(), new Kind.NotExpressible("a singleton at its value for inputs 0"),
                    "term '" + t.name() + "' of " + owner + " is a Takagi-Sugeno term (" + computed.written()
                            + "): its value depends on " + String.join(", ", computed.value().variables())
                            + ", and standard FCL output terms are constants or fuzzy sets"));
            return new Term(t.name(), new MembershipFunction.Singleton(org.fclcert.model.Literal.of(computed.value().evaluate(name -> 0))),
                    t.location());
        }
        findings.add(new Finding("term '" + t.name() + "'", t.location(), new Kind.NotExpressible("kept as read"),
                "term '" + t.name() + "': no conversion to points is known for its membership function"));
        return t;
    }

    /** An interval for a lossy stand-in when the variable has none: around the shape's special points. */
    private static double fallbackLo(MembershipFunction.NamedShape shape) {
        double[] sp = shape.kind().specialPoints(shape.values());
        double lo = java.util.Arrays.stream(sp).min().orElse(0);
        double hi = java.util.Arrays.stream(sp).max().orElse(1);
        return lo - Math.max(1, hi - lo);
    }

    private static double fallbackHi(MembershipFunction.NamedShape shape) {
        double[] sp = shape.kind().specialPoints(shape.values());
        double lo = java.util.Arrays.stream(sp).min().orElse(0);
        double hi = java.util.Arrays.stream(sp).max().orElse(1);
        return hi + Math.max(1, hi - lo);
    }

    private static String pointsText(List<Point> points) {
        StringBuilder b = new StringBuilder();
        for (Point p : points) {
            b.append(b.length() == 0 ? "" : " ").append('(').append(num(p.x())).append(", ").append(num(p.degree()))
                    .append(')');
        }
        return b.toString();
    }

    private static String num(org.fclcert.model.Operand o) {
        return o instanceof org.fclcert.model.Literal l ? num(l.value()) : o.toString();
    }

    static String num(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    // ---------------------------------------------------------------- hedges

    /**
     * Hedges (fuzzylite). {@code x is any} has degree 1, the unit of every AND algorithm (MIN, PROD, BDIF):
     * dropped from an AND chain it converts exactly. Anywhere else, and every other hedge ({@code very},
     * {@code somewhat}, {@code extremely}, {@code seldom}, a {@code not} after another hedge) has no standard
     * form: not expressible; the converted program leaves the hedge out ({@code any}: the subcondition; a
     * rule left with no condition: the rule). A leading {@code not} is the standard's IS NOT already.
     */
    private static Program hedges(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<RuleBlock> ruleBlocks = new ArrayList<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                List<Rule> rules = new ArrayList<>();
                for (Rule r : rb.rules()) {
                    Optional<Condition> c = withoutHedges(r.condition(), false, findings);
                    if (c.isPresent()) {
                        rules.add(new Rule(r.name(), c.get(), r.conclusion(), r.location()));
                    } else {
                        findings.add(new Finding("RULE " + r.name(), r.location(), new Kind.NotExpressible("left out"),
                                "rule " + r.name() + " has no condition left in standard FCL (it is always 1 or"
                                        + " made only of hedged 'any'); the converted program leaves it out"));
                    }
                }
                ruleBlocks.add(new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), rb.accumulation(), rules,
                        rb.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(),
                    ruleBlocks, fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }

    /** The condition without hedges; empty when nothing is left (the condition was 'any'). */
    private static Optional<Condition> withoutHedges(Condition c, boolean inAnd, List<Finding> findings) {
        if (c instanceof Condition.TermSubcondition t) {
            if (t.hedges().isEmpty()) {
                return Optional.of(t);
            }
            String subcondition = "'" + t.variable() + " is " + hedgeWords(t) + (t.any() ? "" : " " + t.term()) + "'";
            if (t.hedges().equals(List.of(Hedge.ANY)) && !t.negated() && inAnd) {
                findings.add(new Finding(Hedge.ANY.featureId(), t.location(), new Kind.Exact(), subcondition
                        + " (degree 1, the unit of AND) left out of its AND chain"));
                return Optional.empty();
            }
            for (Hedge h : t.hedges()) {
                findings.add(new Finding(h.featureId(), t.location(), new Kind.NotExpressible(t.any()
                        ? "the subcondition left out" : "the term without the hedge"), "hedge '" + h.word() + "' in "
                        + subcondition + " has no standard form; the converted program "
                        + (t.any() ? "leaves the subcondition out" : "writes '" + t.variable() + " IS "
                                + (t.negated() ? "NOT " : "") + t.term() + "'")));
            }
            return t.any() ? Optional.empty()
                    : Optional.of(new Condition.TermSubcondition(t.variable(), t.term(), t.negated(), t.location()));
        }
        if (c instanceof Condition.And a) {
            return chain(a.operands(), true, findings).map(ops -> ops.size() == 1 ? ops.get(0)
                    : new Condition.And(ops, a.location()));
        }
        if (c instanceof Condition.Or o) {
            return chain(o.operands(), false, findings).map(ops -> ops.size() == 1 ? ops.get(0)
                    : new Condition.Or(ops, o.location()));
        }
        if (c instanceof Condition.Parenthesized p) {
            return withoutHedges(p.inner(), inAnd, findings).map(inner -> inner instanceof Condition.And
                    || inner instanceof Condition.Or ? new Condition.Parenthesized(inner, p.location()) : inner);
        }
        if (c instanceof Condition.Not n) {
            return withoutHedges(n.operand(), false, findings).map(x -> new Condition.Not(x, n.location()));
        }
        return Optional.of(c);
    }

    private static Optional<List<Condition>> chain(List<Condition> operands, boolean and, List<Finding> findings) {
        List<Condition> out = new ArrayList<>();
        for (Condition op : operands) {
            withoutHedges(op, and, findings).ifPresent(out::add);
        }
        return out.isEmpty() ? Optional.empty() : Optional.of(out);
    }

    private static String hedgeWords(Condition.TermSubcondition t) {
        StringBuilder b = new StringBuilder(t.negated() ? "not" : "");
        for (Hedge h : t.hedges()) {
            b.append(b.length() == 0 ? "" : " ").append(h.word());
        }
        return b.toString();
    }

    // ---------------------------------------------------------------- accumulation

    /**
     * ACCU PROBOR, SUM and the other s-norms (Open Level): no method of Table 5 computes them. Not expressible;
     * the converted program uses MAX for PROBOR and the others, BSUM for SUM (each equal to it where at most one
     * contribution is non-zero, and BSUM where the sum stays at most 1).
     */
    private static Program accumulations(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            BlockIndex names = BlockIndex.of(fb);
            List<RuleBlock> ruleBlocks = new ArrayList<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                Optional<Located<AccumulationMethod>> accu = rb.accumulation();
                if (accu.isPresent() && !accu.get().value().standard() && oneContributionPerSingleton(fb, names, rb)) {
                    String id = accumulationFeature(accu.get().value());
                    findings.add(new Finding(id, accu.get().location(), new Kind.Exact(), "ACCU " + accu.get().value()
                            + " of rule block " + rb.name() + " written as MAX: it concludes only singleton outputs,"
                            + " each term by one rule, so no degrees are ever accumulated"));
                    accu = Optional.of(new Located<>(AccumulationMethod.MAX, accu.get().location()));
                } else if (accu.isPresent() && !accu.get().value().standard()) {
                    AccumulationMethod m = accu.get().value();
                    AccumulationMethod replacement = m == AccumulationMethod.SUM ? AccumulationMethod.BSUM
                            : AccumulationMethod.MAX;
                    String id = accumulationFeature(m);
                    findings.add(new Finding(id, accu.get().location(), new Kind.NotExpressible("ACCU : "
                            + replacement), "ACCU " + m + " of rule block " + rb.name() + " has no equivalent among"
                            + " the methods of Table 5; the converted program uses " + replacement
                            + ", which gives other values where contributions overlap"));
                    accu = Optional.of(new Located<>(replacement, accu.get().location()));
                }
                ruleBlocks.add(new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), accu, rb.rules(),
                        rb.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(),
                    ruleBlocks, fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }

    private static String accumulationFeature(AccumulationMethod m) {
        return (m == AccumulationMethod.SUM ? Feature.O_ACCU_SUM : m == AccumulationMethod.PROBOR ? Feature.O_ACCU_PROBOR
                : Feature.O_ACCU_OTHER_NORM).id();
    }

    /** The outputs the rule block concludes, by {@link org.fclcert.model.Names#key}, each once. */
    private static Set<String> concludedOutputs(RuleBlock rb) {
        Set<String> concluded = new java.util.HashSet<>();
        rb.rules().forEach(r -> r.conclusion().forEach(c -> concluded.add(org.fclcert.model.Names.key(c.variable()))));
        return concluded;
    }

    /** Whether every output the rule block concludes has singleton (or Takagi–Sugeno) terms only. */
    private static boolean concludesOnlySingletons(BlockIndex names, RuleBlock rb) {
        // each output once: a block of 10^5 rules may conclude one output of 10^5 terms
        return concludedOutputs(rb).stream().allMatch(v -> names.defuzzification(v).map(d -> onlySingletons(d.terms()))
                .orElse(true));
    }

    private static boolean onlySingletons(List<Term> terms) {
        return terms.stream().allMatch(t -> t.function() instanceof MembershipFunction.Singleton
                || t.function() instanceof MembershipFunction.Computed);
    }

    /**
     * Whether every output the rule block concludes has singleton (or Takagi–Sugeno) terms only, and each of its
     * terms is concluded by one rule of the function block at most: then every accumulation gives each term its
     * one degree, whatever the method.
     */
    private static boolean oneContributionPerSingleton(FunctionBlock fb, BlockIndex names, RuleBlock rb) {
        Set<String> mine = concludedOutputs(rb);
        for (String v : mine) {
            Optional<Defuzzification> d = names.defuzzification(v);
            if (d.isEmpty() || d.get().terms().isEmpty() || !onlySingletons(d.get().terms())) {
                return false;
            }
        }
        Set<String> seen = new java.util.HashSet<>();
        for (RuleBlock b : fb.ruleBlocks()) {
            for (Rule r : b.rules()) {
                for (var c : r.conclusion()) {
                    String key = org.fclcert.model.Names.key(c.variable()) + '\0'
                            + org.fclcert.model.Names.key(c.term().orElse(""));
                    if (mine.contains(org.fclcert.model.Names.key(c.variable())) && (c.term().isEmpty() || !seen.add(key))) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    /**
     * Defuzzification methods outside Table 1. MoM has no standard equivalent (CoG, CoA, LM and RM all
     * give other values on a plateau), nor has COGSS (Σ u·μ without the division) or Tsukamoto's method (no
     * standard method inverts a term): not expressible; the
     * converted program uses CoG (CoGS on singletons), the method FFLL itself falls back to.
     */
    private static Program methods(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<Defuzzification> defuzzifications = new ArrayList<>();
            for (Defuzzification d : fb.defuzzifications()) {
                Optional<Located<DefuzzificationMethod>> method = d.method();
                if (method.isPresent() && !method.get().value().standard()) {
                    DefuzzificationMethod replacement = d.terms().stream()
                            .allMatch(t -> t.function() instanceof MembershipFunction.Singleton)
                            ? DefuzzificationMethod.COGS : DefuzzificationMethod.COG;
                    DefuzzificationMethod m = method.get().value();
                    String what = m == DefuzzificationMethod.COGSS ? "O-COGSS, the weighted sum of singletons"
                            : m == DefuzzificationMethod.TSUKAMOTO ? "O-TSUKAMOTO, Tsukamoto's method"
                            : "O-MOM, mean of maximum";
                    findings.add(new Finding("METHOD " + m.keyword(), method.get().location(),
                            new Kind.NotExpressible("METHOD : " + replacement.keyword()),
                            "METHOD " + m.keyword() + " of " + d.variable() + " (" + what + ") has no equivalent"
                                    + " among the methods of Table 1; the converted program uses "
                                    + replacement.keyword() + ", which gives other values"));
                    method = Optional.of(new Located<>(replacement, method.get().location()));
                }
                defuzzifications.add(new Defuzzification(d.variable(), d.range(), d.terms(), method,
                        d.defaultValue(), d.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), defuzzifications,
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }

    /**
     * {@code DEFAULT := nan} (fuzzylite, O-DEFAULT-NAN): the standard's DEFAULT is a number (or NC). Not
     * expressible; the converted program uses {@code DEFAULT := 0}.
     */
    private static Program defaults(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<Defuzzification> defuzzifications = new ArrayList<>();
            for (Defuzzification d : fb.defuzzifications()) {
                Optional<DefaultValue> def = d.defaultValue();
                if (def.isPresent() && def.get() instanceof DefaultValue.Constant c && Double.isNaN(c.value().value())) {
                    findings.add(new Finding(Feature.O_DEFAULT_NAN.id(), c.location(),
                            new Kind.NotExpressible("DEFAULT := 0"), "DEFAULT := nan of " + d.variable()
                                    + ": a standard DEFAULT is a number or NC; the converted program uses 0"));
                    def = Optional.of(new DefaultValue.Constant(new org.fclcert.model.Literal(0, true,
                            c.value().location()), c.location()));
                }
                defuzzifications.add(new Defuzzification(d.variable(), d.range(), d.terms(), d.method(), def,
                        d.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), defuzzifications,
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }
}
