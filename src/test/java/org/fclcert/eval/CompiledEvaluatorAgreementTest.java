package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.corpus.Vector;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Hedge;
import org.fclcert.model.Program;
import org.fclcert.model.Subconclusion;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/**
 * The fast path ({@link CompiledEvaluator}) against the reference instance ({@link FunctionBlockInstance})
 * on the whole conformance corpus and on random programs: the same outputs after every step of the same
 * sequence, or the same evaluation error. Fuzzification, aggregation and singleton outputs use the same
 * arithmetic in the same order, so they agree bit for bit; point-set outputs with ACCU MAX merge each
 * term's activations before building the set (same set, fewer vertices), so they agree to
 * {@link #AGREEMENT} of the defuzzification interval's width.
 */
class CompiledEvaluatorAgreementTest {
    /** Relative to max(1, interval width): the rounding of a shorter trapezoid sum. */
    static final double AGREEMENT = 1e-12;

    @Test
    void agreesWithTheReferenceOnTheWholeCorpus() throws Exception {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        int compared = 0;
        int compiled = 0;
        for (CorpusCase c : corpus.cases()) {
            if (c.expectReject() || c.vectors().isEmpty()) {
                continue;
            }
            Analysis a = Analysis.analyze(StrictReader.openLevel(), c.id(), c.programText());
            if (a.program().isEmpty()) {
                continue;
            }
            LoadedProgram loaded = Evaluator.load(a.program().get());
            String block = c.block().orElse(loaded.functionBlockNames().get(0));
            FunctionBlockInstance ref = loaded.newInstance(block);
            CompiledEvaluator fast = loaded.newCompiledInstance(block);
            compiled += fast.isCompiled() ? 1 : 0;
            List<Map<String, Double>> steps = new ArrayList<>();
            for (Vector v : c.vectors()) {
                steps.add(v.in());
            }
            compare(c.id(), ref, fast, steps, 1.0);
            compared++;
        }
        assertTrue(compared > 100, "only " + compared + " corpus cases compared");
        // most of the corpus is flat (constant points, IS conclusions): the fast plan, not the fallback
        assertTrue(compiled > compared / 2, compiled + " of " + compared + " cases on the flat plan");
    }

    @Test
    void agreesWithTheReferenceOnRandomPrograms() throws Exception {
        int flat = 0;
        for (int p = 0; p < 400; p++) {
            Random rnd = new Random(17_000L + p);
            Generator g = new Generator(rnd);
            Program program = g.block().program();
            LoadedProgram loaded = Evaluator.load(program);
            FunctionBlockInstance ref = loaded.newInstance();
            CompiledEvaluator fast = loaded.newCompiledInstance();
            flat += fast.isCompiled() ? 1 : 0;
            List<Map<String, Double>> steps = new ArrayList<>();
            for (int s = 0; s < 40; s++) {
                steps.add(Map.of("x1", input(rnd), "x2", input(rnd), "x3", input(rnd), "w", rnd.nextDouble()));
            }
            compare("random program " + p + " (" + g.notes + ")", ref, fast, steps, 100);
        }
        assertTrue(flat > 250, flat + " of 400 random programs on the flat plan");
    }

    private static double input(Random rnd) {
        // grid points hit term points and jumps exactly; the rest fall between them
        return rnd.nextInt(3) == 0 ? rnd.nextInt(13) - 1 : -1.5 + 14 * rnd.nextDouble();
    }

    private static void compare(String what, FunctionBlockInstance ref, CompiledEvaluator fast,
            List<Map<String, Double>> steps, double width) throws EvaluationException {
        List<String> outs = ref.outputNames();
        int[] index = new int[outs.size()];
        for (int k = 0; k < index.length; k++) {
            index[k] = fast.outputIndex(outs.get(k));
        }
        for (int s = 0; s < steps.size(); s++) {
            String refError = null;
            String fastError = null;
            try {
                for (Map.Entry<String, Double> in : steps.get(s).entrySet()) {
                    if (ref.inputNames().stream().anyMatch(n -> n.equalsIgnoreCase(in.getKey()))) {
                        ref.set(in.getKey(), in.getValue());
                    }
                }
                ref.evaluate();
            } catch (EvaluationException e) {
                refError = e.code();
            }
            try {
                for (Map.Entry<String, Double> in : steps.get(s).entrySet()) {
                    if (ref.inputNames().stream().anyMatch(n -> n.equalsIgnoreCase(in.getKey()))) {
                        fast.setInput(fast.inputIndex(in.getKey()), in.getValue());
                    }
                }
                fast.evaluate();
            } catch (EvaluationException e) {
                fastError = e.code();
            }
            assertEquals(refError, fastError, what + ", step " + (s + 1) + ": error");
            for (int k = 0; k < index.length; k++) {
                double want = ref.get(outs.get(k));
                double got = fast.output(index[k]);
                double tol = AGREEMENT * Math.max(1.0, Math.max(width, Math.abs(want)));
                assertTrue(Double.compare(want, got) == 0 || Math.abs(want - got) <= tol,
                        what + ", step " + (s + 1) + ", " + outs.get(k) + ": reference " + want + ", fast " + got);
            }
        }
    }

