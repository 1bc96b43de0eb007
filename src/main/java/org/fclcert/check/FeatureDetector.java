package org.fclcert.check;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * Finds the conformance features (clause 6, Tables 8 to 10; {@link Feature}) a program uses, each
 * at the place that needs it. Usage: {@code new FeatureDetector().detect(program)}. Meant for
 * programs that passed the checks; on others it still answers, without throwing.
 *
 * <p>Detection rules (also tabulated in {@code docs/conformance-features.md}):
 * <ul>
 * <li>B-FB at every FUNCTION_BLOCK; E-VAR-LOCAL at every VAR variable.</li>
 * <li>Input (FUZZIFY) point terms: B-IN-TERM when at most 3 points, all x constant and all degrees the
 *     literal 0 or 1; E-IN-TERM-4 when exactly 4 points; O-MANY-POINTS when more than 4.</li>
 * <li>Output (DEFUZZIFY) terms: B-OUT-SINGLETON for a constant singleton; E-TERM-VARIABLE-POINT for a
 *     variable singleton; E-OUT-TERM-4 for a point term of at most 4 points; O-MANY-POINTS above 4.</li>
 * <li>At every point, input or output: E-TERM-VARIABLE-POINT for a variable x, O-DEGREES-0-1 for a
 *     literal degree strictly between 0 and 1, O-VAR-DEGREE for a variable degree. So a 4-point term
 *     with a variable x is E-IN-TERM-4 and E-TERM-VARIABLE-POINT; a 3-point term with a variable x or a
 *     degree 0.5 is not B-IN-TERM (Table 8 asks for constant points of degree 0 or 1).</li>
 * <li>Input singleton terms have no row in Tables 8 to 10 and give no feature.</li>
 * <li>AND: the declared algorithm at its declaration (B-AND-MIN, E-AND-PROD, E-AND-BDIF), used by the
 *     rules or not. When a block declares only OR, every AND in its rules needs the Table 3 pair of
 *     that OR, reported at the AND. OR likewise (E-OR-MAX, E-OR-ASUM, E-OR-BSUM).</li>
 * <li>ACT, ACCU, METHOD, DEFAULT, RANGE: the declared choice at its declaration. A rule block without ACT
 *     that concludes on an output's point term is activated by MIN: E-ACT-MIN at the rule block.</li>
 * <li>B-ONE-RULEBLOCK at the rule block of a function block with exactly one; with more, E-RULEBLOCKS
 *     at the second and every later block.</li>
 * <li>B-SUBCONDITIONS at every {@code v IS t}; E-NOT at every NOT and every {@code IS NOT}; E-PARENS at
 *     every parenthesis; E-COND-VARIABLE at every bare-variable subcondition.</li>
 * <li>B-ONE-SUBCONCLUSION at the subconclusion of a rule whose conclusion is one {@code v IS t};
 *     otherwise E-SUBCONCLUSIONS at every subconclusion after the first and at every bare variable.</li>
 * <li>E-WITH-CONST at every constant WITH, E-WITH-VAR at every variable WITH.</li>
 * <li>Dialect constructs visible in the model: O-SHAPE-... at every named-shape term (and no B/E term
 *     feature for it), O-HEDGE-... at every subcondition with that hedge, O-ACCU-PROBOR / O-ACCU-SUM
 *     and O-COGSS at their declarations. Constructs of the text only (comments, spellings, settings a
 *     dialect moves or supplies) are recorded by the dialect reader in {@code Program.dialectFeatures}.</li>
 * </ul>
 */
public final class FeatureDetector {
    /** Most points a Table 9 term may have. */
    private static final int MAX_EXTENSION_POINTS = 4;
    /** Most points a Table 8 input term may have. */
    private static final int MAX_BASIC_POINTS = 3;

    public FeatureReport detect(Program program) {
        List<FeatureUse> uses = new ArrayList<>();
        for (FunctionBlock block : program.functionBlocks()) {
            new Collector(uses).functionBlock(block);
        }
        uses.addAll(program.dialectFeatures());
        uses.sort(Comparator.comparing(FeatureUse::location).thenComparing(u -> u.feature().ordinal()));
        ConformanceLevel level = uses.stream().map(u -> u.feature().level())
                .reduce(ConformanceLevel.BASIC, ConformanceLevel::max);
        return new FeatureReport(level, uses);
    }

    /** Collects the uses of one function block. */
    private static final class Collector {
        private final List<FeatureUse> uses;

        Collector(List<FeatureUse> uses) {
            this.uses = uses;
        }

        private void use(Feature feature, SourceLocation at) {
            uses.add(new FeatureUse(feature, at));
        }

