package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/**
 * The static filter (docs/semantics.md, "The static filter"): its bounds on the 5.3 valve against a hand
 * calculation; a step it cannot decide that the running bounds decide, one only exact arithmetic decides, one it
 * decides; and, on random programs it covers, every static bound at least the running bound of the same quantity at
 * every step, with the outputs, bounds and internals of the interpreter bit for bit.
 */
class StaticFilterTest {
    private static LoadedProgram load(String text) {
        Program program = new StrictReader().read("t.fcl", text).program().orElseThrow();
        return Evaluator.load(program);
    }

    /** u = 2⁻⁵³; Norms.R = 4u. */
    private static final BigDecimal U = BigDecimal.ONE.divide(BigDecimal.valueOf(2).pow(53));
    private static final BigDecimal R = U.multiply(BigDecimal.valueOf(4));

    private static BigDecimal pow2(int e) {
        return BigDecimal.ONE.divide(BigDecimal.valueOf(2).pow(-e));
    }

    /**
     * Whether a static bound is the formula's value to a relative 1e-9. It is the formula evaluated in doubles, as
     * the running bound is (each rounding monotonic, so the static double is at least the running double; the
     * rounding of the bounds themselves is covered by their factors on each rounding term, docs/semantics.md).
     */
    private static void holds(BigDecimal exact, double bound, String what) {
        BigDecimal b = new BigDecimal(bound);
        assertTrue(b.subtract(exact).abs().compareTo(exact.multiply(new BigDecimal("1e-9"))) <= 0,
                what + ": " + bound + " against " + exact);
    }

    @Test
    void valveBoundsByHand() throws Exception {
        LoadedProgram p = load(Files.readString(Path.of("examples", "valve.fcl")));
        FunctionBlockInstance fb = p.newCompiledInstance(null);
        fb.setInputs(5, 60);
        fb.evaluate();
        StaticFilter f = fb.staticFilter();
        assertNotNull(f, "the valve is covered");
        assertNotNull(f.compiled, "and generated");
        // temp's ramps (3, ·) (27, ·): integer points and degrees (distance 0); an input inside has a distance of at
        // most ulp(27)/2 = 2⁻⁴⁹: |Δy|·2·2⁻⁴⁹/24 + 2R. pressure's (55, ·) (95, ·): ulp(95)/2 = 2⁻⁴⁷, /40.
        BigDecimal temp = BigDecimal.valueOf(2).multiply(pow2(-49)).divide(BigDecimal.valueOf(24), MathContext.DECIMAL128)
                .add(R.multiply(BigDecimal.valueOf(2)));
        BigDecimal pressure = BigDecimal.valueOf(2).multiply(pow2(-47))
                .divide(BigDecimal.valueOf(40), MathContext.DECIMAL128).add(R.multiply(BigDecimal.valueOf(2)));
        for (int t = 0; t < 4; t++) {
            holds(t < 2 ? temp : pressure, f.termBound[t], "term " + t);
        }
        // every rule is a MIN of a temp and a pressure term: the larger bound, pressure's
        for (double b : f.ruleBound) {
            holds(pressure, b, "rule");
        }
        // w = 1: 1·S + M·0 + 0·S + R·M (M = 1 and a slack of 2⁻⁴⁰) + the smallest normal; the three singletons each
        // have a rule of weight 1 (closed: rules 2 with 0.8 and 3 with 1, the larger), so the CoGS threshold is 3 of
        // those: about 5.06e-15
        BigDecimal one = pressure.add(R);
        BigDecimal threshold = one.multiply(BigDecimal.valueOf(3));
        holds(threshold, f.threshold[0], "threshold");
        assertEquals(1, fb.staticEvaluations(), "(5, 60) decided statically");
    }

