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
 * (B-COGS), or the default when nothing fires.
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

    static Feature feature(Shrinker.Case c, Deviation d) {
        FeatureReport report = new FeatureDetector().detect(c.program());
        Set<Feature> used = report.features();
        if (!valueKind(d.kind())) {
            Optional<Feature> named = refusal(report, d);
            if (named.isPresent()) {
                return named.get();
            }
        }
        Optional<Feature> precision = precision(c, d, used);
        if (precision.isPresent()) {
            return precision.get();
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
    private static Optional<Feature> refusal(FeatureReport report, Deviation d) {
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
            Optional<Feature> basic = there.stream().sorted().findFirst();
            if (basic.isPresent()) {
                return basic;
            }
        }
        for (String word : d.message().toUpperCase(java.util.Locale.ROOT).split("[^A-Z_]+")) {
            Feature f = WORDS.get(word);
            if (f != null && report.features().contains(f)) {
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

    /**
     * A small error (at most a tenth of the output's width) on an output defuzzified over point terms, in a
     * case with nothing more specific to blame (no accumulation, activation, weight or NC): the integration
     * or maximum search of that output's METHOD. Such errors survive shrinking only with the operators that
     * shape the set, which would otherwise name the case.
     */
    private static Optional<Feature> precision(Shrinker.Case c, Deviation d, Set<Feature> used) {
        if (d.kind() != DeviationKind.WRONG_VALUE || PRIORITY.subList(0, PRIORITY.indexOf(Feature.E_AND_PROD)).stream()
                .anyMatch(used::contains)) {
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
