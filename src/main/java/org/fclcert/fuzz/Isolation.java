package org.fclcert.fuzz;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.FeatureReport;
import java.util.OptionalDouble;
import org.fclcert.corpus.OutputScales;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Trace;
import java.util.Set;
import org.fclcert.check.FeatureDetector;
import org.fclcert.model.Condition;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;

/**
 * Names the feature a minimal case isolates. The shrinker has tried to take every feature beyond Table 8's
 * basics out (ACCU MAX for NSUM, no ACT, no WITH, a DEFAULT constant, ...) and failed, so each one left is
 * needed; the most specific of them names the case. A case of Basic features only is named by what it
 * exercises: an input beyond a term's outer points (B-IN-TERM), a singleton concluded by two rules
 * (B-COGS), or the default when nothing fires. An input exactly on a vertical edge of its term names the case by
 * that term's points feature before anything else, and a rule firing with a degree of at most 1e-6 (which an
 * implementation may take for not firing) by B-DEFAULT-VALUE. A singleton of the deviating CoGS output
 * activated twice names it B-COGS unless an accumulation, activation, weight, NC or operator setting is left.
 */
final class Isolation {
    /** Most specific first: what the shrinker can switch off, then the methods, then structure. */
    private static final List<Feature> PRIORITY = List.of(
            Feature.E_ACCU_NSUM, Feature.E_ACCU_BSUM, Feature.E_ACT_PROD, Feature.E_WITH_VAR, Feature.E_WITH_CONST,
            Feature.B_DEFAULT_NC, Feature.E_AND_PROD, Feature.E_AND_BDIF, Feature.E_OR_ASUM, Feature.E_OR_BSUM,
            Feature.E_OR_MAX, Feature.E_NOT, Feature.E_PARENS, Feature.E_COND_VARIABLE, Feature.E_VAR_LOCAL,
            Feature.E_RULEBLOCKS, Feature.E_SUBCONCLUSIONS, Feature.E_TERM_VARIABLE_POINT, Feature.O_VAR_DEGREE,
            Feature.O_DEGREES_0_1,
            Feature.E_LM, Feature.E_RM, Feature.E_COA, Feature.O_MOM, Feature.E_COG, Feature.E_ACT_MIN,
            Feature.O_MANY_POINTS, Feature.E_IN_TERM_4, Feature.E_RANGE, Feature.E_OUT_TERM_4);

    private Isolation() {
    }

    static Feature feature(Shrinker.Case c, Deviation d, Presentation presentation) {
        FeatureReport report = new FeatureDetector().detect(c.program());
        Set<Feature> used = report.features();
        if (!valueKind(d.kind())) {
            // the line an implementation names is a line of the text it got (in a library's layout, when presented)
            FeatureReport seen = presentation.layout().isEmpty() ? report : presentation.seen(c.program())
                    .map(p -> new FeatureDetector().detect(p)).orElse(report);
            Optional<Feature> named = refusal(seen, report.features(), d);
            if (named.isPresent()) {
                return named.get();
            }
        }
        Optional<Feature> edge = verticalEdgeUnderAnInput(c);
        if (edge.isPresent() && valueKind(d.kind())) {
            return edge.get();
        }
        Optional<Trace> trace = trace(c, d);
        if (valueKind(d.kind()) && trace.isPresent() && trace.get().ruleDegrees().stream()
                .anyMatch(r -> r.degree() > 0 && r.degree() <= TINY)) {
            return Feature.B_DEFAULT_VALUE;
        }
        Optional<Feature> precision = precision(c, d, used);
        if (precision.isPresent()) {
            return precision.get();
        }
        List<Feature> switchable = PRIORITY.subList(0, PRIORITY.indexOf(Feature.E_NOT));
        for (Feature f : switchable) {
            if (used.contains(f)) {
                return f;
            }
        }
        if (d.kind() == DeviationKind.WRONG_VALUE && trace.isPresent() && singletonActivatedTwice(c, d, trace.get())) {
            return Feature.B_COGS;
        }
        for (Feature f : PRIORITY) {
            if (used.contains(f)) {
                return f;
            }
        }
        FunctionBlock fb = c.block();
        if (d.kind() == DeviationKind.WRONG_VALUE && termConcludedTwice(fb)) {
            return Feature.B_COGS;
        }
        if (!valueKind(d.kind())) {
            return Feature.B_FB;
        }
        if (beyondOuterPoints(fb, c.steps())) {
            return Feature.B_IN_TERM;
        }
        if (used.contains(Feature.B_DEFAULT_VALUE) && d.actualOutputs().size() > 0 && fb.ruleBlocks().stream()
                .flatMap(rb -> rb.rules().stream()).count() == 1) {
            return Feature.B_DEFAULT_VALUE;
        }
        return used.contains(Feature.B_AND_MIN) && hasAnd(fb) ? Feature.B_AND_MIN : Feature.B_COGS;
    }