    /**
     * The running bounds of a statically decided step are those of its own inputs, whatever was set since: bound()
     * after new inputs were set, and reset() (which settles them first and then refreshes the representation
     * distances of the initial values), against an interpreted instance driven alike.
     */
    @Test
    void boundsWhenAskedAreThoseOfTheStep() throws Exception {
        LoadedProgram p = load(Files.readString(Path.of("examples", "valve.fcl")));
        FunctionBlockInstance fb = p.newCompiledInstance(null);
        FunctionBlockInstance plain = p.newInstance();
        plain.interpretOnly();
        fb.setInputs(5.1, 60.3);
        plain.setInputs(5.1, 60.3);
        fb.evaluate();
        plain.evaluate();
        assertEquals(1, fb.staticEvaluations());
        fb.setInputs(15, 75);                    // set, not evaluated: the bound asked is still (5.1, 60.3)'s
        double b = plain.bound("valve");
        assertTrue(b > 0 && b < 1e-12, "bound " + b);
        assertEquals(b, fb.bound("valve"));
        assertEquals(15.0, fb.get("temp"), "the inputs set since are kept");
        fb.evaluate();
        plain.setInputs(15, 75);
        plain.evaluate();
        assertEquals(plain.output(0), fb.output(0));
        fb.reset();
        plain.reset();
        assertEquals(plain.bound("valve"), fb.bound("valve"), "reset keeps the last step's bound");
        fb.evaluate();                          // temp 0, pressure 0 (no initial values): cold and low, inlet 100
        plain.evaluate();
        assertEquals(100.0, fb.output(0));
        assertEquals(plain.output(0), fb.output(0));
        assertEquals(plain.bound("valve"), fb.bound("valve"));
        assertEquals(Arrays.toString(plain.state()), Arrays.toString(fb.state()));
        assertEquals(3, fb.staticEvaluations());
    }

