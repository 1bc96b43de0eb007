package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.Written;
import org.junit.jupiter.api.Test;

/**
 * Programs of our own in jFuzzyLogic's style, one group of its constructs each, run in the real, unmodified
 * jFuzzyLogic build (skipped with the reason when it is missing, failing with CI set) and read by fclcert's
 * jFuzzyLogic reader: their values agree. Where jFuzzyLogic computes a weighted average (COGS: singletons,
 * FUNCTION terms) to 1e-9; where it integrates (CoG) on 1000 samples of the universe (docs/peers.md), to 2e-3 of
 * the universe's width, its sampling step's order. Each program is evaluated on a sequence of inputs on one
 * instance, so what carries over between evaluations (DEFAULT NC, an output read in a condition) is compared too.
 */
class JFuzzyLogicDialectTest {
    private static final double EXACT = 1e-9;
    private static final double SAMPLED = 2e-3;

    /** No RANGE: the universe is its terms' span (points not falling to 0; a Gaussian reaching mean ± 4 sd). */
    private static final String UNIVERSE = """
            FUNCTION_BLOCK universe   // outputs without RANGE: jFuzzyLogic takes its terms' span
            VAR_INPUT
              temp : REAL;
              hum : REAL;
            END_VAR
            VAR_OUTPUT
              fan : REAL;
              heat : REAL;
            END_VAR
            FUZZIFY temp
              TERM cold := TRAPE 0 0 5 15;
              TERM hot := TRIAN 10 30 30;
            END_FUZZIFY
            FUZZIFY hum
              TERM dry := (0, 1) (60, 0);
              TERM wet := (40, 0) (100, 1);
            END_FUZZIFY
            DEFUZZIFY fan
              TERM slow := (0, 1) (40, 0);
              TERM fast := (30, 0) (100, 1);
              METHOD : COG;
              DEFAULT := 0;
            END_DEFUZZIFY
            DEFUZZIFY heat
              TERM off := gauss 0 5;
              TERM on := gauss 50 10;
              METHOD : COG;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
              AND : MIN;
              ACCU : MAX;
              RULE 1 : IF temp IS cold AND hum IS dry THEN fan IS slow, heat IS on;
              RULE 2 : IF temp IS hot OR hum IS wet THEN fan IS fast, heat IS off;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * Takagi–Sugeno FUNCTION terms: formulas of the inputs, a weighted average. (jFuzzyLogic accumulates singletons by
     * their value, not their term: two terms that happen to take one value are one point to it, so the values here
     * never meet: flat is an integer on the grid, steep a multiple of ½ plus ¼, level 4.1.)
     */
    private static final String FUNCTIONS = """
            FUNCTION_BLOCK sugeno
            VAR_INPUT
              x : REAL;
              y : REAL;
            END_VAR
            VAR_OUTPUT
              z : REAL;
            END_VAR
            FUZZIFY x
              TERM lo := TRIAN 0 0 10;
              TERM hi := TRIAN 0 10 10;
            END_FUZZIFY
            FUZZIFY y
              TERM small := TRAPE 0 0 2 8;
              TERM big := TRAPE 2 8 10 10;
            END_FUZZIFY
            DEFUZZIFY z
              TERM flat := FUNCTION 2 * x + y;
              TERM steep := FUNCTION (x * 3) - y / 2 + 0.25;
              TERM level := 4.1;
              METHOD : COGS;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
              AND : PROD;
              ACCU : MAX;
              RULE 1 : IF x IS lo THEN z IS flat;
              RULE 2 : IF x IS hi AND y IS big THEN z IS steep;
              RULE 3 : IF y IS small THEN z IS level;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * Points and a trian given by input variables (5.2.2), and the norms jFuzzyLogic adds (HAMACHER, which it couples
     * with EINSTEIN). jFuzzyLogic finds a variable in a point only after a FUZZIFY block of it (its VAR section
     * creates none), hence the blocks of mid and edge.
     */
    private static final String VARIABLES = """
            FUNCTION_BLOCK moving
            VAR_INPUT
              level : REAL;
              mid : REAL;
              edge : REAL;
            END_VAR
            VAR_OUTPUT
              pump : REAL;
            END_VAR
            FUZZIFY mid
              TERM any := (0, 1) (20, 1);
            END_FUZZIFY
            FUZZIFY edge
              TERM any := (0, 1) (30, 1);
            END_FUZZIFY
            FUZZIFY level
              TERM low := (0, 1) (mid, 0);
              TERM ok := TRIAN 0 mid edge;
              TERM high := (mid, 0) (edge, 1);
            END_FUZZIFY
            DEFUZZIFY pump
              TERM stop := 0;
              TERM half := 50;
              TERM full := 100;
              METHOD : COGS;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
              AND : HAMACHER;
              ACCU : MAX;
              RULE 1 : IF level IS low THEN pump IS stop;
              RULE 2 : IF level IS ok AND level IS NOT high THEN pump IS half;
              RULE 3 : IF level IS high OR level IS ok THEN pump IS full;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * Rule blocks read each other's outputs: jFuzzyLogic reads an output at its value when the evaluation begins
     * (its DEFAULT, or with DEFAULT NC the last value), so 'mood' follows last step's tip and this step's 'calm'
     * the constant DEFAULT 10 of 'alarm'; no ACCU (SUM), no DEFAULT (NC), a rule number written twice.
     */
    private static final String CHAINED = """
            FUNCTION_BLOCK chained   /* a second block reads the first block's outputs */
            VAR_INPUT
              service : REAL;
            END_VAR
            VAR_OUTPUT
              tip : REAL;
              alarm : REAL;
              mood : REAL;
            END_VAR
            FUZZIFY service
              TERM poor := TRIAN 0 0 10;
              TERM good := TRIAN 0 10 10;
            END_FUZZIFY
            DEFUZZIFY tip
              TERM low := TRIAN 0 5 15;
              TERM high := TRIAN 10 25 30;
              METHOD : COG;
            END_DEFUZZIFY
            DEFUZZIFY alarm
              TERM quiet := TRIAN 0 0 20;
              TERM loud := TRIAN 0 20 20;
              METHOD : COG;
              DEFAULT := 10;
            END_DEFUZZIFY
            DEFUZZIFY mood
              TERM sad := 0;
              TERM glad := 1;
              TERM calm := 0.5;
              METHOD : COGS;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK first
              RULE 1 : IF service IS poor THEN tip IS low, alarm IS loud;
              RULE 2 : IF service IS good THEN tip IS high, alarm IS quiet;
            END_RULEBLOCK
            RULEBLOCK second
              ACCU : MAX;
              RULE 1 : IF tip IS high THEN mood IS glad;
              RULE 1 : IF tip IS low THEN mood IS sad;
              RULE 3 : IF alarm IS quiet THEN mood IS calm;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private static Program read(String text) {
        DialectReaders.Choice c = DialectReaders.auto(text);
        assertEquals(Dialect.JFUZZYLOGIC, c.dialect(), c.explanation());
        Analysis a = Analysis.analyze(c.reader(), "p.fcl", text);
        assertTrue(a.diagnostics().stream().noneMatch(Diagnostic::isError), a.diagnostics()::toString);
        return a.program().orElseThrow();
    }