    /** A rule degree this small is one an implementation may take for "did not fire" (fuzzylite: 1e-6). */
    private static final double TINY = 1e-6;
    private static final Pattern LINE = Pattern.compile("\\(line (\\d+)\\)");
    private static final Map<String, Feature> WORDS = Map.ofEntries(Map.entry("COGS", Feature.B_COGS),
            Map.entry("COG", Feature.E_COG), Map.entry("COA", Feature.E_COA), Map.entry("LM", Feature.E_LM),
            Map.entry("RM", Feature.E_RM), Map.entry("MOM", Feature.O_MOM), Map.entry("NSUM", Feature.E_ACCU_NSUM),
            Map.entry("BSUM", Feature.E_ACCU_BSUM), Map.entry("PROD", Feature.E_AND_PROD), Map.entry("BDIF", Feature.E_AND_BDIF),
            Map.entry("ASUM", Feature.E_OR_ASUM), Map.entry("ACT", Feature.E_ACT_MIN), Map.entry("NOT", Feature.E_NOT),
            Map.entry("RANGE", Feature.E_RANGE), Map.entry("VAR", Feature.E_VAR_LOCAL), Map.entry("WITH", Feature.E_WITH_CONST),
            Map.entry("NC", Feature.B_DEFAULT_NC), Map.entry("OR", Feature.E_OR_MAX));

    static boolean valueKind(DeviationKind k) {
        return k == DeviationKind.WRONG_VALUE || k == DeviationKind.NOT_A_NUMBER || k == DeviationKind.MISSING_OUTPUT;
    }

    /**
     * A refusal (rejection, error, crash) is named by the most specific feature used on the line the
     * implementation names, else by a feature whose keyword its message names.
     */
    private static Optional<Feature> refusal(FeatureReport report, Set<Feature> used, Deviation d) {
        Matcher m = LINE.matcher(d.message());
        if (m.find()) {
            int line = Integer.parseInt(m.group(1));
            Set<Feature> there = report.uses().stream().filter(u -> u.location().line() == line)
                    .map(u -> u.feature()).collect(java.util.stream.Collectors.toSet());
            for (Feature f : PRIORITY) {
                if (there.contains(f)) {
                    return Optional.of(f);
                }
            }
            Optional<Feature> basic = there.stream().filter(used::contains).sorted().findFirst();
            if (basic.isPresent()) {
                return basic;
            }
        }
        for (String word : d.message().toUpperCase(java.util.Locale.ROOT).split("[^A-Z_]+")) {
            Feature f = WORDS.get(word);
            if (f != null && used.contains(f)) {
                return Optional.of(f);
            }
        }
        return Optional.empty();
    }

    /** What a refusal says with its numbers taken out: two refusals with the same signature are one finding. */
    static String signature(Deviation d) {
        String text = d.message().replaceFirst("^(step \\d+: |on load: |on reset: )", "");
        return d.kind().word() + ":" + text.replaceAll("-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?", "#");
    }

    private static final Pattern QUOTED = Pattern.compile("'([^']{1,40})'|<([^<>]{1,40})>");

