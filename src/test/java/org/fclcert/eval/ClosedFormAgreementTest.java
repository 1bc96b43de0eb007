package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.stream.Collectors;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.junit.jupiter.api.Test;

/**
 * Property test: on randomly generated programs (fixed seed) using every AND/OR pair, NOT,
 * parentheses, bare-variable subconditions, both activations, all three accumulations, constant and
 * variable weights, RANGE and no RANGE, and every defuzzification method, the closed-form evaluator
 * agrees with {@link NumericOracle}: a dense midpoint rule with 10^6 samples over the
 * defuzzification interval. Agreement is |closed − numeric| ≤ 1e-6 · W, W the width of the
 * interval (the scale of every result; results near 0 make a purely relative bound meaningless).
 * Singleton outputs are compared to the oracle's direct sums to 1e-12.
 */
class ClosedFormAgreementTest {
    private static final int PROGRAMS = 200;
    private static final int SAMPLES = 1_000_000;
    private static final double DEFAULT = -999;
    private static final DefuzzificationMethod[] CONTINUOUS = {
        DefuzzificationMethod.COG, DefuzzificationMethod.COA, DefuzzificationMethod.LM, DefuzzificationMethod.RM};

    @Test
    void closedFormAgreesWithDenseNumericIntegration() throws EvaluationException {
        Random rnd = new Random(61131_7L);
        int fired = 0;
        int[] methodSeen = new int[4];
        for (int p = 0; p < PROGRAMS; p++) {
            Generator g = new Generator(rnd);
            FunctionBlock fb = g.block();
            Map<String, Double> in = Map.of("x1", uniform(rnd, -1, 11), "x2", uniform(rnd, -1, 11),
                    "w", uniform(rnd, -0.2, 1.2));
            NumericOracle oracle = new NumericOracle(fb, in);
            Defuzzification y = fb.defuzzification("y").orElseThrow();
            double lo = g.lo;
            double hi = g.hi;
            List<NumericOracle.Activation> acts = oracle.activations("y");
            double[] numeric = NumericOracle.defuzzify(acts, g.accu, lo, hi, SAMPLES);
            for (int m = 0; m < 4; m++) {
                FunctionBlock variant = withMethod(fb, y, CONTINUOUS[m]);
                FunctionBlockInstance inst = Evaluator.load(new Program("random.fcl", List.of(variant))).newInstance();
                for (Map.Entry<String, Double> e : in.entrySet()) {
                    inst.set(e.getKey(), e.getValue());
                }
                inst.evaluate();
                double expected = Double.isNaN(numeric[m]) ? DEFAULT : numeric[m];
                String what = "program " + p + " " + CONTINUOUS[m].keyword() + " " + g.description();
                assertEquals(expected, inst.get("y"), 1e-6 * (hi - lo), () -> explain(what, inst, acts));
                if (!Double.isNaN(numeric[m])) {
                    methodSeen[m]++;
                }
            }
            fired += Double.isNaN(numeric[0]) ? 0 : 1;
            checkSingletons(fb, oracle, g, in, p);
        }
        assertTrue(fired > PROGRAMS * 3 / 4, "most random programs fire some rule: " + fired);
        for (int m = 0; m < 4; m++) {
            assertTrue(methodSeen[m] > PROGRAMS / 2, CONTINUOUS[m] + " compared " + methodSeen[m]);
        }
    }

    /** On failure: the closed form's accumulated set next to the oracle's activations. */
    private static String explain(String what, FunctionBlockInstance inst, List<NumericOracle.Activation> acts) {
        Trace t = new Trace();
        try {
            inst.evaluate(t);
        } catch (EvaluationException e) {
            return what + " " + e;
        }
        return what + "\nclosed form set " + t.accumulatedSet("y").orElseThrow().breakpoints() + "\nactivations "
                + acts.stream().map(a -> java.util.Arrays.toString(a.x()) + java.util.Arrays.toString(a.y())
                        + " d=" + a.degree() + " w=" + a.weight() + " prod=" + a.prod()).toList();
    }