        void functionBlock(FunctionBlock block) {
            use(Feature.B_FB, block.location());
            for (Variable v : block.variables(VariableKind.LOCAL)) {
                use(Feature.E_VAR_LOCAL, v.location());
            }
            for (Fuzzification f : block.fuzzifications()) {
                f.terms().forEach(this::inputTerm);
            }
            for (Defuzzification d : block.defuzzifications()) {
                defuzzification(d);
            }
            List<RuleBlock> ruleBlocks = block.ruleBlocks();
            for (int i = 0; i < ruleBlocks.size(); i++) {
                if (ruleBlocks.size() == 1) {
                    use(Feature.B_ONE_RULEBLOCK, ruleBlocks.get(i).location());
                } else if (i > 0) {
                    use(Feature.E_RULEBLOCKS, ruleBlocks.get(i).location());
                }
                ruleBlock(ruleBlocks.get(i));
                impliedActivation(block, ruleBlocks.get(i));
            }
        }

        /**
         * A block without ACT that concludes {@code v IS t} on an output with point (non-singleton) terms is
         * activated by MIN (docs/semantics.md, point 3): E-ACT-MIN at the rule block, as the implied AND/OR pairs
         * are counted where they are needed. Singleton outputs are activated alike by MIN and PROD (w·d).
         */
        private void impliedActivation(FunctionBlock block, RuleBlock rb) {
            if (rb.activation().isPresent()) {
                return;
            }
            boolean pointConclusion = rb.rules().stream().flatMap(r -> r.conclusion().stream())
                    .filter(s -> !s.bareVariable())
                    .anyMatch(s -> block.defuzzification(s.variable()).flatMap(d -> d.term(s.term().get()))
                            .map(t -> !(t.function() instanceof MembershipFunction.Singleton)).orElse(false));
            if (pointConclusion) {
                use(Feature.E_ACT_MIN, rb.location());
            }
        }

        /** A named shape (dialects only): its O-SHAPE-... feature at the term; true when the term is one. */
        private boolean namedShape(Term term) {
            if (term.function() instanceof MembershipFunction.NamedShape shape) {
                Feature.byId(shape.kind().featureId()).ifPresent(f -> use(f, term.location()));
                return true;
            }
            return false;
        }

        private void inputTerm(Term term) {
            if (namedShape(term) || !(term.function() instanceof MembershipFunction.Points p)) {
                return;
            }
            List<Point> points = p.points();
            if (points.size() <= MAX_BASIC_POINTS && points.stream().allMatch(Collector::basicPoint)) {
                use(Feature.B_IN_TERM, term.location());
            } else if (points.size() == MAX_EXTENSION_POINTS) {
                use(Feature.E_IN_TERM_4, term.location());
            }
            pointQualities(term, points);
        }

        private static boolean basicPoint(Point p) {
            return p.x() instanceof Literal && p.degree() instanceof Literal d && (d.value() == 0 || d.value() == 1);
        }

        private void outputTerm(Term term) {
            if (namedShape(term)) {
                return;
            }
            if (term.function() instanceof MembershipFunction.Computed) {
                use(Feature.O_TAKAGI_SUGENO, term.location());
                return;
            }
            if (term.function() instanceof MembershipFunction.Singleton s) {
                use(s.value() instanceof VariableRef ? Feature.E_TERM_VARIABLE_POINT : Feature.B_OUT_SINGLETON,
                        term.location());
                return;
            }
            List<Point> points = ((MembershipFunction.Points) term.function()).points();
            if (points.size() <= MAX_EXTENSION_POINTS) {
                use(Feature.E_OUT_TERM_4, term.location());
            }
            pointQualities(term, points);
        }

        private void pointQualities(Term term, List<Point> points) {
            if (points.size() > MAX_EXTENSION_POINTS) {
                use(Feature.O_MANY_POINTS, term.location());
            }
            for (Point p : points) {
                if (p.x() instanceof VariableRef) {
                    use(Feature.E_TERM_VARIABLE_POINT, p.location());
                }
                if (p.degree() instanceof VariableRef) {
                    use(Feature.O_VAR_DEGREE, p.location());
                } else if (p.degree() instanceof Literal d && d.value() > 0 && d.value() < 1) {
                    use(Feature.O_DEGREES_0_1, p.location());
                }
            }
        }

        private void defuzzification(Defuzzification d) {
            d.range().ifPresent(r -> use(Feature.E_RANGE, r.location()));
            d.terms().forEach(this::outputTerm);
            d.method().ifPresent(m -> use(method(m.value()), m.location()));
            d.defaultValue().ifPresent(v -> use(v instanceof DefaultValue.NoChange
                    ? Feature.B_DEFAULT_NC : Feature.B_DEFAULT_VALUE, v.location()));
        }