    /**
     * The first token a refusal quotes ({@code 'LREAL'}, {@code <CoGS>}) that is not a name of the program: two
     * refusals quoting the same keyword, type or symbol are one finding however the library words them (a printed
     * parse error, or the same error followed by an internal failure).
     */
    static Optional<String> quotedToken(Deviation d, org.fclcert.model.Program program) {
        Set<String> names = new java.util.HashSet<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            names.add(Names.key(fb.name()));
            fb.variables().forEach(v -> names.add(Names.key(v.name())));
            fb.fuzzifications().forEach(f -> f.terms().forEach(t -> names.add(Names.key(t.name()))));
            fb.defuzzifications().forEach(x -> x.terms().forEach(t -> names.add(Names.key(t.name()))));
            fb.ruleBlocks().forEach(rb -> names.add(Names.key(rb.name())));
        }
        Matcher m = QUOTED.matcher(d.message());
        while (m.find()) {
            String token = m.group(1) != null ? m.group(1) : m.group(2);
            if (!names.contains(Names.key(token)) && !token.matches("[-+0-9.eE]+")) {
                return Optional.of(d.kind().word() + ":" + token);
            }
        }
        return Optional.empty();
    }

    /**
     * A small error (at most a tenth of the output's width) on an output defuzzified over point terms, in a
     * case with nothing more specific to blame (no accumulation, activation, weight or NC): the integration
     * or maximum search of that output's METHOD. Such errors survive shrinking only with the operators that
     * shape the set, which would otherwise name the case.
     */
    private static Optional<Feature> precision(Shrinker.Case c, Deviation d, Set<Feature> used) {
        if (PRIORITY.subList(0, PRIORITY.indexOf(Feature.E_AND_PROD)).stream().anyMatch(used::contains)) {
            return Optional.empty();
        }
        return smallErrorOfMethod(c, d);
    }

    /**
     * The METHOD feature of the output {@code d} is on, when {@code d} is a wrong value off by at most a tenth of
     * that output's width (the size of error an integration or a maximum search makes); empty otherwise.
     */
    static Optional<Feature> smallErrorOfMethod(Shrinker.Case c, Deviation d) {
        if (d.kind() != DeviationKind.WRONG_VALUE) {
            return Optional.empty();
        }
        Optional<Defuzzification> def = c.block().defuzzification(d.output());
        OptionalDouble width = OutputScales.of(c.block()).width(d.output());
        if (def.isEmpty() || def.get().method().isEmpty() || width.isEmpty()
                || Math.abs(d.actual() - d.expected()) > 0.1 * width.getAsDouble()) {
            return Optional.empty();
        }
        return Optional.of(switch (def.get().method().get().value()) {
            case COG -> Feature.E_COG;
            case COA -> Feature.E_COA;
            case LM -> Feature.E_LM;
            case RM -> Feature.E_RM;
            case MOM -> Feature.O_MOM;
            default -> Feature.B_COGS;
        });
    }

    /**
     * The points feature of an input term with a vertical edge (two points at one x) that some step puts its input
     * exactly on: B-IN-TERM for three points or fewer, E-IN-TERM-4 for four, O-MANY-POINTS beyond. Implementations
     * differ on the degree at the edge (docs/semantics.md point 1 takes the largest); the shrinker never makes an
     * edge, so one left in a minimal case under an input was there from the start, and is needed.
     */
    static Optional<Feature> verticalEdgeUnderAnInput(Shrinker.Case c) {
        for (Fuzzification f : c.block().fuzzifications()) {
            for (Term t : f.terms()) {
                if (!(t.function() instanceof MembershipFunction.Points p)) {
                    continue;
                }
                List<Point> pts = p.points();
                for (int i = 1; i < pts.size(); i++) {
                    if (pts.get(i).x() instanceof Literal x && pts.get(i - 1).x() instanceof Literal prev
                            && x.value() == prev.value() && c.steps().stream().anyMatch(s -> s.entrySet().stream()
                                    .anyMatch(e -> Names.same(e.getKey(), f.variable()) && e.getValue() == x.value()))) {
                        return Optional.of(pts.size() <= 3 ? Feature.B_IN_TERM : pts.size() == 4 ? Feature.E_IN_TERM_4
                                : Feature.O_MANY_POINTS);
                    }
                }
            }
        }
        return Optional.empty();
    }

    /** Some step puts an input beyond a term's outer points, where the term keeps a non-zero outer degree. */
    private static boolean beyondOuterPoints(FunctionBlock fb, List<Map<String, Double>> steps) {
        for (Fuzzification f : fb.fuzzifications()) {
            for (Term t : f.terms()) {
                if (!(t.function() instanceof MembershipFunction.Points p)) {
                    continue;
                }
                List<Point> pts = p.points();
                if (!(pts.get(0).x() instanceof Literal x0 && pts.get(pts.size() - 1).x() instanceof Literal xn)) {
                    continue;
                }
                double d0 = pts.get(0).degree() instanceof Literal l ? l.value() : 1;
                double dn = pts.get(pts.size() - 1).degree() instanceof Literal l ? l.value() : 1;
                for (Map<String, Double> s : steps) {
                    for (Map.Entry<String, Double> e : s.entrySet()) {
                        if (Names.same(e.getKey(), f.variable())
                                && (e.getValue() < x0.value() && d0 > 0 || e.getValue() > xn.value() && dn > 0)) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    /** The reference's trace of the step {@code d} is at (empty for a deviation at load). */
    private static Optional<Trace> trace(Shrinker.Case c, Deviation d) {
        if (d.step() < 0 || d.step() >= c.steps().size()) {
            return Optional.empty();
        }
        try {
            return Optional.of(new ReferenceProgram(c.program()).run(c.steps().subList(0, d.step() + 1))
                    .get(d.step()).trace());
        } catch (EvaluationException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /** A singleton term of the deviating CoGS output activated by two subconclusions at once in the step. */
    private static boolean singletonActivatedTwice(Shrinker.Case c, Deviation d, Trace t) {
        Optional<Defuzzification> def = c.block().defuzzification(d.output());
        if (def.isEmpty() || def.get().method().map(m -> m.value() != DefuzzificationMethod.COGS).orElse(true)) {
            return false;
        }
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (Trace.Activation a : t.activations()) {
            if (Names.same(a.variable(), d.output()) && a.term().isPresent() && a.activatedDegree() > 0
                    && !seen.add(Names.key(a.term().get()))) {
                return true;
            }
        }
        return false;
    }

    private static boolean termConcludedTwice(FunctionBlock fb) {
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (RuleBlock rb : fb.ruleBlocks()) {
            for (Rule r : rb.rules()) {
                for (Subconclusion s : r.conclusion()) {
                    if (s.term().isPresent() && !seen.add(Names.key(s.variable()) + "." + Names.key(s.term().get()))) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    private static boolean hasAnd(FunctionBlock fb) {
        return fb.ruleBlocks().stream().flatMap(rb -> rb.rules().stream())
                .anyMatch(r -> ConditionTrees.nodes(r.condition()).stream().anyMatch(n -> n instanceof Condition.And));
    }
}