    /**
     * a IS A with A a ramp over (0, 2²⁰); b IS B with B a ramp 1e-10 wide at 0.1 (points not decimals in binary):
     * B's static bound is about 2·3·(ulp(0.1)/2)/1e-10 ≈ 4.2e-7, the threshold of the only singleton.
     */
    private static final String STEEP = """
            FUNCTION_BLOCK sf
            VAR_INPUT a : REAL; b : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY a
                TERM big := (0, 0) (1048576, 1);
            END_FUZZIFY
            FUZZIFY b
                TERM steep := (0.1, 0) (0.1000000001, 1);
            END_FUZZIFY
            DEFUZZIFY y
                TERM s := 10;
                METHOD : CoGS;
                DEFAULT := -1;
            END_DEFUZZIFY
            RULEBLOCK r
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF a IS big AND b IS steep THEN y IS s;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    @Test
    void staticTestFailsRunningBoundsOrExactDecide() throws Exception {
        LoadedProgram p = load(STEEP);
        FunctionBlockInstance fb = p.newCompiledInstance(null);
        FunctionBlockInstance plain = p.newInstance();
        plain.interpretOnly();
        fb.setInputs(524288, 1);           // big = 1/2 exactly, steep = 1 (above its points)
        fb.evaluate();
        StaticFilter f = fb.staticFilter();
        assertNotNull(f);
        assertTrue(f.threshold[0] > 4.1e-7 && f.threshold[0] < 4.3e-7, "threshold " + f.threshold[0]);
        assertEquals(1, fb.staticEvaluations(), "0.5 > 4.2e-7: decided statically");
        assertEquals(10.0, fb.output(0));
        // big = 2⁻³⁰ exactly (a = 1/1024 is a decimal: distance 0, bound 2R), steep = 1 exactly: the degree 9.3e-10 is
        // under the static threshold, but the running bound (MIN takes the certainly smaller operand's, 2R) decides
        fb.setInputs(1.0 / 1024, 1);
        fb.evaluate();
        assertEquals(1, fb.staticEvaluations(), "2^-30 < 4.2e-7: not decided statically");
        assertEquals(0, fb.fallbacks(), "decided by the running bounds");
        assertEquals(10.0, fb.output(0));
        // one singleton: CoGS spread 0, bound 2·2·u·10 (the value 10 is a decimal)
        assertEquals(40 * 0x1.0p-53, fb.bound("y"), 1e-30);
        // a = 1e-300 is not a decimal in binary: its distance (half an ulp) moves the degree by far more than the
        // degree itself, 1e-300/2²⁰: only exact arithmetic decides (any positive degree gives 10)
        fb.setInputs(1e-300, 1);
        fb.evaluate();
        assertEquals(1, fb.fallbacks(), "decided exactly");
        assertEquals(10.0, fb.output(0));
        assertEquals(0.0, fb.bound("y"));
        // a = 0: big is an exact 0 at its point, nothing fired: DEFAULT, by the running bounds
        fb.setInputs(0, 1);
        fb.evaluate();
        assertEquals(-1.0, fb.output(0));
        assertEquals(1, fb.fallbacks());
        assertEquals(1, fb.staticEvaluations());
        for (double[] v : new double[][] {{524288, 1}, {1.0 / 1024, 1}, {1e-300, 1}, {0, 1}}) {
            plain.setInputs(v);
            plain.evaluate();
        }
        assertEquals(1, plain.fallbacks(), "the interpreter falls back at the same step");
    }

    /**
     * A chain output's decisions (TermChain; docs/semantics.md, "The static filter"): a step whose every test passes is
     * decided statically with the interpreter's value; one whose CoG area is within its bound (a term of width 2e-12
     * under a RANGE of 1000: area 5e-13 against 2Δ ≥ 2·8·(n + 2)·u·1000 ≈ 1e-11) is left to the running path, which
     * hands it to exact arithmetic; a rule of a degree not above its static bound, and nothing fired, likewise.
     */
    @Test
    void chainOutputDecisions() throws Exception {
        LoadedProgram p = load("""
                FUNCTION_BLOCK c
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x
                    TERM up := (0, 0) (10, 1);
                    TERM down := (0, 1) (10, 0);
                END_FUZZIFY
                DEFUZZIFY y
                    TERM thin := (0, 0) (0.000000000001, 1) (0.000000000002, 0);
                    TERM wide := (600, 0) (800, 1) (1000, 0);
                    METHOD : CoG;
                    DEFAULT := -1;
                    RANGE := (0 .. 1000);
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    ACT : MIN;
                    ACCU : MAX;
                    RULE 1 : IF x IS up THEN y IS thin;
                    RULE 2 : IF x IS down THEN y IS wide;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """);
        FunctionBlockInstance fb = p.newCompiledInstance(null);
        FunctionBlockInstance plain = p.newInstance();
        plain.interpretOnly();
        double[] xs = {2, 10, 1e-300, 5};
        for (double x : xs) {
            fb.setInputs(x);
            plain.setInputs(x);
            fb.evaluate();
            plain.evaluate();
            assertEquals(plain.output(0), fb.output(0), "x = " + x);
            assertEquals(plain.bound("y"), fb.bound("y"), "x = " + x);
        }
        assertNotNull(fb.staticFilter(), "the chain output is covered");
        // x = 2: up 0.2, down 0.8, both fired, area 0.8·200·1.2 ≫ 2Δ: statically; x = 10: down an exact 0 at its
        // point, only 'thin' at 1: area 1e-12 within the bound: the running path, then exact arithmetic (a lone thin
        // triangle's centre is its peak, 1e-12); x = 1e-300: up's degree 1e-301 is not above its bound (running and
        // static): exact; x = 5: both at 0.5: statically
        assertEquals(2, fb.staticEvaluations());
        assertEquals(2, fb.fallbacks());
        assertEquals(plain.fallbacks(), fb.fallbacks());
        fb.setInputs(10);
        fb.evaluate();
        assertEquals(1e-12, fb.output(0), 1e-24);
    }

    /**
     * A chain output whose terms are too many points for the generated staging ({@code StaticFilter.stage}'s budget:
     * nine terms of seven points): its steps are still decided statically, each contribution staged by
     * {@code SetBuilder.contributionVertices}, bit for bit the interpreter's; and a small chain is staged by generated
     * code.
     */
    @Test
    void aChainOverTheStagingBudgetIsStagedByTheInterpreter() throws Exception {
        StringBuilder in = new StringBuilder();
        StringBuilder out = new StringBuilder();
        StringBuilder rules = new StringBuilder();
        for (int k = 0; k < 9; k++) {
            in.append("    TERM t").append(k).append(" := (").append(k - 1).append(", 0) (").append(k).append(", 1) (")
                    .append(k + 1).append(", 0);\n");
            int u = 5 * k;
            out.append("    TERM o").append(k).append(" := (").append(u).append(", 0) (").append(u + 1).append(", 0.2) (")
                    .append(u + 2).append(", 0.6) (").append(u + 3).append(", 1) (").append(u + 4).append(", 0.6) (")
                    .append(u + 5).append(", 0.2) (").append(u + 6).append(", 0);\n");
            rules.append("    RULE ").append(k + 1).append(" : IF x IS t").append(k).append(" THEN y IS o").append(k)
                    .append(";\n");
        }
        LoadedProgram p = load("FUNCTION_BLOCK c\nVAR_INPUT x : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
                + "FUZZIFY x\n" + in + "END_FUZZIFY\nDEFUZZIFY y\n" + out
                + "    METHOD : CoG;\n    DEFAULT := -1;\n    RANGE := (0 .. 46);\nEND_DEFUZZIFY\n"
                + "RULEBLOCK r\n    AND : MIN;\n    ACT : MIN;\n    ACCU : MAX;\n" + rules
                + "END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        FunctionBlockInstance fb = p.newCompiledInstance(null);
        FunctionBlockInstance plain = p.newInstance();
        plain.interpretOnly();
        double[] xs = {0.3, 1.7, 2.5, 3.25, 4.9, 6.1, 7.75, 0.5, 5.5};
        for (double x : xs) {
            fb.setInputs(x);
            plain.setInputs(x);
            fb.evaluate();
            plain.evaluate();
            assertEquals(Double.doubleToRawLongBits(plain.output(0)), Double.doubleToRawLongBits(fb.output(0)),
                    "x = " + x);
            assertEquals(plain.bound("y"), fb.bound("y"), "x = " + x);
        }
        assertNotNull(fb.staticFilter(), "the chain output is covered");
        assertFalse(fb.staticFilter().staged(), "nine terms of seven points: over the staging budget");
        assertEquals(xs.length, fb.staticEvaluations(), "every step decided statically");
        // x = 0.5: t0 and t1 at 0.5; o0 and o1 clipped at 0.5 (plateaus 1.75..4.25 and 6.75..9.25), crossing at
        // (5.5, 0.1): the set is symmetric about 5.5, its CoG 5.5
        fb.setInputs(0.5);
        fb.evaluate();
        assertEquals(5.5, fb.output(0), 1e-12);
        FunctionBlockInstance small = load("""
                FUNCTION_BLOCK s
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x
                    TERM lo := (0, 1) (10, 0);
                    TERM hi := (0, 0) (10, 1);
                END_FUZZIFY
                DEFUZZIFY y
                    TERM a := (0, 0) (20, 1) (40, 0);
                    TERM b := (30, 0) (50, 1) (70, 0);
                    METHOD : CoG;
                    DEFAULT := -1;
                    RANGE := (0 .. 70);
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    ACT : MIN;
                    ACCU : MAX;
                    RULE 1 : IF x IS lo THEN y IS a;
                    RULE 2 : IF x IS hi THEN y IS b;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """).newCompiledInstance(null);
        small.setInputs(5);
        small.evaluate();
        assertTrue(small.staticFilter().staged(), "a small chain is staged by generated code");
    }

    /**
     * Random programs the static filter covers (1-3 inputs of 2-4 piece-wise linear terms with points off and on
     * binary fractions, steep and wide pieces, large abscissas; MIN, PROD or MAX of 1-3 terms, IS NOT, weights; 2-4
     * singletons, CoGS), 40 steps each at random inputs, on points, next to points, and on multiples of 1/1024. After
     * every step of the instance with the static filter (generated, and interpreted on a second instance): the same
     * state, fallbacks, internals and bounds as the interpreter bit for bit, and every running bound of a term, rule
     * and contribution at most its static bound, Σ of the singletons' running bounds at most the threshold. A static
     * bound made smaller than the running one fails here (see the report of issue 24 for the planted fault).
     */
    @Test
    void staticBoundsDominateRunningBoundsOnRandomPrograms() throws Exception {
        randomPrograms(24_5_0L, StaticFilterTest::program);
    }

    /**
     * The same on random programs whose output has point terms in a chain (TermChain: triangles, trapezoids and
     * shoulders of a fuzzy partition, on a decimal grid and off it; with RANGE or without), CoG, MIN or PROD
     * activation, MAX accumulation: the outputs the filter computes by the chain construction.
     */
    @Test
    void chainOutputsOnRandomPrograms() throws Exception {
        randomPrograms(24_7_0L, StaticFilterTest::chainProgram);
    }

    interface Generator {
        String program(Random rnd, List<double[]> points);
    }

    private static void randomPrograms(long seed, Generator generator) throws Exception {
        int programs = 0;
        long decided = 0;
        long steps = 0;
        long fallbacks = 0;
        for (int n = 0; n < 400; n++) {
            Random rnd = new Random(seed + n);
            List<double[]> points = new ArrayList<>();
            String text = generator.program(rnd, points);
            LoadedProgram p = load(text);
            FunctionBlockInstance gen = p.newCompiledInstance(null);
            FunctionBlockInstance interpreted = p.newCompiledInstance(null);
            FunctionBlockInstance plain = p.newInstance();
            plain.interpretOnly();
            int inputs = plain.inputNames().size();
            for (int s = 0; s < 40; s++) {
                double[] v = new double[inputs];
                for (int i = 0; i < inputs; i++) {
                    v[i] = input(rnd, points.get(i));
                }
                gen.setInputs(v);
                interpreted.setInputs(v);
                plain.setInputs(v);
                gen.evaluate();
                if (s == 0) {
                    assertNotNull(gen.staticFilter(), "covered:\n" + text);
                    interpreted.evaluate();
                    interpreted.interpretStaticStep();
                } else {
                    interpreted.evaluate();
                }
                plain.evaluate();
                String where = "program " + n + " step " + s + " inputs " + Arrays.toString(v) + "\n" + text;
                assertEquals(Arrays.toString(plain.state()), Arrays.toString(gen.state()), where);
                assertEquals(Arrays.toString(plain.state()), Arrays.toString(interpreted.state()), where);
                assertEquals(plain.fallbacks(), gen.fallbacks(), where);
                double[][] a = plain.internals();
                double[][] b = gen.internals();
                double[][] c = interpreted.internals();
                for (int k = 0; k < a.length; k++) {
                    assertTrue(Arrays.equals(a[k], b[k]) && Arrays.equals(a[k], c[k]),
                            where + "\ninternals " + k + ": " + Arrays.toString(a[k]) + " / "
                                    + Arrays.toString(b[k]));
                }
                assertEquals(plain.bound("y"), gen.bound("y"), where);
                if (gen.fallbacks() > fallbacks) {
                    fallbacks = gen.fallbacks();
                    continue;       // the exact path's step: no running bounds to compare
                }
                dominates(gen.staticFilter(), b, where);
            }
            programs++;
            decided += gen.staticEvaluations();
            steps += gen.evaluations();
            fallbacks = 0;
        }
        System.out.println("static filter (seed " + seed + "): " + programs + " programs, " + steps + " steps, "
                + decided + " decided statically");
        assertTrue(decided > steps / 4 && decided < steps, decided + " of " + steps + " decided statically");
    }

    /** Every running bound of the last step (internals) at most its static bound. */
    private static void dominates(StaticFilter f, double[][] in, String where) {
        double[] termErrors = in[1];
        double[] contributionError = in[4];
        double[] degreeError = in[5];
        for (int t = 0; t < f.terms; t++) {
            assertTrue(termErrors[t] <= f.termBound[t], where + "\nterm " + t + ": running " + termErrors[t]
                    + " above static " + f.termBound[t]);
        }
        for (int c = 0; c < contributionError.length; c++) {
            assertTrue(contributionError[c] <= f.contributionBound[c], where + "\ncontribution " + c + ": running "
                    + contributionError[c] + " above static " + f.contributionBound[c]);
            assertTrue(degreeError[c] <= f.contributionDegreeBound[c], where + "\ndegree of contribution " + c
                    + ": running " + degreeError[c] + " above static " + f.contributionDegreeBound[c]);
        }
        // a singleton's running bound under MAX is at most the largest of its contributions' (maxError): their sum
        // over the singletons, in order, at most the CoGS threshold
        for (int i = 0; i < f.threshold.length; i++) {
            double[] largest = new double[f.singletonBound[i].length];
            for (int c = 0; c < contributionError.length; c++) {
                if (f.contributionOutput[c] == i) {
                    int t = f.contributionSingleton[c];
                    largest[t] = Math.max(largest[t], contributionError[c]);
                }
            }
            double sum = 0;
            for (double e : largest) {
                sum += e;
            }
            assertTrue(sum <= f.threshold[i], where + "\nsingletons' running bounds " + sum + " above the threshold "
                    + f.threshold[i]);
        }
    }

    private static final String[] XS = {"0", "0.1", "0.3", "1", "2.5", "3", "7", "10", "12.7", "27", "55", "95",
        "100", "1000.1", "1048575", "1048577", "123456.789"};

    /** A random covered program; the points of each input's terms into {@code points}. */
    private static String program(Random rnd, List<double[]> points) {
        StringBuilder s = new StringBuilder("FUNCTION_BLOCK r\nVAR_INPUT\n");
        int inputs = 1 + rnd.nextInt(3);
        for (int i = 0; i < inputs; i++) {
            s.append("    x").append(i).append(" : REAL;\n");
        }
        s.append("END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n");
        List<String> terms = new ArrayList<>();
        for (int i = 0; i < inputs; i++) {
            s.append("FUZZIFY x").append(i).append('\n');
            int n = 2 + rnd.nextInt(3);
            List<Double> xs = new ArrayList<>();
            for (int t = 0; t < n; t++) {
                int k = 2 + rnd.nextInt(3);
                double base = Double.parseDouble(XS[rnd.nextInt(XS.length)]);
                double[] x = new double[k];
                for (int j = 0; j < k; j++) {
                    // mostly increasing by random decimal steps; sometimes a steep piece of 1e-9 or a repeated point
                    double step = rnd.nextInt(6) == 0 ? 1e-9 : rnd.nextInt(8) == 0 ? 0 : (1 + rnd.nextInt(200)) / 10.0;
                    base = j == 0 ? base : base + step;
                    x[j] = Double.parseDouble(String.format(Locale.ROOT, "%.10g", base));
                    if (j > 0 && x[j] < x[j - 1]) {
                        x[j] = x[j - 1];
                    }
                    xs.add(x[j]);
                }
                s.append("    TERM t").append(t).append(" :=");
                for (int j = 0; j < k; j++) {
                    String y = switch (rnd.nextInt(4)) {
                        case 0 -> "0";
                        case 1 -> "1";
                        case 2 -> "0.5";
                        default -> String.format(Locale.ROOT, "%.3f", rnd.nextDouble());
                    };
                    s.append(" (").append(x[j]).append(", ").append(y).append(')');
                }
                s.append(";\n");
                terms.add("x" + i + " IS " + (rnd.nextInt(6) == 0 ? "NOT " : "") + "t" + t);
            }
            s.append("END_FUZZIFY\n");
            points.add(xs.stream().mapToDouble(Double::doubleValue).toArray());
        }
        s.append("DEFUZZIFY y\n");
        int singletons = 2 + rnd.nextInt(3);
        for (int k = 0; k < singletons; k++) {
            s.append("    TERM s").append(k).append(" := ").append(rnd.nextInt(7) == 0 ? "0.1" : rnd.nextInt(201) - 100)
                    .append(";\n");
        }
        s.append("    METHOD : CoGS;\n    DEFAULT := -7;\nEND_DEFUZZIFY\n");
        String and = rnd.nextBoolean() ? "MIN" : "PROD";
        s.append("RULEBLOCK rb\n    AND : ").append(and).append(";\n    OR : MAX;\n    ACCU : MAX;\n");
        int rules = 1 + rnd.nextInt(6);
        for (int r = 0; r < rules; r++) {
            int k = 1 + rnd.nextInt(3);
            String op = rnd.nextBoolean() ? " AND " : " OR ";
            StringBuilder cond = new StringBuilder();
            for (int j = 0; j < k; j++) {
                cond.append(j > 0 ? op : "").append(terms.get(rnd.nextInt(terms.size())));
            }
            s.append("    RULE ").append(r + 1).append(" : IF ").append(cond).append(" THEN y IS s")
                    .append(rnd.nextInt(singletons));
            if (rnd.nextInt(3) == 0) {
                s.append(" WITH ").append(new String[] {"0.8", "0.5", "0.1", "0.333"}[rnd.nextInt(4)]);
            }
            s.append(";\n");
        }
        s.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        return s.toString();
    }

    /** A random program whose output y is CoG over a chain of point terms (see {@link #chainOutputsOnRandomPrograms}). */
    private static String chainProgram(Random rnd, List<double[]> points) {
        String text = program(rnd, points);
        int from = text.indexOf("DEFUZZIFY y");
        int to = text.indexOf("END_DEFUZZIFY");
        int singletons = 0;
        while (text.indexOf("TERM s" + singletons + " ", from) >= 0 && text.indexOf("TERM s" + singletons + " ", from) < to) {
            singletons++;
        }
        List<String> terms = new ArrayList<>();
        boolean grid = rnd.nextBoolean();
        // without RANGE the checks want every term 0 at its outer points (FCL-C025): shoulders only with one
        boolean range = rnd.nextInt(4) != 0;
        double at = grid ? rnd.nextInt(41) - 20 : rnd.nextDouble() * 40 - 20;
        double first = at;
        double end = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < singletons; k++) {
            // a triangle or trapezoid rising from `at` to past the last term's end, then falling
            double rise = grid ? 1 + rnd.nextInt(10) : 0.5 + rnd.nextDouble() * 10;
            double x1 = Double.parseDouble(dec(Math.max(at + rise, end + (grid ? 1 : 0.25))));
            double x2 = Double.parseDouble(dec(x1 + (rnd.nextBoolean() ? 0 : grid ? 1 + rnd.nextInt(4) : rnd.nextDouble() * 5)));
            double x3 = Double.parseDouble(dec(x2 + (grid ? 1 + rnd.nextInt(10) : 0.5 + rnd.nextDouble() * 10)));
            String peak = rnd.nextInt(4) == 0 ? "0.5" : "1";
            boolean leftShoulder = range && k == 0 && rnd.nextInt(3) == 0;
            boolean rightShoulder = range && k == singletons - 1 && rnd.nextInt(3) == 0;
            StringBuilder d = new StringBuilder();
            d.append("    TERM s").append(k).append(" :=");
            if (!leftShoulder) {
                d.append(" (").append(dec(at)).append(", 0)");
            }
            d.append(" (").append(dec(x1)).append(", ").append(peak).append(')');
            if (x2 > x1) {
                d.append(" (").append(dec(x2)).append(", ").append(peak).append(')');
            }
            if (!rightShoulder) {
                d.append(" (").append(dec(x3)).append(", 0)");
            }
            d.append(";\n");
            terms.add(d.toString());
            end = x3;
            // the next term starts on this one's fall (an overlap), at its end (touching) or beyond (a gap)
            at = Double.parseDouble(dec(switch (rnd.nextInt(4)) {
                case 0 -> x3;
                case 1 -> x3 + (grid ? 1 : rnd.nextDouble());
                default -> x2 + (x3 - x2) * (grid ? 0.5 : rnd.nextDouble());
            }));
        }
        // declared in any order: the chain's order (and the static filter's stored order) is the terms' places,
        // not their declaration's or the rules'
        java.util.Collections.shuffle(terms, rnd);
        StringBuilder d = new StringBuilder("DEFUZZIFY y\n");
        terms.forEach(d::append);
        d.append("    METHOD : CoG;\n    DEFAULT := -7;\n");
        if (range) {
            d.append("    RANGE := (").append(dec(first - (rnd.nextBoolean() ? 0 : 3))).append(" .. ")
                    .append(dec(end - (rnd.nextBoolean() && end - 2 > first + 1 ? 2 : 0))).append(");\n");
        }
        String act = rnd.nextInt(3) == 0 ? "PROD" : "MIN";
        String out = text.substring(0, from) + d + text.substring(to);
        return out.replace("    ACCU : MAX;\n", "    ACT : " + act + ";\n    ACCU : MAX;\n");
    }

    private static String dec(double v) {
        return new BigDecimal(v).round(new MathContext(6)).stripTrailingZeros().toPlainString();
    }

    /** An input: random in the points' span, on a point, next to one, or a multiple of 1/1024. */
    private static double input(Random rnd, double[] xs) {
        double lo = Arrays.stream(xs).min().orElse(0) - 1;
        double hi = Arrays.stream(xs).max().orElse(1) + 1;
        double x = xs[rnd.nextInt(xs.length)];
        return switch (rnd.nextInt(5)) {
            case 0 -> x;
            case 1 -> Math.nextUp(x);
            case 2 -> Math.nextDown(x);
            case 3 -> Math.rint((lo + rnd.nextDouble() * (hi - lo)) * 1024) / 1024;
            default -> lo + rnd.nextDouble() * (hi - lo);
        };
    }
}