    /** The inputs of each step: every input on a grid of n points over [lo, hi], in order. */
    private static List<Map<String, Double>> steps(Map<String, double[]> inputs, int n) {
        List<Map<String, Double>> rows = new ArrayList<>(List.of(new LinkedHashMap<>()));
        for (Map.Entry<String, double[]> e : inputs.entrySet()) {
            List<Map<String, Double>> next = new ArrayList<>();
            for (Map<String, Double> r : rows) {
                for (int i = 0; i < n; i++) {
                    Map<String, Double> m = new LinkedHashMap<>(r);
                    m.put(e.getKey(), e.getValue()[0] + (e.getValue()[1] - e.getValue()[0]) * i / (n - 1));
                    next.add(m);
                }
            }
            rows = next;
        }
        return rows;
    }

    /**
     * Runs the steps on one jFuzzyLogic instance and one fclcert instance and compares every output: exactly
     * those named, the others to {@link #SAMPLED} of the output's universe (its RANGE as fclcert reads it).
     * Returns the number of values compared.
     */
    private static int compare(ImplementationUnderTest iut, String text, List<Map<String, Double>> steps,
            List<String> exact) throws Exception {
        return compare(iut, text, steps, exact, List.of());
    }

    /** As above, leaving out at the first step the outputs named in {@code notFirst}. */
    private static int compare(ImplementationUnderTest iut, String text, List<Map<String, Double>> steps,
            List<String> exact, List<String> notFirst) throws Exception {
        Program p = read(text);
        assertTrue(iut.load(text) instanceof LoadOutcome.Loaded, "jFuzzyLogic loads it");
        iut.reset();
        FunctionBlockInstance ours = Evaluator.load(p).newInstance();
        String block = p.functionBlocks().get(0).name();
        int compared = 0;
        boolean first = true;
        double worstExact = 0;
        double worstSampled = 0;
        for (Map<String, Double> step : steps) {
            Map<String, Double> theirs = iut.eval(block, step);
            for (Map.Entry<String, Double> e : step.entrySet()) {
                ours.set(e.getKey(), e.getValue());
            }
            ours.evaluate();
            for (Defuzzification d : p.functionBlocks().get(0).defuzzifications()) {
                String o = d.variable();
                if (first && notFirst.contains(o)) {
                    continue;
                }
                double tolerance = exact.contains(o) ? EXACT : SAMPLED * width(d);
                assertEquals(theirs.get(o), ours.get(o), tolerance, block + " " + o + " at " + step);
                double diff = Math.abs(theirs.get(o) - ours.get(o));
                if (exact.contains(o)) {
                    worstExact = Math.max(worstExact, diff);
                } else {
                    worstSampled = Math.max(worstSampled, diff / width(d));
                }
                compared++;
            }
            first = false;
        }
        System.out.println("jFuzzyLogic and fclcert on '" + block + "': " + compared + " values, largest difference "
                + worstExact + " (weighted averages), " + worstSampled + " of the universe (sampled)");
        return compared;
    }