    private static void checkSingletons(FunctionBlock fb, NumericOracle oracle, Generator g, Map<String, Double> in,
            int p) throws EvaluationException {
        Defuzzification z = fb.defuzzification("z").orElseThrow();
        List<Double> values = z.terms().stream()
                .map(t -> ((Literal) ((MembershipFunction.Singleton) t.function()).value()).value()).toList();
        double[] direct = NumericOracle.singletons(oracle.activations("z"), g.accu, values);
        DefuzzificationMethod[] methods = {DefuzzificationMethod.COGS, DefuzzificationMethod.LM,
            DefuzzificationMethod.RM};
        for (int m = 0; m < 3; m++) {
            FunctionBlock variant = withMethod(fb, z, methods[m]);
            FunctionBlockInstance inst = Evaluator.load(new Program("random.fcl", List.of(variant))).newInstance();
            for (Map.Entry<String, Double> e : in.entrySet()) {
                inst.set(e.getKey(), e.getValue());
            }
            inst.evaluate();
            double expected = Double.isNaN(direct[m]) ? DEFAULT : direct[m];
            assertEquals(expected, inst.get("z"), 1e-12 * Math.max(1, Math.abs(expected)),
                    "program " + p + " singletons " + methods[m].keyword());
        }
    }

    private static FunctionBlock withMethod(FunctionBlock fb, Defuzzification d, DefuzzificationMethod m) {
        List<Defuzzification> ds = fb.defuzzifications().stream()
                .map(x -> x == d ? new Defuzzification(d.variable(), d.range(), d.terms(),
                        Optional.of(new Located<>(m, Fcl.AT)), d.defaultValue(), Fcl.AT) : x)
                .toList();
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), ds, fb.ruleBlocks(), fb.options(),
                Fcl.AT);
    }

    private static double uniform(Random rnd, double lo, double hi) {
        return lo + (hi - lo) * rnd.nextDouble();
    }

    /** One random program: inputs x1, x2 (three terms each) and w; outputs y (points) and z (singletons). */
    private static final class Generator {
        private final Random rnd;
        final AccumulationMethod accu;
        double lo;
        double hi;
        private final List<String> notes = new ArrayList<>();

        Generator(Random rnd) {
            this.rnd = rnd;
            this.accu = AccumulationMethod.values()[rnd.nextInt(3)];
        }

        String description() {
            return accu + " " + String.join(" ", notes);
        }

        FunctionBlock block() {
            Fcl.Block b = Fcl.block("random").input("x1").input("x2").input("w").output("y").output("z")
                    .fuzzify("x1", inputTerm("a"), inputTerm("b"), inputTerm("c"))
                    .fuzzify("x2", inputTerm("a"), inputTerm("b"), inputTerm("c"));
            b.defuzzify(pointOutput());
            Fcl.Out z = Fcl.defuzzify("z", DefuzzificationMethod.COGS).defaultValue(DEFAULT);
            double[] zs = distinct(3, -50, 50);
            for (int i = 0; i < 3; i++) {
                z.term("s" + i, Fcl.single(zs[i]));
            }
            b.defuzzify(z);
            int blocks = 1 + rnd.nextInt(2);
            for (int i = 0; i < blocks; i++) {
                b.rules(ruleBlock("rb" + i));
            }
            return b.build();
        }

        private Term inputTerm(String name) {
            int n = 2 + rnd.nextInt(3);
            double[] x = distinct(n, -1, 11);
            double[] xy = new double[2 * n];
            for (int i = 0; i < n; i++) {
                xy[2 * i] = x[i];
                xy[2 * i + 1] = degree();
            }
            return Fcl.term(name, Fcl.pts(xy));
        }

        private double degree() {
            int k = rnd.nextInt(4);
            return k == 0 ? 0 : k == 1 ? 1 : rnd.nextDouble();
        }

        private double[] distinct(int n, double from, double to) {
            double[] x = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = Math.rint(uniform(rnd, from, to) * 1000) / 1000;
            }
            java.util.Arrays.sort(x);
            for (int i = 1; i < n; i++) {
                if (x[i] <= x[i - 1]) {
                    x[i] = x[i - 1] + 0.5;
                }
            }
            return x;
        }

        private Fcl.Out pointOutput() {
            boolean range = rnd.nextBoolean();
            Fcl.Out y = Fcl.defuzzify("y", DefuzzificationMethod.COG).defaultValue(DEFAULT);
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            int terms = 3 + rnd.nextInt(2);
            for (int t = 0; t < terms; t++) {
                int n = 2 + rnd.nextInt(4);
                double[] x = distinct(n, 0, 100);
                double[] xy = new double[2 * n];
                for (int i = 0; i < n; i++) {
                    xy[2 * i] = x[i];
                    boolean end = i == 0 || i == n - 1;
                    xy[2 * i + 1] = !range && end ? 0 : degree();
                }
                if (n == 2 && !range) {
                    xy[3] = 0;
                    xy[1] = 0;
                    xy = new double[] {x[0], 0, (x[0] + x[1]) / 2, 1, x[1], 0};
                }
                min = Math.min(min, xy[0]);
                max = Math.max(max, xy[xy.length - 2]);
                y.term("t" + t, Fcl.pts(xy));
            }
            if (range) {
                lo = Math.rint(uniform(rnd, -10, 30));
                hi = Math.rint(uniform(rnd, 70, 110));
                y.range(lo, hi);
                notes.add("RANGE " + lo + ".." + hi);
            } else {
                lo = min;
                hi = max;
            }
            return y;
        }

        private Fcl.Rules ruleBlock(String name) {
            Fcl.Rules r = Fcl.ruleBlock(name).accu(accu);
            AndAlgorithm and = AndAlgorithm.values()[rnd.nextInt(3)];
            switch (rnd.nextInt(3)) {
                case 0 -> r.and(and);
                case 1 -> r.or(and.pair());
                default -> r.and(and).or(and.pair());
            }
            int act = rnd.nextInt(3);
            if (act > 0) {
                r.act(act == 1 ? ActivationMethod.MIN : ActivationMethod.PROD);
            }
            notes.add(name + ":" + and + "/" + (act == 2 ? "PROD" : "MIN"));
            int rules = 2 + rnd.nextInt(4);
            for (int i = 0; i < rules; i++) {
                List<Subconclusion> sc = new ArrayList<>();
                sc.add(subconclusion("y", 3));
                if (rnd.nextInt(3) > 0) {
                    sc.add(subconclusion("z", 3));
                }
                if (rnd.nextInt(4) == 0) {
                    sc.add(subconclusion("y", 3));
                }
                r.rule(condition(3), sc.toArray(Subconclusion[]::new));
            }
            return r;
        }

        private Subconclusion subconclusion(String output, int terms) {
            String term = (output.equals("y") ? "t" : "s") + rnd.nextInt(terms);
            int k = rnd.nextInt(4);
            if (k == 0) {
                return Fcl.then(output, term, Fcl.num(Math.rint(rnd.nextDouble() * 100) / 100));
            }
            if (k == 1) {
                Operand w = Fcl.var("w");
                return Fcl.then(output, term, w);
            }
            return Fcl.then(output, term);
        }

        private Condition condition(int depth) {
            int k = depth == 0 ? rnd.nextInt(3) : rnd.nextInt(8);
            return switch (k) {
                case 0, 1 -> rnd.nextInt(4) == 0
                        ? Fcl.isNot(input(), "abc".substring(rnd.nextInt(3)).substring(0, 1))
                        : Fcl.is(input(), "abc".substring(rnd.nextInt(3)).substring(0, 1));
                case 2 -> Fcl.v("w");
                case 3 -> Fcl.not(Fcl.paren(condition(depth - 1)));
                case 4, 5 -> Fcl.and(operand(depth), operand(depth));
                default -> Fcl.or(condition(depth - 1), condition(depth - 1), condition(0));
            };
        }

        /** An AND operand: anything but a bare OR (Table 6: an OR inside an AND needs parentheses). */
        private Condition operand(int depth) {
            Condition c = condition(depth - 1);
            return c instanceof Condition.Or ? Fcl.paren(c) : c;
        }

        private String input() {
            return rnd.nextBoolean() ? "x1" : "x2";
        }
    }

    @SuppressWarnings("unused")
    private static String describe(FunctionBlock fb) {
        return fb.ruleBlocks().stream().map(RuleBlock::rules).flatMap(List::stream).map(Rule::toString)
                .collect(Collectors.joining("\n"));
    }

    @SuppressWarnings("unused")
    private static final Class<?>[] USED = {DefaultValue.class, Range.class, OrAlgorithm.class};
}
