package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;
import org.fclcert.write.StandardConversion.Finding;
import org.fclcert.write.StandardConversion.Kind;
import org.junit.jupiter.api.Test;

/**
 * The jFuzzyLogic and fuzzylite samples convert to standard FCL (StandardConversion, wired for named shapes,
 * hedges, PROBOR/SUM, COGSS, DEFAULT nan and the reader-recorded constructs): where the conversion claims
 * exactness the converted text, read back by the strict reader, evaluates exactly like the dialect program on a
 * grid; where it approximates, the stated bound holds against a dense independent measurement; where it cannot,
 * the findings name each construct. Auto detection picks the right dialect for every sample of all three.
 */
class LibraryDialectConversionTest {
    private static final String RESOURCES = "src/test/resources/org/fclcert/syntax/dialect/";

    private static String text(String path) {
        try {
            return Files.readString(Path.of(path));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Program read(DialectReader reader, String path) {
        Analysis a = Analysis.analyze(reader, path, text(path));
        return a.program().orElseThrow(() -> new AssertionError(path + ": " + a.diagnostics()));
    }

    private static Program standard(String name, String text) {
        Analysis a = Analysis.analyze(new StrictReader(), name, text);
        assertTrue(a.diagnostics().stream().noneMatch(d -> d.isError()), () -> a.diagnostics() + "\n" + text);
        return a.program().orElseThrow();
    }

    private static List<String> ids(StandardConversion.Result r, Class<? extends Kind> kind) {
        return r.findings().stream().filter(f -> kind.isInstance(f.kind())).map(Finding::construct).toList();
    }

    // ---------------------------------------------------------------- exact conversions

    @Test
    void exactSamplesEvaluateLikeTheirConversionOnAGrid() throws EvaluationException {
        Map<String, DialectReader> samples = Map.of("examples/jfuzzylogic/fan.fcl", new JFuzzyLogicReader(),
                "examples/fuzzylite/parking.fcl", new FuzzyliteReader());
        for (Map.Entry<String, DialectReader> e : samples.entrySet()) {
            Program original = read(e.getValue(), e.getKey());
            StandardConversion.Result r = new StandardConversion().convert(original);
            assertTrue(r.exact(), () -> e.getKey() + ": " + r.findings());
            Program converted = standard(e.getKey(), new CanonicalWriter().write(r.program()));
            assertEquals(41 * 41, compareOnGrid(original, converted), e.getKey());
        }
    }

    /*
     * fan.fcl: 2 comment styles (line 1 and the '//' on line 40), the input RANGE, 6 named linear shapes and COGF:
     * 10 findings, all exact. parking.fcl: 2 '#' comments, 5 ENABLED (two inputs, two outputs, the rule block),
     * 2 input RANGEs, 6 named linear shapes, 1 Discrete, 2 ACCU in DEFUZZIFY, LOCK RANGE, 4 rules without ';',
     * 'and' between conclusions, 'speed is any' in an AND: 2+5+2+6+1+2+1+4+1+1 = 25 findings, counted by hand.
     */
    @Test
    void everyConstructOfTheExactSamplesHasOneFinding() {
        StandardConversion.Result fan = new StandardConversion().convert(read(new JFuzzyLogicReader(),
                "examples/jfuzzylogic/fan.fcl"));
        assertEquals(List.of("O-COMMENT-STYLE", "O-DECLARATION-RANGE", "O-SHAPE-TRAPEZOID", "O-SHAPE-TRIANGLE",
                "O-SHAPE-TRAPEZOID", "O-SHAPE-TRIANGLE", "O-SHAPE-TRIANGLE", "O-SHAPE-TRAPEZOID", "O-METHOD-COGF",
                "O-COMMENT-STYLE"), ids(fan, Kind.Exact.class));
        StandardConversion.Result parking = new StandardConversion().convert(read(new FuzzyliteReader(),
                "examples/fuzzylite/parking.fcl"));
        assertEquals(25, parking.findings().size(), parking.findings().toString());
        assertEquals(25, ids(parking, Kind.Exact.class).size());
        assertEquals(5, ids(parking, Kind.Exact.class).stream().filter("O-ENABLED"::equals).count());
        assertEquals(4, ids(parking, Kind.Exact.class).stream().filter("O-RULE-WITHOUT-SEMICOLON"::equals).count());
        Finding any = parking.findings().stream().filter(f -> f.construct().equals("O-HEDGE-ANY")).findFirst()
                .orElseThrow();
        assertEquals(56, any.location().line());
        assertInstanceOf(Kind.Exact.class, any.kind());
    }

    /** Both programs on a 41 × 41 grid over each input's RANGE widened by a quarter on each side. */
    private static int compareOnGrid(Program a, Program b) throws EvaluationException {
        FunctionBlock fb = a.functionBlocks().get(0);
        List<Variable> inputs = fb.variables(VariableKind.INPUT);
        double[][] span = new double[2][];
        for (int k = 0; k < 2; k++) {
            String name = inputs.get(k).name();
            Fuzzification f = fb.fuzzifications().stream().filter(z -> z.variable().equals(name)).findFirst()
                    .orElseThrow();
            double lo = f.declaredRange().map(r -> r.min().value()).orElse(0.0);
            double hi = f.declaredRange().map(r -> r.max().value()).orElse(100.0);
            span[k] = new double[] {lo - (hi - lo) / 4, hi + (hi - lo) / 4};
        }
        return EvaluatesAlike.onGrid(a, b, 41, i -> span[0][0] + (span[0][1] - span[0][0]) * i / 40,
                j -> span[1][0] + (span[1][1] - span[1][0]) * j / 40);
    }

    // ---------------------------------------------------------------- approximations

    @Test
    void approximationBoundsHoldOnADenseGrid() {
        for (int n : List.of(11, 41, 161)) {
            Program original = read(new JFuzzyLogicReader(), "examples/jfuzzylogic/tipper.fcl");
            StandardConversion.Result r = new StandardConversion().convert(original,
                    new StandardConversion.Options(n));
            assertTrue(r.expressible(), r.findings().toString());
            assertFalse(r.exact());
            List<Finding> approximated = r.findings().stream().filter(f -> f.kind() instanceof Kind.Approximated)
                    .toList();
            assertEquals(5, approximated.size(), "3 Gaussians of service, the Gaussian and the cosine of tip");
            FunctionBlock before = original.functionBlocks().get(0);
            FunctionBlock after = standard("tipper", new CanonicalWriter().write(r.program())).functionBlocks().get(0);
            for (Finding f : approximated) {
                double bound = ((Kind.Approximated) f.kind()).maxError();
                String term = f.message().substring(f.message().indexOf('\'') + 1, f.message().indexOf("' of "));
                double[] interval = f.message().contains("input") ? new double[] {0, 10} : new double[] {0, 30};
                MembershipFunction.NamedShape shape = (MembershipFunction.NamedShape) termOf(before, term).function();
                List<Point> points = ((MembershipFunction.Points) termOf(after, term).function()).points();
                double measured = 0;
                int samples = 30_000;
                for (int i = 0; i <= samples; i++) {
                    double u = interval[0] + (interval[1] - interval[0]) * i / samples;
                    measured = Math.max(measured, Math.abs(shape.kind().degree(shape.values(), u)
                            - polyline(points, u)));
                }
                assertTrue(measured <= bound, term + " with " + n + " points: measured " + measured + " > " + bound);
                assertTrue(measured > 0 && bound < 20 * measured + 1e-12, term + ": bound " + bound
                        + " far above the measured " + measured);
            }
        }
    }

    /*
     * Gaussian of sd 1.5 on [0, 10] with 11 points (step 1): the chord error of a curve is at most h²·max|μ''|/8,
     * and |μ''| ≤ 1/sd² = 0.444, so 1 · 0.444 / 8 = 0.0556 bounds the true error; the reported bound (which also
     * covers the sampling between sub-samples) is checked against the dense measurement above, and here against
     * this closed form: it must not be below the true error, and the true error must be below 0.0556.
     */
    @Test
    void approximationErrorOfAGaussianAgreesWithTheChordBound() {
        StandardConversion.Result r = new StandardConversion().convert(read(new JFuzzyLogicReader(),
                "examples/jfuzzylogic/tipper.fcl"), new StandardConversion.Options(11));
        Finding poor = r.findings().stream().filter(f -> f.message().startsWith("term 'poor'")).findFirst()
                .orElseThrow();
        double bound = ((Kind.Approximated) poor.kind()).maxError();
        assertTrue(bound > 0.01 && bound < 0.0556 * 1.05, "bound " + bound);
    }

    private static Term termOf(FunctionBlock fb, String name) {
        for (Fuzzification f : fb.fuzzifications()) {
            if (f.term(name).isPresent()) {
                return f.term(name).get();
            }
        }
        for (Defuzzification d : fb.defuzzifications()) {
            if (d.term(name).isPresent()) {
                return d.term(name).get();
            }
        }
        throw new AssertionError(name);
    }

    /** Linear interpolation through constant points, flat outside (5.2.2), written independently of the evaluator. */
    private static double polyline(List<Point> points, double u) {
        double[] x = points.stream().mapToDouble(p -> ((Literal) p.x()).value()).toArray();
        double[] y = points.stream().mapToDouble(p -> ((Literal) p.degree()).value()).toArray();
        if (u <= x[0]) {
            return y[0];
        }
        for (int i = 0; i + 1 < x.length; i++) {
            if (u <= x[i + 1]) {
                return x[i + 1] == x[i] ? y[i + 1] : y[i] + (y[i + 1] - y[i]) * (u - x[i]) / (x[i + 1] - x[i]);
            }
        }
        return y[y.length - 1];
    }

    // ---------------------------------------------------------------- lossy samples

    @Test
    void lossySamplesNameEveryConstructStandardFclCannotSay() {
        StandardConversion.Result obstacle = new StandardConversion().convert(read(new FuzzyliteReader(),
                RESOURCES + "fuzzylite/obstacle.fcl"), new StandardConversion.Options(50));
        assertEquals(List.of("O-SHAPE-GAUSSIAN", "O-ACCU-PROBOR", "METHOD COGSS", "O-HEDGE-VERY", "O-HEDGE-SOMEWHAT",
                "O-HEDGE-EXTREMELY", "O-HEDGE-SELDOM"), ids(obstacle, Kind.NotExpressible.class));
        // the output's bell has a RANGE (0 .. 1) and converts approximately; the input's Gaussian has none (-inf)
        assertEquals(List.of("O-SHAPE-BELL"), ids(obstacle, Kind.Approximated.class));
        assertTrue(obstacle.findings().stream().anyMatch(f -> f.construct().equals("O-SHAPE-GAUSSIAN")
                && f.message().contains("no finite RANGE")), obstacle.findings().toString());
        standard("obstacle", new CanonicalWriter().write(obstacle.program()));   // what --allow-lossy writes

        StandardConversion.Result tipper = new StandardConversion().convert(read(new JFuzzyLogicReader(),
                RESOURCES + "jfuzzylogic/tipper.fcl"));
        assertEquals(List.of("O-SHAPE-GAUSSIAN", "O-SHAPE-BELL", "O-SHAPE-SIGMOID", "O-SHAPE-GAUSSIAN",
                "O-SHAPE-COSINE", "O-ACCU-PROBOR"), ids(tipper, Kind.NotExpressible.class));
        standard("tipper", new CanonicalWriter().write(tipper.program()));

        // habits.fcl pairs AND MIN with OR ASUM: a check error (FCL-C014), so there is no program to convert
        Analysis habits = Analysis.analyze(new JFuzzyLogicReader(), "habits.fcl",
                text(RESOURCES + "jfuzzylogic/habits.fcl"));
        assertTrue(habits.diagnostics().stream().anyMatch(d -> d.isError() && d.code().equals("FCL-C014")));
    }

    // ---------------------------------------------------------------- auto detection

    @Test
    void autoPicksTheDialectOfEverySampleAndStrictForStandardPrograms() throws IOException {
        Map<Dialect, List<String>> samples = Map.of(
                Dialect.JFUZZYLOGIC, List.of("examples/jfuzzylogic/fan.fcl", "examples/jfuzzylogic/tipper.fcl",
                        RESOURCES + "jfuzzylogic/tipper.fcl", RESOURCES + "jfuzzylogic/habits.fcl"),
                Dialect.FUZZYLITE, List.of("examples/fuzzylite/parking.fcl", RESOURCES + "fuzzylite/obstacle.fcl"),
                Dialect.FFLL, List.of("examples/ffll/guard.fcl", "examples/ffll/heater.fcl",
                        RESOURCES + "ffll/mixer.fcl"));
        for (Map.Entry<Dialect, List<String>> e : samples.entrySet()) {
            for (String path : e.getValue()) {
                DialectReaders.Choice c = DialectReaders.auto(text(path));
                assertEquals(e.getKey(), c.dialect(), path + ": " + c.explanation());
                assertTrue(c.explanation().startsWith("read as " + e.getKey().displayName() + ": "), c.explanation());
            }
        }
        List<Path> standard = new ArrayList<>(List.of(Path.of("examples/valve.fcl")));
        try (Stream<Path> s = Files.list(Path.of("conformance/basic"))) {
            s.sorted().forEach(standard::add);
        }
        for (Path p : standard) {
            DialectReaders.Choice c = DialectReaders.auto(Files.readString(p));
            assertEquals(Dialect.STRICT, c.dialect(), p + ": " + c.explanation());
        }
    }

    /** A standard rule continued on the next line is not fuzzylite's 'rule without ;' (it was, before). */
    @Test
    void aStandardRuleOverSeveralLinesGivesNothingAway() {
        String rule = "RULEBLOCK r\n AND : MIN;\n RULE 1 : IF a IS x\n   AND b IS y\n   THEN c IS z;\nEND_RULEBLOCK\n";
        assertEquals(List.of(), new FuzzyliteReader().giveaways(rule));
        String fuzzylite = "RULEBLOCK r\n RULE 1 : if a is x then c is z\n RULE 2 : if a is y then c is z\n"
                + "END_RULEBLOCK\n";
        assertEquals(List.of(new DialectReader.Giveaway("rule without ';'", 2),
                new DialectReader.Giveaway("lower-case rule keywords", 2, 0),
                new DialectReader.Giveaway("rule without ';'", 3),
                new DialectReader.Giveaway("lower-case rule keywords", 3, 0)), new FuzzyliteReader().giveaways(fuzzylite));
    }
}