    /** The universe jFuzzyLogic samples: the RANGE as fclcert reads it, else the span of the terms' points. */
    private static double width(Defuzzification d) {
        if (d.range().isPresent()) {
            return d.range().get().max().value() - d.range().get().min().value();
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (var t : d.terms()) {
            if (t.function() instanceof org.fclcert.model.MembershipFunction.Singleton one) {
                lo = Math.min(lo, ((org.fclcert.model.Literal) one.value()).value());
                hi = Math.max(hi, ((org.fclcert.model.Literal) one.value()).value());
                continue;
            }
            var pts = t.function() instanceof org.fclcert.model.MembershipFunction.NamedShape n ? n.points().orElseThrow()
                    : ((org.fclcert.model.MembershipFunction.Points) t.function()).points();
            for (var pt : pts) {
                double x = ((org.fclcert.model.Literal) pt.x()).value();
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        return hi - lo;
    }

    private static ImplementationUnderTest open() throws IutException {
        return Iuts.open(JFuzzyLogic.spec(), IutOptions.defaults().withTimeout(Duration.ofSeconds(20)));
    }

    /**
     * RANGE in FUZZIFY: jFuzzyLogic's grammar refuses it ("mismatched input 'RANGE' expecting END_FUZZIFY"), so
     * fclcert's reader of its dialect does too, at the RANGE; without it the same program loads in both.
     */
    @Test
    void rangeInFuzzifyIsRefusedAsJFuzzyLogicRefusesIt() throws Exception {
        String text = """
                FUNCTION_BLOCK t
                VAR_INPUT
                    x : REAL;
                END_VAR
                VAR_OUTPUT
                    y : REAL;
                END_VAR
                // jFuzzyLogic
                FUZZIFY x
                    RANGE := (0 .. 10);
                    TERM lo := (0, 1) (10, 0);
                END_FUZZIFY
                DEFUZZIFY y
                    TERM a := 5;
                    METHOD : COGS;
                    DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    ACCU : MAX;
                    RULE 1 : IF x IS lo THEN y IS a;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = Analysis.analyze(DialectReaders.reader(Dialect.JFUZZYLOGIC), "p.fcl", text);
        assertTrue(a.diagnostics().stream().anyMatch(d -> d.isError() && d.code().equals("FCL-S306")
                && d.location().line() == 10 && d.location().column() == 5), a.diagnostics()::toString);
        String without = text.replace("    RANGE := (0 .. 10);\n", "");
        try (ImplementationUnderTest iut = open()) {
            assertFalse(iut.load(text) instanceof LoadOutcome.Loaded, "jFuzzyLogic refuses RANGE in FUZZIFY");
            assertTrue(iut.load(without) instanceof LoadOutcome.Loaded, "jFuzzyLogic loads it without");
        }
        read(without);

        // where jFuzzyLogic takes an input's RANGE: after its declaration; fclcert reads it there, and writes it there
        String declared = without.replace("    x : REAL;\n", "    x : REAL;\n    RANGE := (0 .. 10);\n");
        Program p = read(declared);
        assertEquals(List.of(0.0, 10.0), p.functionBlocks().get(0).fuzzification("x").orElseThrow().declaredRange()
                .map(r -> List.of(r.min().value(), r.max().value())).orElseThrow());
        Written w = DialectWriters.writer(Dialect.JFUZZYLOGIC).write(p);
        assertTrue(w.text().contains("    x : REAL;\n    RANGE := (0 .. 10);\n"), w.text());
        assertTrue(w.differences().isEmpty(), w.differences()::toString);
        try (ImplementationUnderTest iut = open()) {
            assertTrue(iut.load(declared) instanceof LoadOutcome.Loaded, "jFuzzyLogic loads a RANGE after x's declaration");
            assertTrue(iut.load(w.text()) instanceof LoadOutcome.Loaded, "jFuzzyLogic loads what fclcert writes");
        }
    }

    /**
     * Each smooth shape as jFuzzyLogic computes it: two terms per output, clipped at complementary degrees and cut
     * by the RANGE, so a wrong parameter order or scale moves the CoG. The cosine's first parameter is half its
     * support (fclcert read it as the whole support until 2026-12-04: 0.02 to 0.2 off on O-SHAPE-COSINE-081).
     */
    @Test
    void smoothShapesAreJFuzzyLogicsOwn() throws Exception {
        String text = """
                FUNCTION_BLOCK smooth
                VAR_INPUT
                    x : REAL;
                END_VAR
                VAR_OUTPUT
                    c : REAL;
                    g : REAL;
                    b : REAL;
                    s : REAL;
                    d : REAL;
                END_VAR
                FUZZIFY x
                    TERM lo := (0, 1) (10, 0);
                    TERM hi := (0, 0) (10, 1);
                END_FUZZIFY
                DEFUZZIFY c
                    TERM p := cosine 2 1;
                    TERM q := cosine 3 6;
                    METHOD : COG;
                    DEFAULT := 0;
                    RANGE := (0 .. 10);
                END_DEFUZZIFY
                DEFUZZIFY g
                    TERM p := gauss 1 2;
                    TERM q := gauss 8 1;
                    METHOD : COG;
                    DEFAULT := 0;
                    RANGE := (0 .. 10);
                END_DEFUZZIFY
                DEFUZZIFY b
                    TERM p := gbell 2 3 1;
                    TERM q := gbell 1 2 7;
                    METHOD : COG;
                    DEFAULT := 0;
                    RANGE := (0 .. 10);
                END_DEFUZZIFY
                DEFUZZIFY s
                    TERM p := sigm -2 3;
                    TERM q := sigm 1 6;
                    METHOD : COG;
                    DEFAULT := 0;
                    RANGE := (0 .. 10);
                END_DEFUZZIFY
                DEFUZZIFY d
                    TERM p := dsigm 3 1 2 4;
                    TERM q := dsigm 1 5 4 8;
                    METHOD : COG;
                    DEFAULT := 0;
                    RANGE := (0 .. 10);
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    ACT : MIN;
                    ACCU : MAX;
                    RULE 1 : IF x IS lo THEN c IS p, g IS p, b IS p, s IS p, d IS p;
                    RULE 2 : IF x IS hi THEN c IS q, g IS q, b IS q, s IS q, d IS q;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        try (ImplementationUnderTest iut = open()) {
            assertEquals(5 * 11, compare(iut, text, steps(Map.of("x", new double[] {0, 10}), 11), List.of()));
        }
    }

    /** The implied universes fclcert reads are the ones jFuzzyLogic defuzzifies over. */
    @Test
    void impliedUniversesAgreeWithJFuzzyLogicsSampledCog() throws Exception {
        Program p = read(UNIVERSE);
        Defuzzification fan = p.functionBlocks().get(0).defuzzification("fan").orElseThrow();
        Defuzzification heat = p.functionBlocks().get(0).defuzzification("heat").orElseThrow();
        assertEquals(List.of(0.0, 100.0), List.of(fan.range().get().min().value(), fan.range().get().max().value()));
        assertEquals(List.of(-20.0, 90.0), List.of(heat.range().get().min().value(), heat.range().get().max().value()));
        try (ImplementationUnderTest iut = open()) {
            assertEquals(2 * 121, compare(iut, UNIVERSE, steps(Map.of("temp", new double[] {0, 30},
                    "hum", new double[] {0, 100}), 11), List.of()));
        }
    }

    @Test
    void functionTermsAreTheWeightedAverageJFuzzyLogicComputes() throws Exception {
        try (ImplementationUnderTest iut = open()) {
            assertEquals(121, compare(iut, FUNCTIONS, steps(Map.of("x", new double[] {0, 10},
                    "y", new double[] {0, 10}), 11), List.of("z")));
        }
    }

    @Test
    void variablePointsAndJFuzzyLogicsOwnNormsAgree() throws Exception {
        List<Map<String, Double>> steps = new ArrayList<>();
        for (Map<String, Double> s : steps(Map.of("level", new double[] {0, 20}, "mid", new double[] {4, 10}), 9)) {
            Map<String, Double> m = new LinkedHashMap<>(s);
            m.put("edge", s.get("mid") + 6);
            steps.add(m);
        }
        try (ImplementationUnderTest iut = open()) {
            assertEquals(81, compare(iut, VARIABLES, steps, List.of("pump")));
        }
    }

    /**
     * Chained rule blocks: over a sequence of steps on one instance, 'mood' reads last step's tip (NC) and the
     * alarm's DEFAULT 10, as jFuzzyLogic does; tip and alarm are sampled CoGs over their terms' span. Left out: 'mood'
     * at the first step, where jFuzzyLogic's tip has no value yet (NaN: every degree of it is NaN, so 'mood' falls
     * to its DEFAULT) and fclcert's has its initial value 0.
     */
    @Test
    void chainedRuleBlocksReadTheOutputsAsJFuzzyLogicDoes() throws Exception {
        Program p = read(CHAINED);
        assertTrue(p.dialectFeatures().stream().filter(u -> u.feature().id().equals("O-OUTPUT-VALUE-CONDITION")).count() == 3);
        List<Map<String, Double>> steps = new ArrayList<>();
        for (double s : new double[] {8, 2, 2, 9, 5, 0, 10, 3, 7, 7}) {
            steps.add(Map.of("service", s));
        }
        try (ImplementationUnderTest iut = open()) {
            // mood reads jFuzzyLogic's sampled tip: to the sampling's order too
            assertEquals(29, compare(iut, CHAINED, steps, List.of(), List.of("mood")));
        }
        // by hand, for the reading itself: the first step starts from tip 0, where neither 'low' (5..15 peak 5,
        // 0 at 0) nor 'high' is above 0; alarm at its DEFAULT 10: quiet 0.5, so calm 0.5 alone: mood = 0.5
        FunctionBlockInstance x = Evaluator.load(p).newInstance();
        x.set("service", 8);
        x.evaluate();
        assertEquals(0.5, x.get("mood"), EXACT);
        double tip = x.get("tip");
        assertTrue(tip > 15 && tip < 25, "tip " + tip);
        // the next step reads that tip (above 15: low 0, high h): glad h and calm 0.5 → (1·h + 0.5·0.5) / (h + 0.5),
        // whatever service is now
        double high = tip <= 25 ? (tip - 10) / 15 : (30 - tip) / 5;
        x.set("service", 0);
        x.evaluate();
        assertEquals((high + 0.25) / (high + 0.5), x.get("mood"), EXACT);
    }
}
