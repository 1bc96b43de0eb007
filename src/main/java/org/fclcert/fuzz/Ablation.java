package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Located;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;

/**
 * A program with one feature switched to its Basic Level counterpart (NSUM to MAX, PROD activation to none,
 * no weights, ..., and for B-COGS every singleton term concluded at most once), to tell whether a new disagreement is one already found: if it disappears when the
 * feature of a known finding is switched off, it is that finding again and need not be shrunk.
 */
final class Ablation {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;

    private Ablation() {
    }

    static Optional<Program> without(Program p, Feature f) {
        FunctionBlock fb = p.functionBlocks().get(0);
        FunctionBlock out = switch (f) {
            case E_ACCU_NSUM, E_ACCU_BSUM -> blocks(fb, rb -> new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(),
                    Optional.of(new Located<>(AccumulationMethod.MAX, AT)), rb.rules(), rb.location()));
            case E_ACT_PROD, E_ACT_MIN -> blocks(fb, rb -> new RuleBlock(rb.name(), rb.and(), rb.or(), Optional.empty(),
                    rb.accumulation(), rb.rules(), rb.location()));
            case E_AND_PROD, E_AND_BDIF, E_OR_ASUM, E_OR_BSUM -> blocks(fb, rb -> new RuleBlock(rb.name(),
                    Optional.of(new Located<>(AndAlgorithm.MIN, AT)), rb.or().map(o -> new Located<>(OrAlgorithm.MAX, AT)),
                    rb.activation(), rb.accumulation(), rb.rules(), rb.location()));
            case E_WITH_CONST, E_WITH_VAR -> blocks(fb, rb -> new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(),
                    rb.accumulation(), rb.rules().stream().map(r -> new Rule(r.name(), r.condition(), r.conclusion().stream()
                            .map(s -> new Subconclusion(s.variable(), s.term(), Optional.empty(), s.location())).toList(),
                            r.location())).toList(), rb.location()));
            case B_DEFAULT_NC -> new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications().stream()
                    .map(d -> d.defaultValue().orElse(null) instanceof DefaultValue.NoChange
                            ? new Defuzzification(d.variable(), d.range(), d.terms(), d.method(),
                                    Optional.of(new DefaultValue.Constant(Literal.of(0), AT)), d.location()) : d).toList(),
                    fb.ruleBlocks(), fb.options(), fb.location());
            case B_COGS -> termsConcludedOnce(fb);
            default -> null;
        };
        return out == null ? Optional.empty() : Optional.of(new Program(p.sourceName(), List.of(out)));
    }

    /**
     * Each singleton term concluded by several subconclusions split into as many terms at the same place, one per
     * subconclusion: the accumulated degree of each is then its one rule's, so that per term (Table 5) and per rule
     * (fuzzylite's COGS) give the same value. An implementation that sums CoGS per rule agrees with the reference on
     * the result; null when no singleton term is concluded twice.
     */
    private static FunctionBlock termsConcludedOnce(FunctionBlock fb) {
        Map<String, Integer> seen = new HashMap<>();
        Map<String, List<Term>> extra = new LinkedHashMap<>();
        List<RuleBlock> blocks = new ArrayList<>();
        boolean split = false;
        for (RuleBlock rb : fb.ruleBlocks()) {
            List<Rule> rules = new ArrayList<>();
            for (Rule r : rb.rules()) {
                List<Subconclusion> parts = new ArrayList<>();
                for (Subconclusion s : r.conclusion()) {
                    Optional<Term> term = s.term().flatMap(t -> singleton(fb, s.variable(), t));
                    if (term.isEmpty()) {
                        parts.add(s);
                        continue;
                    }
                    int n = seen.merge(Names.key(s.variable()) + "." + Names.key(term.get().name()), 1, Integer::sum);
                    if (n == 1) {
                        parts.add(s);
                        continue;
                    }
                    String name = term.get().name() + "_" + n;
                    extra.computeIfAbsent(Names.key(s.variable()), k -> new ArrayList<>())
                            .add(new Term(name, term.get().function(), AT));
                    parts.add(new Subconclusion(s.variable(), Optional.of(name), s.weight(), s.location()));
                    split = true;
                }
                rules.add(new Rule(r.name(), r.condition(), parts, r.location()));
            }
            blocks.add(new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(), rb.accumulation(), rules, rb.location()));
        }
        if (!split) {
            return null;
        }
        List<Defuzzification> defs = fb.defuzzifications().stream().map(d -> {
            List<Term> more = extra.get(Names.key(d.variable()));
            if (more == null) {
                return d;
            }
            List<Term> terms = new ArrayList<>(d.terms());
            terms.addAll(more);
            return new Defuzzification(d.variable(), d.range(), terms, d.method(), d.defaultValue(), d.location());
        }).toList();
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), defs, blocks, fb.options(), fb.location());
    }

    private static Optional<Term> singleton(FunctionBlock fb, String variable, String term) {
        return fb.defuzzification(variable).flatMap(d -> d.terms().stream().filter(t -> Names.same(t.name(), term))
                .findFirst()).filter(t -> t.function() instanceof MembershipFunction.Singleton);
    }

    private static FunctionBlock blocks(FunctionBlock fb, java.util.function.UnaryOperator<RuleBlock> f) {
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(),
                fb.ruleBlocks().stream().map(f).toList(), fb.options(), fb.location());
    }
}
