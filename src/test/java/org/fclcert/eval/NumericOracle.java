package org.fclcert.eval;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Operand;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.VariableRef;

/**
 * An independent, deliberately naive evaluator for checking the closed-form one: it walks the model
 * directly (no compilation), evaluates membership functions from the model's points, and
 * defuzzifies by a dense midpoint rule. It supports what the random programs use: one rule block
 * level of inputs (no bare-variable conclusions feeding later blocks), points with distinct x
 * (constants or input variables, sorted here).
 *
 * <p>NSUM is evaluated as the plain sum: its normalisation divides the whole set by one constant,
 * which CoG, CoA, LM and RM (and CoGS) do not see.
 */
final class NumericOracle {
    /** One activated subconclusion: the term's points, rule degree, weight, ACT. */
    record Activation(double[] x, double[] y, double degree, double weight, boolean prod) {
    }

    private final FunctionBlock fb;
    private final Map<String, Double> inputs;

    NumericOracle(FunctionBlock fb, Map<String, Double> inputs) {
        this.fb = fb;
        this.inputs = inputs;
    }

    /** Piece-wise linear membership straight from the definition of 5.2.2 (ascending x). */
    static double membership(double[] x, double[] y, double u) {
        int n = x.length;
        if (u <= x[0]) {
            return y[0];
        }
        if (u >= x[n - 1]) {
            return y[n - 1];
        }
        for (int i = 1; i < n; i++) {
            if (u <= x[i]) {
                double t = (u - x[i - 1]) / (x[i] - x[i - 1]);
                return y[i - 1] + t * (y[i] - y[i - 1]);
            }
        }
        throw new AssertionError();
    }

    private double value(Operand o) {
        return o instanceof Literal l ? l.value() : inputs.get(((VariableRef) o).name());
    }

    /** The term's points with their current values, sorted by x (List.sort is stable). */
    private double[][] points(Term t) {
        List<double[]> pts = new ArrayList<>();
        for (Point p : ((MembershipFunction.Points) t.function()).points()) {
            pts.add(new double[] {value(p.x()), value(p.degree())});
        }
        pts.sort((a, b) -> Double.compare(a[0], b[0]));
        double[] x = pts.stream().mapToDouble(p -> p[0]).toArray();
        double[] y = pts.stream().mapToDouble(p -> p[1]).toArray();
        return new double[][] {x, y};
    }

    private double termDegree(String variable, String term) {
        Term t = fb.fuzzification(variable).orElseThrow().term(term).orElseThrow();
        double[][] p = points(t);
        return membership(p[0], p[1], inputs.get(variable));
    }

    double condition(Condition c, AndAlgorithm and, OrAlgorithm or) {
        if (c instanceof Condition.TermSubcondition t) {
            double d = termDegree(t.variable(), t.term());
            return t.negated() ? 1 - d : d;
        }
        if (c instanceof Condition.VariableSubcondition v) {
            return Math.min(1, Math.max(0, inputs.get(v.variable())));
        }
        if (c instanceof Condition.Not n) {
            return 1 - condition(n.operand(), and, or);
        }
        if (c instanceof Condition.Parenthesized p) {
            return condition(p.inner(), and, or);
        }
        boolean isAnd = c instanceof Condition.And;
        List<Condition> ops = isAnd ? ((Condition.And) c).operands() : ((Condition.Or) c).operands();
        double acc = condition(ops.get(0), and, or);
        for (int i = 1; i < ops.size(); i++) {
            double b = condition(ops.get(i), and, or);
            acc = isAnd ? switch (and) {
                case MIN -> Math.min(acc, b);
                case PROD -> acc * b;
                case BDIF -> Math.max(0, acc + b - 1);
                default -> throw new IllegalArgumentException("the oracle knows the algorithms of Table 3 only");
            } : switch (or) {
                case MAX -> Math.max(acc, b);
                case ASUM -> acc + b - acc * b;
                case BSUM -> Math.min(1, acc + b);
                default -> throw new IllegalArgumentException("the oracle knows the algorithms of Table 3 only");
            };
        }
        return acc;
    }