    @Test
    void indicesResolveNamesOnceAndRejectWhatSetByNameRejects() throws Exception {
        LoadedProgram loaded = Evaluator.load(Fcl.block("b").input("x").output("y")
                .fuzzify("x", Fcl.term("lo", Fcl.pts(0, 1, 10, 0)), Fcl.term("hi", Fcl.pts(0, 0, 10, 1)))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("a", Fcl.single(0))
                        .term("b", Fcl.single(100)).defaultValue(-1))
                .rules(Fcl.ruleBlock("r").and(AndAlgorithm.MIN).accu(AccumulationMethod.MAX)
                        .rule(Fcl.is("x", "lo"), Fcl.then("y", "a")).rule(Fcl.is("x", "hi"), Fcl.then("y", "b")))
                .program());
        CompiledEvaluator fast = loaded.newCompiledInstance();
        assertTrue(fast.isCompiled());
        int x = fast.inputIndex("X");
        int y = fast.outputIndex("y");
        fast.setInput(x, 2.5);
        fast.evaluate();
        // degrees 0.75 (lo) and 0.25 (hi): (0 * 0.75 + 100 * 0.25) / 1, by hand
        assertEquals(25.0, fast.output(y), 0.0);
        assertEquals("FCL-V001", assertThrows(EvaluationException.class, () -> fast.inputIndex("z")).code());
        assertEquals("FCL-V003", assertThrows(EvaluationException.class, () -> fast.inputIndex("y")).code());
        assertEquals("FCL-V002", assertThrows(EvaluationException.class,
                () -> fast.setInput(x, Double.NaN)).code());
        // all inputs at once, in declaration order: x = 7.5 gives lo 0.25, hi 0.75, so 75
        fast.setInputs(7.5);
        fast.evaluate();
        assertEquals(75.0, fast.output(y), 0.0);
        assertEquals(7.5, fast.input(x), 0.0);
        assertEquals("FCL-V002", assertThrows(EvaluationException.class,
                () -> fast.setInputs(Double.POSITIVE_INFINITY)).code());
        assertThrows(IllegalArgumentException.class, () -> fast.setInputs(1, 2));
        // a REAL holds at most Float.MAX_VALUE (about 3.4E38) either way; the value before stays
        assertEquals("FCL-V004", assertThrows(EvaluationException.class, () -> fast.setInputs(-1e39)).code());
        assertEquals("FCL-V004", assertThrows(EvaluationException.class, () -> fast.setInput(x, 1e39)).code());
        assertEquals("FCL-V002", assertThrows(EvaluationException.class,
                () -> fast.setInput(x, Double.NEGATIVE_INFINITY)).code());
        assertEquals(7.5, fast.input(x), 0.0);
        fast.setInput(x, -Float.MAX_VALUE);
        assertEquals(-Float.MAX_VALUE, fast.input(x), 0.0);
    }

    /**
     * Random valid programs over inputs x1..x3 (2-4 terms each, points possibly sharing an x: jumps) and w,
     * outputs y (point terms, one of CoG/CoA/LM/RM/MoM) and z (singletons, CoGS/LM/RM/MoM/COGSS), one to
     * three rule blocks with random AND/OR pairs, ACT and ACCU, NOT, parentheses, hedges, weights. A few
     * programs use what only the fallback covers (variable weights, bare-variable conditions, PROBOR sets).
     */
    private static final class Generator {
        private final Random rnd;
        final List<String> notes = new ArrayList<>();
        private final boolean fallbackOnly;

        Generator(Random rnd) {
            this.rnd = rnd;
            this.fallbackOnly = rnd.nextInt(8) == 0;
        }

        Fcl.Block block() {
            Fcl.Block b = Fcl.block("random").input("x1").input("x2").input("x3").input("w").output("y").output("z");
            for (String x : List.of("x1", "x2", "x3")) {
                int terms = 2 + rnd.nextInt(3);
                org.fclcert.model.Term[] ts = new org.fclcert.model.Term[terms];
                for (int t = 0; t < terms; t++) {
                    ts[t] = Fcl.term("t" + t, Fcl.pts(points(2 + rnd.nextInt(3), -1, 11, false)));
                }
                b.fuzzify(x, ts);
            }
            DefuzzificationMethod[] pm = {DefuzzificationMethod.COG, DefuzzificationMethod.COA,
                DefuzzificationMethod.LM, DefuzzificationMethod.RM, DefuzzificationMethod.MOM};
            Fcl.Out y = Fcl.defuzzify("y", pm[rnd.nextInt(pm.length)]).defaultValue(-999);
            if (rnd.nextBoolean()) {
                y.range(0, 100);
            }
            for (int t = 0; t < 4; t++) {
                y.term("o" + t, Fcl.pts(points(3, 0, 100, true)));
            }
            b.defuzzify(rnd.nextInt(5) == 0 ? y.noChange() : y);
            DefuzzificationMethod[] sm = {DefuzzificationMethod.COGS, DefuzzificationMethod.LM,
                DefuzzificationMethod.RM, DefuzzificationMethod.MOM, DefuzzificationMethod.COGSS};
            Fcl.Out z = Fcl.defuzzify("z", sm[rnd.nextInt(sm.length)]).defaultValue(-999);
            for (int t = 0; t < 3; t++) {
                z.term("s" + t, Fcl.single(Math.rint(rnd.nextDouble() * 100 - 50)));
            }
            b.defuzzify(z);
            AccumulationMethod[] accus = fallbackOnly ? AccumulationMethod.values()
                    : new AccumulationMethod[] {AccumulationMethod.MAX, AccumulationMethod.BSUM, AccumulationMethod.NSUM,
                        AccumulationMethod.SUM};
            AccumulationMethod accu = accus[rnd.nextInt(accus.length)];
            int blocks = 1 + rnd.nextInt(3);
            for (int i = 0; i < blocks; i++) {
                AndAlgorithm and = AndAlgorithm.values()[rnd.nextInt(3)];
                ActivationMethod act = rnd.nextBoolean() ? ActivationMethod.MIN : ActivationMethod.PROD;
                Fcl.Rules r = Fcl.ruleBlock("rb" + i).and(and).or(and.pair()).act(act).accu(accu);
                notes.add(and + "/" + act + "/" + accu);
                int rules = 1 + rnd.nextInt(6);
                for (int k = 0; k < rules; k++) {
                    List<Subconclusion> sc = new ArrayList<>();
                    sc.add(then("y", "o" + rnd.nextInt(4)));
                    if (rnd.nextBoolean()) {
                        sc.add(then("z", "s" + rnd.nextInt(3)));
                    }
                    r.rule(condition(2), sc.toArray(Subconclusion[]::new));
                }
                b.rules(r);
            }
            return b;
        }

        private Subconclusion then(String out, String term) {
            int k = rnd.nextInt(4);
            if (k == 0) {
                // a few weights, so that terms are sometimes concluded with equal and sometimes with unequal weights
                return Fcl.then(out, term, Fcl.num(new double[] {0.5, 0.8, 1.0}[rnd.nextInt(3)]));
            }
            if (k == 1 && fallbackOnly) {
                return Fcl.then(out, term, Fcl.var("w"));
            }
            return Fcl.then(out, term);
        }

        private double[] points(int n, double from, double to, boolean zeroEnds) {
            double[] xy = new double[2 * n];
            double x = from + rnd.nextDouble() * (to - from) / 2;
            for (int i = 0; i < n; i++) {
                xy[2 * i] = Math.rint(x * 4) / 4;
                xy[2 * i + 1] = zeroEnds && (i == 0 || i == n - 1) ? 0
                        : new double[] {0, 1, 0.5, Math.rint(rnd.nextDouble() * 1000) / 1000}[rnd.nextInt(4)];
                // one step in five is zero: two points at one x, a jump
                x += rnd.nextInt(5) == 0 ? 0 : 0.5 + rnd.nextDouble() * (to - from) / n;
            }
            return xy;
        }

        private Condition condition(int depth) {
            int k = depth == 0 ? rnd.nextInt(3) : rnd.nextInt(9);
            String x = "x" + (1 + rnd.nextInt(3));
            String t = "t" + rnd.nextInt(2);
            return switch (k) {
                case 0 -> Fcl.is(x, t);
                case 1 -> Fcl.isNot(x, t);
                case 2 -> fallbackOnly && rnd.nextBoolean() ? Fcl.v("w") : Fcl.is(x, t);
                case 3 -> Fcl.not(Fcl.paren(condition(depth - 1)));
                case 4 -> hedged(x, t);
                case 5, 6 -> Fcl.and(operand(depth), operand(depth), operand(0));
                default -> Fcl.or(condition(depth - 1), condition(depth - 1));
            };
        }

        private Condition hedged(String x, String t) {
            Hedge h = Hedge.values()[rnd.nextInt(4)];
            return new Condition.TermSubcondition(x, t, false, List.of(h), Fcl.AT);
        }

        private Condition operand(int depth) {
            Condition c = condition(Math.max(0, depth - 1));
            return c instanceof Condition.Or ? Fcl.paren(c) : c;
        }
    }
}
