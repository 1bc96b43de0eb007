package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeSet;
import org.fclcert.model.Condition;
import org.fclcert.model.Defuzzification;
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
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * Random input steps for a program, each judged fair before it is kept. A linguistic input takes values on
 * its terms' breakpoints, inside plateaus, halfway between breakpoints (where symmetric terms tie), just inside
 * a term's foot (a degree of about 1e-7, which an implementation may take for zero), outside all terms, and
 * anywhere; an input read as a degree (WITH, a bare subcondition, a variable degree) takes
 * 0, 1, simple fractions or any value in [0, 1]; an input giving a point takes values around that point's
 * neighbours. Programs with state (NC, local variables) get longer sequences with more steps outside the
 * terms, so that nothing fires and the previous value must be kept.
 */
public final class VectorGenerator {
    private final FairnessJudge fairness;

    public VectorGenerator(FairnessJudge fairness) {
        this.fairness = fairness;
    }

    /** The steps of one program (possibly fewer than asked when candidates are unfair; possibly none). */
    public List<Map<String, Double>> steps(ReferenceProgram program, Random r) {
        Roles roles = Roles.of(program.block());
        int n = program.stateful() ? 3 + r.nextInt(6) : 2 + r.nextInt(7);
        double outside = program.stateful() ? 0.3 : 0.12;
        List<Map<String, Double>> steps = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            for (int attempt = 0; attempt < 4; attempt++) {
                Map<String, Double> step = new LinkedHashMap<>();
                for (Variable v : program.block().variables(VariableKind.INPUT)) {
                    step.put(v.name(), roles.value(v.name(), r, outside));
                }
                if (fairness.fair(program, steps, step)) {
                    steps.add(step);
                    break;
                }
            }
        }
        return steps;
    }

    /** How each input is read, and the values worth trying for it. */
    static final class Roles {
        private final Map<String, double[]> linguistic = new HashMap<>();
        /** Per input: just inside a term's foot, where its degree is about 1e-7. */
        private final Map<String, double[]> nearFeet = new HashMap<>();
        private final Map<String, double[]> parameters = new HashMap<>();
        private final java.util.Set<String> degrees = new java.util.HashSet<>();

        static Roles of(FunctionBlock fb) {
            Roles roles = new Roles();
            for (Fuzzification f : fb.fuzzifications()) {
                TreeSet<Double> xs = new TreeSet<>();
                TreeSet<Double> special = new TreeSet<>();
                TreeSet<Double> feet = new TreeSet<>();
                for (Term t : f.terms()) {
                    if (t.function() instanceof MembershipFunction.Points p) {
                        List<Point> points = p.points();
                        for (int i = 0; i < points.size(); i++) {
                            Point pt = points.get(i);
                            if (pt.x() instanceof Literal l) {
                                xs.add(l.value());
                                if (i > 0 && points.get(i - 1).x() instanceof Literal prev
                                        && points.get(i - 1).degree().equals(pt.degree())) {
                                    special.add((prev.value() + l.value()) / 2);     // inside a plateau
                                }
                                if (i > 0 && points.get(i - 1).x() instanceof Literal prev && prev.value() < l.value()) {
                                    foot(feet, prev.value(), points.get(i - 1).degree(), l.value(), pt.degree());
                                }
                            }
                        }
                    } else if (t.function() instanceof MembershipFunction.Singleton s && s.value() instanceof Literal l) {
                        xs.add(l.value());
                    }
                }
                Double prev = null;
                for (double x : xs) {
                    if (prev != null) {
                        special.add((prev + x) / 2);
                    }
                    prev = x;
                }
                special.addAll(xs);
                roles.linguistic.put(Names.key(f.variable()), special.stream().mapToDouble(Double::doubleValue).toArray());
                roles.nearFeet.put(Names.key(f.variable()), feet.stream().mapToDouble(Double::doubleValue).toArray());
            }
            for (Fuzzification f : fb.fuzzifications()) {
                for (Term t : f.terms()) {
                    pointOperands(roles, t);
                }
            }
            for (Defuzzification d : fb.defuzzifications()) {
                for (Term t : d.terms()) {
                    pointOperands(roles, t);
                }
            }
            for (RuleBlock rb : fb.ruleBlocks()) {
                for (Rule rule : rb.rules()) {
                    for (Condition node : ConditionTrees.nodes(rule.condition())) {
                        if (node instanceof Condition.VariableSubcondition v) {
                            roles.degrees.add(Names.key(v.variable()));
                        }
                    }
                    for (Subconclusion s : rule.conclusion()) {
                        s.weight().filter(w -> w instanceof VariableRef)
                                .ifPresent(w -> roles.degrees.add(Names.key(((VariableRef) w).name())));
                    }
                }
            }
            return roles;
        }

        /** On a rising or falling segment from degree 0: the input where the degree is 1e-7 of the other end's. */
        private static void foot(java.util.Set<Double> feet, double x0, Object d0, double x1, Object d1) {
            if (!(d0 instanceof Literal a && d1 instanceof Literal b) || (a.value() == 0) == (b.value() == 0)) {
                return;
            }
            double near = a.value() == 0 ? x0 + (x1 - x0) * 1e-7 : x1 - (x1 - x0) * 1e-7;
            if (near > x0 && near < x1) {
                feet.add(near);
            }
        }

        private static void pointOperands(Roles roles, Term t) {
            if (t.function() instanceof MembershipFunction.Points p) {
                double lo = Double.POSITIVE_INFINITY;
                double hi = Double.NEGATIVE_INFINITY;
                for (Point pt : p.points()) {
                    if (pt.x() instanceof Literal l) {
                        lo = Math.min(lo, l.value());
                        hi = Math.max(hi, l.value());
                    }
                }
                for (Point pt : p.points()) {
                    if (pt.x() instanceof VariableRef v) {
                        roles.parameters.put(Names.key(v.name()), lo <= hi ? new double[] {lo, hi} : new double[] {0, 1});
                    }
                    if (pt.degree() instanceof VariableRef v) {
                        roles.degrees.add(Names.key(v.name()));
                    }
                }
            } else if (t.function() instanceof MembershipFunction.Singleton s && s.value() instanceof VariableRef v) {
                roles.parameters.put(Names.key(v.name()), new double[] {-10, 100});
            }
        }

        double value(String input, Random r, double outside) {
            String key = Names.key(input);
            if (degrees.contains(key)) {
                double[] simple = {0, 1, 0.5, 0.25, 0.75};
                return r.nextDouble() < 0.5 ? simple[r.nextInt(simple.length)] : r.nextDouble();
            }
            double[] range = parameters.get(key);
            if (range != null) {
                double v = range[0] + (range[1] - range[0]) * r.nextDouble();
                return r.nextBoolean() ? Math.round(v * 100) / 100.0 : v;
            }
            double[] special = linguistic.get(key);
            if (special == null || special.length == 0) {
                return r.nextBoolean() ? 0 : r.nextDouble();
            }
            double lo = special[0];
            double hi = special[special.length - 1];
            double span = hi > lo ? hi - lo : Math.max(1, Math.abs(lo));
            double[] feet = nearFeet.getOrDefault(key, new double[0]);
            if (feet.length > 0 && r.nextDouble() < 0.05) {
                return feet[r.nextInt(feet.length)];
            }
            double u = r.nextDouble();
            if (u < outside) {
                return r.nextBoolean() ? lo - span * (0.05 + r.nextDouble() * 0.5) : hi + span * (0.05 + r.nextDouble() * 0.5);
            }
            if (u < outside + 0.4) {
                return special[r.nextInt(special.length)];
            }
            double v = lo - 0.1 * span + 1.2 * span * r.nextDouble();
            return r.nextBoolean() ? ProgramGenerator.round(Math.round(v * 1000) / 1000.0) : v;
        }
    }
}