        private void ruleBlock(RuleBlock rb) {
            rb.and().ifPresent(a -> use(and(a.value()), a.location()));
            rb.or().ifPresent(o -> use(or(o.value()), o.location()));
            rb.activation().ifPresent(a -> use(activation(a.value()), a.location()));
            rb.accumulation().ifPresent(a -> use(accumulation(a.value()), a.location()));
            for (Rule rule : rb.rules()) {
                condition(rb, rule.condition());
                conclusion(rule);
            }
        }

        private void condition(RuleBlock rb, Condition root) {
            for (Conditions.Node node : Conditions.nodes(root)) {
                Condition c = node.condition();
                if (c instanceof Condition.TermSubcondition t) {
                    use(Feature.B_SUBCONDITIONS, t.location());
                    if (t.negated()) {
                        use(Feature.E_NOT, t.location());
                    }
                    for (org.fclcert.model.Hedge h : t.hedges()) {
                        Feature.byId(h.featureId()).ifPresent(f -> use(f, t.location()));
                    }
                } else if (c instanceof Condition.VariableSubcondition) {
                    use(Feature.E_COND_VARIABLE, c.location());
                } else if (c instanceof Condition.Not) {
                    use(Feature.E_NOT, c.location());
                } else if (c instanceof Condition.Parenthesized) {
                    use(Feature.E_PARENS, c.location());
                } else if (c instanceof Condition.And && rb.and().isEmpty() && rb.or().isPresent()) {
                    use(and(rb.or().get().value().pair()), c.location());
                } else if (c instanceof Condition.Or && rb.or().isEmpty() && rb.and().isPresent()) {
                    use(or(rb.and().get().value().pair()), c.location());
                }
            }
        }

        private void conclusion(Rule rule) {
            List<Subconclusion> parts = rule.conclusion();
            boolean basic = parts.size() == 1 && !parts.get(0).bareVariable();
            for (int i = 0; i < parts.size(); i++) {
                Subconclusion s = parts.get(i);
                if (basic) {
                    use(Feature.B_ONE_SUBCONCLUSION, s.location());
                } else if (i > 0 || s.bareVariable()) {
                    use(Feature.E_SUBCONCLUSIONS, s.location());
                }
                s.weight().ifPresent(w -> use(w instanceof VariableRef ? Feature.E_WITH_VAR : Feature.E_WITH_CONST,
                        w.location()));
            }
        }
    }

    static Feature and(AndAlgorithm a) {
        return switch (a) {
            case MIN -> Feature.B_AND_MIN;
            case PROD -> Feature.E_AND_PROD;
            case BDIF -> Feature.E_AND_BDIF;
            case EPROD, HPROD, DPROD, NMIN -> Feature.O_OTHER_NORM;
        };
    }

    static Feature or(OrAlgorithm o) {
        return switch (o) {
            case MAX -> Feature.E_OR_MAX;
            case ASUM -> Feature.E_OR_ASUM;
            case BSUM -> Feature.E_OR_BSUM;
            case ESUM, HSUM, DSUM, NMAX -> Feature.O_OTHER_NORM;
        };
    }

    static Feature activation(ActivationMethod a) {
        return switch (a) {
            case MIN -> Feature.E_ACT_MIN;
            case PROD -> Feature.E_ACT_PROD;
            case BDIF, EPROD, HPROD, DPROD, NMIN -> Feature.O_ACT_OTHER_NORM;
        };
    }

    static Feature accumulation(AccumulationMethod a) {
        return switch (a) {
            case MAX -> Feature.B_ACCU_MAX;
            case BSUM -> Feature.E_ACCU_BSUM;
            case NSUM -> Feature.E_ACCU_NSUM;
            case PROBOR -> Feature.O_ACCU_PROBOR;
            case SUM -> Feature.O_ACCU_SUM;
            case ESUM, HSUM, DSUM, NMAX -> Feature.O_ACCU_OTHER_NORM;
        };
    }

    static Feature method(DefuzzificationMethod m) {
        return switch (m) {
            case COGS -> Feature.B_COGS;
            case COG -> Feature.E_COG;
            case COA -> Feature.E_COA;
            case LM -> Feature.E_LM;
            case RM -> Feature.E_RM;
            case MOM -> Feature.O_MOM;
            case COGSS -> Feature.O_COGSS;
            case TSUKAMOTO -> Feature.O_TSUKAMOTO;
        };
    }
}
