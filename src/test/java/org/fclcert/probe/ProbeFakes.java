package org.fclcert.probe;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Trace;
import org.fclcert.harness.fakes.EvaluatorIut;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Program;
import org.fclcert.model.Term;

/** Implementations with one known Table 11 limit each, built on the correct {@link EvaluatorIut}. */
final class ProbeFakes {
    private ProbeFakes() {
    }

    private static Optional<LoadOutcome> reject(String message) {
        return Optional.of(new LoadOutcome.Rejected(message, OptionalInt.empty()));
    }

    /** Rejects any term of more than three points (input or output). */
    static class MaxThreePoints extends EvaluatorIut {
        @Override
        protected Optional<LoadOutcome> veto(String fcl, Analysis analysis) {
            Optional<Program> p = analysis.program();
            if (p.isPresent() && p.get().functionBlocks().stream().anyMatch(fb -> fb.fuzzifications().stream()
                    .anyMatch(f -> f.terms().stream().anyMatch(MaxThreePoints::tooMany)) || fb.defuzzifications()
                    .stream().anyMatch(d -> d.terms().stream().anyMatch(MaxThreePoints::tooMany)))) {
                return reject("at most 3 points per term");
            }
            return Optional.empty();
        }

        private static boolean tooMany(Term t) {
            return t.function() instanceof MembershipFunction.Points pts && pts.points().size() > 3;
        }
    }

    /** Rejects a rule block of more than ten rules, and declares (truthfully) that limit. */
    static final class MaxTenRulesPerBlock extends EvaluatorIut {
        @Override
        public IutInfo hello() {
            return new IutInfo("ten-rules", "test", "java:" + getClass().getName(), List.of(),
                    Map.of("max-rules-per-block", 10L, "max-rule-blocks", 500L));
        }

        @Override
        protected Optional<LoadOutcome> veto(String fcl, Analysis analysis) {
            if (analysis.program().isPresent() && analysis.program().get().functionBlocks().stream()
                    .anyMatch(fb -> fb.ruleBlocks().stream().anyMatch(rb -> rb.rules().size() > 10))) {
                return reject("at most 10 rules per rule block");
            }
            return Optional.empty();
        }
    }

    /**
     * Case-sensitive names: rejects a program in which a name is spelt in two letter cases (keywords, which
     * the generator always writes one way, aside), as an implementation comparing names exactly would
     * find an undeclared name.
     */
    static final class CaseSensitive extends EvaluatorIut {
        private static final Pattern WORD = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

        @Override
        protected Optional<LoadOutcome> veto(String fcl, Analysis analysis) {
            Map<String, String> spelling = new HashMap<>();
            Matcher m = WORD.matcher(fcl);
            while (m.find()) {
                String w = m.group();
                String seen = spelling.putIfAbsent(w.toLowerCase(), w);
                if (seen != null && !seen.equals(w)) {
                    return reject("'" + w + "' is not declared");
                }
            }
            return Optional.empty();
        }
    }

    /** Membership degrees kept as integers 0 … 200: every activation rounded to a multiple of 1/200 (CoGS outputs). */
    static final class QuantisedDegrees extends EvaluatorIut {
        @Override
        protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
            for (Defuzzification d : block.defuzzifications()) {
                Map<String, Double> degree = new LinkedHashMap<>();
                for (Trace.Activation a : trace.activations()) {
                    if (a.variable().equalsIgnoreCase(d.variable()) && a.term().isPresent()) {
                        double q = Math.round(a.activatedDegree() * 200) / 200.0;
                        degree.merge(a.term().get().toLowerCase(), q, Math::max);
                    }
                }
                double num = 0;
                double den = 0;
                for (Term t : d.terms()) {
                    Double q = degree.get(t.name().toLowerCase());
                    if (q == null || !(t.function() instanceof MembershipFunction.Singleton s
                            && s.value() instanceof Literal l)) {
                        continue;
                    }
                    num += q * l.value();
                    den += q;
                }
                if (den > 0) {
                    double value = num / den;
                    outputs.keySet().stream().filter(k -> k.equalsIgnoreCase(d.variable())).findFirst()
                            .ifPresent(k -> outputs.put(k, value));
                }
            }
            return outputs;
        }
    }

    /** Reads {@code //} comments to the end of the line and rejects {@code (* *)}, as fuzzylite 6.0 does. */
    static final class SlashCommentsOnly extends EvaluatorIut {
        @Override
        public LoadOutcome load(String fcl) {
            if (fcl.contains("(*")) {
                return new LoadOutcome.Rejected("'(*' is not a comment", OptionalInt.empty());
            }
            return super.load(fcl.replaceAll("//[^\n]*", ""));
        }
    }

    /** Drops every rule after the tenth of a block without saying so (a silently wrong result). */
    static final class DropsRulesAfterTen extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return new Program(p.sourceName(), p.functionBlocks().stream().map(fb -> new FunctionBlock(fb.name(),
                    fb.variables(), fb.fuzzifications(), fb.defuzzifications(), fb.ruleBlocks().stream()
                    .map(rb -> new org.fclcert.model.RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(),
                            rb.accumulation(), rb.rules().subList(0, Math.min(10, rb.rules().size())), rb.location()))
                    .toList(), fb.options(), fb.location())).toList());
        }
    }
}