    /** Every subconclusion on {@code output}, over all rule blocks, with its rule's degree. */
    List<Activation> activations(String output) {
        Defuzzification d = fb.defuzzification(output).orElseThrow();
        List<Activation> out = new ArrayList<>();
        for (RuleBlock rb : fb.ruleBlocks()) {
            AndAlgorithm and = rb.and().map(Located::value)
                    .orElseGet(() -> rb.or().map(o -> o.value().pair()).orElse(AndAlgorithm.MIN));
            OrAlgorithm or = rb.or().map(Located::value).orElse(and.pair());
            boolean prod = rb.activation().map(Located::value).orElse(ActivationMethod.MIN) == ActivationMethod.PROD;
            for (Rule r : rb.rules()) {
                double degree = condition(r.condition(), and, or);
                for (Subconclusion s : r.conclusion()) {
                    if (Names.same(s.variable(), output)) {
                        double w = s.weight().map(this::value).map(x -> Math.min(1, Math.max(0, x))).orElse(1.0);
                        Term t = d.term(s.term().orElseThrow()).orElseThrow();
                        double[][] p = t.function() instanceof MembershipFunction.Singleton sg
                                ? new double[][] {{value(sg.value())}, {1}} : points(t);
                        out.add(new Activation(p[0], p[1], degree, w, prod));
                    }
                }
            }
        }
        return out;
    }

    static double accumulated(List<Activation> acts, AccumulationMethod accu, double u) {
        double acc = 0;
        for (Activation a : acts) {
            double mu = membership(a.x(), a.y(), u);
            double c = a.weight() * (a.prod() ? a.degree() * mu : Math.min(a.degree(), mu));
            acc = accu == AccumulationMethod.MAX ? Math.max(acc, c) : acc + c;
        }
        return accu == AccumulationMethod.BSUM ? Math.min(1, acc) : acc;
    }

    /**
     * As {@link #accumulated}, for arguments that only grow between calls: each activation keeps a
     * cursor on the first of its points at or right of u, so a sample costs O(1) per activation.
     */
    private static final class Sweep {
        private final double[][] x;
        private final double[][] y;
        private final double[] degree;
        private final double[] weight;
        private final boolean[] prod;
        private final int[] cursor;
        private final boolean max;
        private final boolean bounded;

        Sweep(List<Activation> acts, AccumulationMethod accu) {
            int k = acts.size();
            x = new double[k][];
            y = new double[k][];
            degree = new double[k];
            weight = new double[k];
            prod = new boolean[k];
            cursor = new int[k];
            for (int i = 0; i < k; i++) {
                x[i] = acts.get(i).x();
                y[i] = acts.get(i).y();
                degree[i] = acts.get(i).degree();
                weight[i] = acts.get(i).weight();
                prod[i] = acts.get(i).prod();
            }
            max = accu == AccumulationMethod.MAX;
            bounded = accu == AccumulationMethod.BSUM;
        }

        double at(double u) {
            double acc = 0;
            for (int k = 0; k < cursor.length; k++) {
                double[] xk = x[k];
                double[] yk = y[k];
                int i = cursor[k];
                while (i < xk.length && xk[i] < u) {
                    i++;
                }
                cursor[k] = i;
                double mu = i == 0 ? yk[0] : i == xk.length ? yk[xk.length - 1]
                        : yk[i - 1] + (u - xk[i - 1]) / (xk[i] - xk[i - 1]) * (yk[i] - yk[i - 1]);
                double c = weight[k] * (prod[k] ? degree[k] * mu : Math.min(degree[k], mu));
                acc = max ? Math.max(acc, c) : acc + c;
            }
            return bounded ? Math.min(1, acc) : acc;
        }
    }

    /** Dense midpoint-rule results over [lo, hi]: {CoG, CoA, LM, RM}; NaN where the set is empty. */
    static double[] defuzzify(List<Activation> all, AccumulationMethod accu, double lo, double hi, int samples) {
        // an activation of height 0 adds nothing under MAX or a sum; leaving it out only saves time
        List<Activation> acts = all.stream().filter(a -> a.degree() * a.weight() > 0).toList();
        double h = (hi - lo) / samples;
        double[] mu = new double[samples];
        double area = 0;
        double moment = 0;
        Sweep sweep = new Sweep(acts, accu);
        for (int i = 0; i < samples; i++) {
            double u = lo + (i + 0.5) * h;
            mu[i] = sweep.at(u);
            area += mu[i];
            moment += u * mu[i];
        }
        double cog = area > 0 ? moment / area : Double.NaN;
        double coa = area > 0 ? (halfFromLeft(mu, lo, h, area) + halfFromRight(mu, lo, h, area)) / 2 : Double.NaN;
        double[] extremes = extremes(acts, accu, lo, hi, mu, h);
        return new double[] {cog, coa, extremes[0], extremes[1]};
    }

    private static double halfFromLeft(double[] mu, double lo, double h, double area) {
        double cum = 0;
        for (int i = 0; i < mu.length; i++) {
            if (cum + mu[i] >= area / 2) {
                return lo + (i + (area / 2 - cum) / mu[i]) * h;
            }
            cum += mu[i];
        }
        return lo + mu.length * h;
    }

