package org.fclcert.harness.fakes;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.function.UnaryOperator;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Trace;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Located;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;

/**
 * Implementations that are wrong in one known way each, as the peers (fuzzylite, jFuzzyLogic, FFLL) are or
 * as a plausible implementation could be. Each is the correct {@link EvaluatorIut} with one defect.
 */
public final class Fakes {
    private Fakes() {
    }

    /** Answers 0 for every output. */
    public static final class AlwaysZero extends EvaluatorIut {
        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            outputs.replaceAll((k, v) -> 0.0);
            return outputs;
        }
    }

    /** Accumulates NSUM as BSUM (fuzzylite 6.0, jFuzzyLogic). */
    public static final class NsumAsBsum extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return mapRuleBlocks(p, rb -> rb.accumulation().filter(a -> a.value() == AccumulationMethod.NSUM)
                    .map(a -> withAccumulation(rb, new Located<>(AccumulationMethod.BSUM, a.location()))).orElse(rb));
        }
    }

    /** Gives AND and OR the same precedence, combining left to right (jFuzzyLogic). */
    public static final class EqualPrecedence extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return mapRuleBlocks(p, rb -> withRules(rb, rb.rules().stream()
                    .map(r -> new Rule(r.name(), Conditions.leftToRight(r.condition()), r.conclusion(), r.location()))
                    .toList()));
        }
    }

    /**
     * Keeps one AND/OR pair for the whole function block: the last AND or OR declared in the text wins, and
     * sets the other to its De Morgan pair, in every rule block. (Within one rule block coupling cannot be
     * seen in a valid program, since FCL-C014 requires a Table 3 pair; across blocks it can.)
     */
    public static final class CoupledAndOr extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return new Program(p.sourceName(), p.functionBlocks().stream().map(CoupledAndOr::couple).toList());
        }

        private static FunctionBlock couple(FunctionBlock fb) {
            Located<AndAlgorithm> and = null;
            Located<OrAlgorithm> or = null;
            SourceLocation last = null;
            for (RuleBlock rb : fb.ruleBlocks()) {
                if (rb.and().isPresent() && (last == null || rb.and().get().location().compareTo(last) > 0)) {
                    last = rb.and().get().location();
                    and = rb.and().get();
                    or = new Located<>(and.value().pair(), last);
                }
                if (rb.or().isPresent() && (last == null || rb.or().get().location().compareTo(last) > 0)) {
                    last = rb.or().get().location();
                    or = rb.or().get();
                    and = new Located<>(or.value().pair(), last);
                }
            }
            if (and == null) {
                return fb;
            }
            Optional<Located<AndAlgorithm>> a = Optional.of(and);
            Optional<Located<OrAlgorithm>> o = Optional.of(or);
            List<RuleBlock> blocks = fb.ruleBlocks().stream().map(rb -> new RuleBlock(rb.name(), a, o, rb.activation(),
                    rb.accumulation(), rb.rules(), rb.location())).toList();
            return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(), blocks,
                    fb.options(), fb.location());
        }
    }

    /** CoGS that sums every rule's activation separately instead of accumulating per term (fuzzylite 6.0). */
    public static final class PerRuleCogs extends EvaluatorIut {
        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            for (Defuzzification d : block.defuzzifications()) {
                if (method(d) != DefuzzificationMethod.COGS) {
                    continue;
                }
                double num = 0;
                double den = 0;
                for (Trace.Activation a : trace.activations()) {
                    if (a.variable().equalsIgnoreCase(d.variable()) && a.term().isPresent()) {
                        Optional<Double> value = d.term(a.term().get()).flatMap(Shapes::singletonValue);
                        if (value.isEmpty()) {
                            return outputs;
                        }
                        num += a.activatedDegree() * value.get();
                        den += a.activatedDegree();
                    }
                }
                if (den > 0) {
                    put(outputs, d.variable(), num / den);
                }
            }
            return outputs;
        }
    }

    /** CoG, CoA, LM and RM computed on 100 samples at the midpoints of the output's interval (fuzzylite 6.0). */
    public static final class SampledDefuzzification extends EvaluatorIut {
        static final int SAMPLES = 100;

        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            for (Trace.AccumulatedSet set : trace.accumulatedSets()) {
                if (set.singletons() || set.breakpoints().size() < 2) {
                    continue;
                }
                Defuzzification d = block.defuzzification(set.variable()).orElseThrow();
                Optional<Double> sampled = Shapes.sampled(method(d), set.breakpoints(), SAMPLES);
                put(outputs, set.variable(), sampled.orElseGet(() -> defaultValue(d)));
            }
            return outputs;
        }
    }

    /**
     * Applies a weighting factor to the rule's degree before MIN activation, min(w·d, μ), instead of to the
     * activated set, w·min(d, μ); computes CoG with its own fine integration. Where every weight is 1, or
     * activation is PROD, the two readings agree and the reference value is kept.
     */
    public static final class WeightBeforeActivation extends EvaluatorIut {
        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            for (Trace.AccumulatedSet set : trace.accumulatedSets()) {
                Defuzzification d = block.defuzzification(set.variable()).orElseThrow();
                List<Trace.Activation> acts = trace.activations().stream()
                        .filter(a -> a.variable().equalsIgnoreCase(d.variable()) && a.term().isPresent()).toList();
                if (set.singletons() || method(d) != DefuzzificationMethod.COG || set.breakpoints().size() < 2
                        || !Shapes.constantPoints(d) || acts.stream().allMatch(a -> a.weight() == 1.0) || acts.stream()
                                .anyMatch(a -> activation(block, a.ruleBlock()) != ActivationMethod.MIN)) {
                    continue;
                }
                List<Shapes.Clipped> clipped = acts.stream()
                        .map(a -> new Shapes.Clipped(d.term(a.term().get()).orElseThrow(), a.activatedDegree()))
                        .toList();
                AccumulationMethod accu = accumulation(block, acts.get(0).ruleBlock());
                double lo = set.breakpoints().get(0).u();
                double hi = set.breakpoints().get(set.breakpoints().size() - 1).u();
                Shapes.clippedCog(clipped, accu, lo, hi).ifPresent(v -> put(outputs, set.variable(), v));
            }
            return outputs;
        }

        private static ActivationMethod activation(FunctionBlock fb, String ruleBlock) {
            return fb.ruleBlock(ruleBlock).flatMap(RuleBlock::activation).map(Located::value)
                    .orElse(ActivationMethod.MIN);
        }

        private static AccumulationMethod accumulation(FunctionBlock fb, String ruleBlock) {
            return fb.ruleBlock(ruleBlock).flatMap(RuleBlock::accumulation).map(Located::value)
                    .orElse(AccumulationMethod.MAX);
        }
    }

    /** Gives 0 instead of the DEFAULT constant when no rule fired. */
    public static final class IgnoresDefault extends EvaluatorIut {
        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            trace.results().stream().filter(r -> r.outcome() == Trace.Outcome.DEFAULT)
                    .forEach(r -> put(outputs, r.variable(), 0.0));
            return outputs;
        }
    }

    /** Gives 0 instead of keeping the previous value when DEFAULT is NC and no rule fired. */
    public static final class NcAsZero extends EvaluatorIut {
        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            trace.results().stream().filter(r -> r.outcome() == Trace.Outcome.NO_CHANGE)
                    .forEach(r -> put(outputs, r.variable(), 0.0));
            return outputs;
        }
    }

    /** Loads every program, even one the standard rejects (jFuzzyLogic-like). */
    public static final class AcceptsAnything extends EvaluatorIut {
        @Override
        protected Optional<LoadOutcome> veto(String fcl, Analysis analysis) {
            return analysis.program().isEmpty() ? Optional.of(new LoadOutcome.Loaded(List.of())) : Optional.empty();
        }
    }

    /** Rejects every program that negates (NOT, IS NOT): it does not implement that Table 9 row. */
    public static final class RejectsNot extends EvaluatorIut {
        @Override
        protected Optional<LoadOutcome> veto(String fcl, Analysis analysis) {
            return analysis.program().flatMap(Conditions::firstNegation)
                    .map(at -> new LoadOutcome.Rejected("NOT is not supported", OptionalInt.of(at.line())));
        }
    }

    static DefuzzificationMethod method(Defuzzification d) {
        return d.method().map(Located::value).orElse(DefuzzificationMethod.COG);
    }

    static double defaultValue(Defuzzification d) {
        return d.defaultValue().filter(v -> v instanceof DefaultValue.Constant)
                .map(v -> ((DefaultValue.Constant) v).value().value()).orElse(0.0);
    }

    static void put(Map<String, Double> outputs, String variable, double value) {
        String key = outputs.keySet().stream().filter(k -> k.equalsIgnoreCase(variable)).findFirst().orElse(variable);
        outputs.put(key, value);
    }

    static Program mapRuleBlocks(Program p, UnaryOperator<RuleBlock> f) {
        return new Program(p.sourceName(), p.functionBlocks().stream().map(fb -> new FunctionBlock(fb.name(),
                fb.variables(), fb.fuzzifications(), fb.defuzzifications(), fb.ruleBlocks().stream().map(f).toList(),
                fb.options(), fb.location())).toList());
    }

    static RuleBlock withAccumulation(RuleBlock rb, Located<AccumulationMethod> accu) {
        return new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), Optional.of(accu), rb.rules(),
                rb.location());
    }

    static RuleBlock withRules(RuleBlock rb, List<Rule> rules) {
        return new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), rb.accumulation(), rules, rb.location());
    }

}