    private static double halfFromRight(double[] mu, double lo, double h, double area) {
        double cum = 0;
        for (int i = mu.length - 1; i >= 0; i--) {
            if (cum + mu[i] >= area / 2) {
                return lo + (i + 1 - (area / 2 - cum) / mu[i]) * h;
            }
            cum += mu[i];
        }
        return lo;
    }

    /**
     * LM and RM: the supremum is taken over the samples and over the points where a maximum of a
     * piece-wise linear set can sit (term points, clip crossings, interval ends, the places where
     * a bounded sum reaches 1), found here by brute force.
     */
    private static double[] extremes(List<Activation> acts, AccumulationMethod accu, double lo, double hi,
            double[] mu, double h) {
        double[] cand = candidates(acts, accu, lo, hi);
        double sup = 0;
        for (double m : mu) {
            sup = Math.max(sup, m);
        }
        double[] cmu = new double[cand.length];
        for (int i = 0; i < cand.length; i++) {
            cmu[i] = accumulated(acts, accu, cand[i]);
            sup = Math.max(sup, cmu[i]);
        }
        if (!(sup > 0)) {
            return new double[] {Double.NaN, Double.NaN};
        }
        double eps = 1e-12 * sup;
        double lm = Double.POSITIVE_INFINITY;
        double rm = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < cand.length; i++) {
            if (cmu[i] >= sup - eps) {
                lm = Math.min(lm, cand[i]);
                rm = Math.max(rm, cand[i]);
            }
        }
        for (int i = 0; i < mu.length; i++) {
            if (mu[i] >= sup - eps) {
                lm = Math.min(lm, lo + (i + 0.5) * h);
                rm = Math.max(rm, lo + (i + 0.5) * h);
            }
        }
        return new double[] {lm, rm};
    }

    private static double[] candidates(List<Activation> acts, AccumulationMethod accu, double lo, double hi) {
        List<Double> c = new ArrayList<>(List.of(lo, hi));
        for (Activation a : acts) {
            for (int i = 0; i < a.x().length; i++) {
                c.add(a.x()[i]);
                if (i > 0 && !a.prod()) {
                    double y0 = a.y()[i - 1];
                    double y1 = a.y()[i];
                    if ((y0 - a.degree()) * (y1 - a.degree()) < 0) {
                        c.add(a.x()[i - 1] + (a.degree() - y0) / (y1 - y0) * (a.x()[i] - a.x()[i - 1]));
                    }
                }
            }
        }
        double[] s = c.stream().mapToDouble(Double::doubleValue).filter(u -> u >= lo && u <= hi).sorted().toArray();
        if (accu != AccumulationMethod.BSUM) {
            return s;
        }
        List<Double> more = new ArrayList<>();
        for (int i = 0; i + 1 < s.length; i++) {
            double s0 = sum(acts, s[i]);
            double s1 = sum(acts, s[i + 1]);
            if ((s0 - 1) * (s1 - 1) < 0) {
                more.add(s[i] + (1 - s0) / (s1 - s0) * (s[i + 1] - s[i]));
            }
        }
        double[] all = Arrays.copyOf(s, s.length + more.size());
        for (int i = 0; i < more.size(); i++) {
            all[s.length + i] = more.get(i);
        }
        return all;
    }

    private static double sum(List<Activation> acts, double u) {
        return accumulated(acts, AccumulationMethod.NSUM, u);
    }

    /** Singletons: per-term accumulation, then CoGS, LM or RM; {CoGS, LM, RM}. */
    static double[] singletons(List<Activation> acts, AccumulationMethod accu, List<Double> termValues) {
        double[] mu = new double[termValues.size()];
        for (Activation a : acts) {
            int t = termValues.indexOf(a.x()[0]);
            double c = a.weight() * a.degree();
            mu[t] = accu == AccumulationMethod.MAX ? Math.max(mu[t], c)
                    : accu == AccumulationMethod.BSUM ? Math.min(1, mu[t] + c) : mu[t] + c;
        }
        double num = 0;
        double den = 0;
        double sup = 0;
        for (int t = 0; t < mu.length; t++) {
            num += termValues.get(t) * mu[t];
            den += mu[t];
            sup = Math.max(sup, mu[t]);
        }
        double lm = Double.NaN;
        double rm = Double.NaN;
        for (int t = 0; t < mu.length; t++) {
            if (sup > 0 && mu[t] >= sup * (1 - 1e-12)) {
                double u = termValues.get(t);
                lm = Double.isNaN(lm) ? u : Math.min(lm, u);
                rm = Double.isNaN(rm) ? u : Math.max(rm, u);
            }
        }
        return new double[] {den > 0 ? num / den : Double.NaN, lm, rm};
    }
}
