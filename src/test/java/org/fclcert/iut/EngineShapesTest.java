package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.Trace;
import org.fclcert.model.Program;
import org.fclcert.syntax.FclReader;
import org.fclcert.write.DialectWriters;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.FisReader;
import org.fclcert.syntax.dialect.FllReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every named membership function of FIS and FLL as the engines themselves compute it, against fclcert's reading of
 * the same text (reader, model, evaluator: the degrees of the input's terms in an evaluation's trace). FIS: Octave's
 * fuzzy-logic-toolkit reads the file ({@code readfis}) and evaluates each term with {@code evalmf}; FLL: pyfuzzylite
 * 8.0.6 imports the file ({@code FllImporter}) and evaluates each term's {@code membership}; and fuzzylite 6.0's own
 * reading of FIS (its command line's FisImporter, exporting FLL for pyfuzzylite), fuzzylite's additions included.
 * Octave and pyfuzzylite also evaluate what fclcert's FIS and FLL writers write of the program read (what
 * {@code --present-as fis|fll} sends them).
 * Each shape with several parameter sets (asymmetric, reversed, touching corners), each at 50 grid points plus the
 * integers −12…12 (where most breakpoints lie), to 1e-9. Where an engine computes otherwise on purpose, the test asserts that difference as
 * worked out from the engine's own source (named at the assertion). Skipped outside CI when Octave with the toolkit,
 * pyfuzzylite or fuzzylite is missing (scripts/ensure-octave, scripts/ensure-pyfuzzylite, scripts/ensure-fuzzylite);
 * with CI set, their absence fails.
 */
class EngineShapesTest {
    private static final double TOLERANCE = 1e-9;

    /** 50 points over the input's range, and the integers −12…12. */
    private static double[] points() {
        double[] x = new double[75];
        for (int i = 0; i < 50; i++) {
            x[i] = -19.5 + 0.8 * i;
        }
        for (int i = 0; i < 25; i++) {
            x[50 + i] = i - 12;
        }
        java.util.Arrays.sort(x); // Octave's evalmf takes strictly increasing points only
        return x;
    }

    /** FIS membership functions with MATLAB's parameters, each valid for Octave's toolkit (its are_mf_params). */
    private static final List<String[]> FIS_TERMS = List.of(
            new String[] {"trimf", "-3 1 7"}, new String[] {"trimf", "-9 -8.5 12"},
            new String[] {"trapmf", "-8 -2 3 11"}, new String[] {"trapmf", "-15 -10 -10 -5"},
            new String[] {"gaussmf", "2.5 1"}, new String[] {"gaussmf", "0.7 -3"},
            new String[] {"gauss2mf", "1.5 -2 3 4"}, new String[] {"gauss2mf", "2 3 1 -1"},
            new String[] {"gbellmf", "4 2 1"}, new String[] {"gbellmf", "2.5 3 -3"}, new String[] {"gbellmf", "0.5 1 2"},
            new String[] {"sigmf", "2 1"}, new String[] {"sigmf", "-0.8 -3"},
            new String[] {"dsigmf", "3 -4 1.5 5"}, new String[] {"dsigmf", "2 2 0.5 -2"},
            new String[] {"psigmf", "2 -3 -1.5 4"}, new String[] {"psigmf", "0.5 0 0.5 6"},
            new String[] {"smf", "-4 6"}, new String[] {"smf", "1 1.5"},
            new String[] {"zmf", "-3 8"}, new String[] {"zmf", "2 2.5"},
            new String[] {"pimf", "-10 -2 1 9"}, new String[] {"pimf", "-6 0 0 10"});

    /**
     * Bells Octave evaluates and fclcert refuses (FCL-C041: width and slope must be positive): a negative a is the same
     * bell as |a| (the formula takes |(x − c)/a|), a negative b turns it upside down (0 at c, 1 far away).
     */
    private static final List<String[]> FIS_REFUSED = List.of(new String[] {"gbellmf", "-3 1 2"},
            new String[] {"gbellmf", "1.5 -2 4"});

    /** FLL term classes with fuzzylite's parameters (fclcert's canonical order). */
    private static final List<String[]> FLL_TERMS = List.of(
            new String[] {"Triangle", "-3 1 7"}, new String[] {"Triangle", "-5 -5 4"},
            new String[] {"Trapezoid", "-8 -2 3 11"}, new String[] {"Trapezoid", "-15 -10 -10 -5"},
            new String[] {"Rectangle", "-3 4"}, new String[] {"Ramp", "-4 6"}, new String[] {"Ramp", "5 -3"},
            new String[] {"Discrete", "-10 0 -2 1 5 0.3 12 0"},
            new String[] {"Gaussian", "1 2.5"}, new String[] {"Gaussian", "-3 0.7"},
            new String[] {"GaussianProduct", "-2 1.5 4 3"}, new String[] {"GaussianProduct", "3 2 -1 1"},
            new String[] {"Bell", "1 4 2"}, new String[] {"Bell", "-3 2.5 0.4"},
            new String[] {"Sigmoid", "1 2"}, new String[] {"Sigmoid", "-3 -0.8"},
            new String[] {"SigmoidDifference", "-4 3 1.5 5"}, new String[] {"SigmoidDifference", "-2 0.5 2 6"},
            new String[] {"SigmoidProduct", "-3 2 -1.5 4"}, new String[] {"SigmoidProduct", "0 0.5 0.5 6"},
            new String[] {"Cosine", "2 7"}, new String[] {"Cosine", "-5 3"},
            new String[] {"SShape", "-4 6"}, new String[] {"SShape", "1 1.5"},
            new String[] {"ZShape", "-3 8"}, new String[] {"ZShape", "2 2.5"},
            new String[] {"PiShape", "-10 -2 1 9"}, new String[] {"PiShape", "-6 0 0 10"},
            new String[] {"Concave", "1 6"}, new String[] {"Concave", "4 -2"},
            new String[] {"Spike", "1 4"}, new String[] {"Spike", "-2 0.5"});

    private static String fis(List<String[]> terms) {
        StringBuilder b = new StringBuilder("""
                [System]
                Name='shapes'
                Type='mamdani'
                Version=2.0
                NumInputs=1
                NumOutputs=1
                NumRules=1
                AndMethod='min'
                OrMethod='max'
                ImpMethod='min'
                AggMethod='max'
                DefuzzMethod='centroid'

                [Input1]
                Name='x'
                Range=[-20 20]
                """);
        b.append("NumMFs=").append(terms.size()).append('\n');
        for (int k = 0; k < terms.size(); k++) {
            b.append("MF").append(k + 1).append("='t").append(k + 1).append("':'").append(terms.get(k)[0])
                    .append("',[").append(terms.get(k)[1]).append("]\n");
        }
        return b.append("""

                [Output1]
                Name='y'
                Range=[0 1]
                NumMFs=1
                MF1='o':'trimf',[0 0.5 1]

                [Rules]
                1, 1 (1) : 1
                """).toString();
    }

    private static String fll(List<String[]> terms) {
        StringBuilder b = new StringBuilder("Engine: shapes\nInputVariable: x\n  enabled: true\n  range: -20.000 20.000\n"
                + "  lock-range: false\n");
        for (int k = 0; k < terms.size(); k++) {
            b.append("  term: t").append(k + 1).append(' ').append(terms.get(k)[0]).append(' ')
                    .append(terms.get(k)[1]).append('\n');
        }
        return b.append("""
                OutputVariable: y
                  enabled: true
                  range: 0.000 1.000
                  lock-range: false
                  aggregation: Maximum
                  defuzzifier: Centroid 100
                  default: nan
                  lock-previous: false
                  term: o Triangle 0.000 0.500 1.000
                RuleBlock: r
                  enabled: true
                  conjunction: Minimum
                  disjunction: Maximum
                  implication: Minimum
                  activation: General
                  rule: if x is t1 then y is o
                """).toString();
    }

    /** fclcert's degree of every input term at every point: [term][point], through reader, model and evaluator. */
    private static double[][] fclcert(FclReader reader, String name, String text, int terms, double[] x)
            throws Exception {
        Analysis a = Analysis.analyze(reader, name, text);
        Program program = a.program().orElseThrow(() -> new AssertionError(name + ": " + a.diagnostics()));
        double[][] out = new double[terms][x.length];
        FunctionBlockInstance instance = Evaluator.load(program).newInstance();
        Trace trace = new Trace();
        for (int i = 0; i < x.length; i++) {
            instance.set("x", x[i]);
            instance.evaluate(trace);
            List<Trace.TermDegree> degrees = trace.termDegrees();
            assertEquals(terms, degrees.size(), name + ": " + degrees);
            for (int k = 0; k < terms; k++) {
                assertEquals("t" + (k + 1), degrees.get(k).term());
                out[k][i] = degrees.get(k).degree();
            }
        }
        return out;
    }

    private static String list(double[] x) {
        StringBuilder b = new StringBuilder();
        for (double v : x) {
            b.append(b.length() == 0 ? "" : " ").append(String.format(Locale.ROOT, "%.17g", v));
        }
        return b.toString();
    }

    /** Runs a program, returns its standard output's lines of numbers ([term][point]). */
    private static double[][] run(List<String> command, int terms, int points) throws Exception {
        Process p = new ProcessBuilder(command).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), command + " did not finish");
        assertEquals(0, p.exitValue(), () -> command + ": " + out + err);
        String[] lines = out.strip().split("\n");
        assertEquals(terms, lines.length, () -> out + err);
        double[][] y = new double[terms][];
        for (int k = 0; k < terms; k++) {
            String[] w = lines[k].strip().split("\\s+");
            assertEquals(points, w.length, lines[k]);
            y[k] = new double[points];
            for (int i = 0; i < points; i++) {
                y[k][i] = w[i].equalsIgnoreCase("nan") ? Double.NaN : Double.parseDouble(w[i]);
            }
        }
        return y;
    }

    /** The largest difference of each term, named by its class and parameters, for the report. */
    private record Compared(Map<String, Double> worst, int points) {
        double max() {
            return worst.values().stream().mapToDouble(Double::doubleValue).max().orElse(0);
        }
    }

    private static Compared compare(List<String[]> terms, double[][] theirs, double[][] ours, double[] x,
            String engine, Map<String, Expected> deviations) {
        Map<String, Double> worst = new LinkedHashMap<>();
        int points = 0;
        for (int k = 0; k < terms.size(); k++) {
            String term = terms.get(k)[0] + " " + terms.get(k)[1];
            Expected deviation = deviations.get(term);
            double w = 0;
            for (int i = 0; i < x.length; i++) {
                double expected = deviation == null ? ours[k][i] : deviation.of(x[i], ours[k][i]);
                double d = Math.abs(theirs[k][i] - expected);
                if (!(d <= TOLERANCE)) {
                    fail(engine + " " + term + " at " + x[i] + ": engine " + theirs[k][i] + ", fclcert " + ours[k][i]
                            + (deviation == null ? "" : ", expected of the engine " + expected));
                }
                w = Math.max(w, d);
                points++;
            }
            worst.put(term, w);
        }
        return new Compared(worst, points);
    }

    /** What an engine computes where it differs from fclcert on purpose: of the point and fclcert's degree. */
    private interface Expected {
        double of(double x, double fclcert);
    }

    private static double sigmoid(double x, double a, double c) {
        return 1 / (1 + Math.exp(-a * (x - c)));
    }

    @Test
    void octavesMembershipFunctionsAreFclcertsReadingOfFis(@TempDir Path dir) throws Exception {
        OctaveFltIutTest.octave();
        double[] x = points();
        String text = fis(FIS_TERMS);
        List<String[]> all = new ArrayList<>(FIS_TERMS);
        all.addAll(FIS_REFUSED);
        Path file = dir.resolve("shapes.fis");
        Files.writeString(file, fis(all), StandardCharsets.UTF_8);
        double[][] theirs = octave(file, all.size(), x, dir);
        // what fclcert refuses, Octave computes by the formula 1 / (1 + |(x − c)/a|^(2b)) (gbellmf.m)
        Analysis refused = Analysis.analyze(new FisReader(), "refused.fis", fis(FIS_REFUSED));
        assertEquals(List.of("t1", "t2"), refused.diagnostics().stream().filter(d -> d.code().equals("FCL-C041"))
                .map(d -> d.message().replaceAll("^term '([^']*)'.*", "$1")).toList(), refused.diagnostics().toString());
        for (int r = 0; r < FIS_REFUSED.size(); r++) {
            String[] p = FIS_REFUSED.get(r)[1].split(" ");
            double a = Double.parseDouble(p[0]);
            double b = Double.parseDouble(p[1]);
            double c0 = Double.parseDouble(p[2]);
            for (int i = 0; i < x.length; i++) {
                assertEquals(1 / (1 + Math.pow(Math.abs((x[i] - c0) / a), 2 * b)), theirs[FIS_TERMS.size() + r][i],
                        1e-12);
            }
        }
        double[][] ours = fclcert(new FisReader(), "shapes.fis", text, FIS_TERMS.size(), x);
        // dsigmf.m of the toolkit 0.4.6 bounds f1 − f2 to [0, 1] (max (0, min (1, ...)), as its help says); fclcert
        // reads dsigmf as fuzzylite does, SigmoidDifference = |f1 − f2| (pyfuzzylite 8 term.py, fuzzylite 6 the same).
        // With 2 2 0.5 −2 the second sigmoid (inflection −2, gentle) exceeds the first (inflection 2, steep) below
        // x = 10/3, by up to 0.73: there Octave gives 0, fuzzylite and fclcert f2 − f1; above, both f1 − f2 ≤ 0.031.
        // (3 −4 1.5 5 too, below x = −13, by less than 4e-13.)
        Map<String, Expected> deviations = new LinkedHashMap<>();
        for (String[] t : FIS_TERMS) {
            if (t[0].equals("dsigmf")) {
                double[] q = java.util.Arrays.stream(t[1].split(" ")).mapToDouble(Double::parseDouble).toArray();
                deviations.put(t[0] + " " + t[1], (u, f) -> Math.max(0, Math.min(1, sigmoid(u, q[0], q[1])
                        - sigmoid(u, q[2], q[3]))));
            }
        }
        Compared c = compare(FIS_TERMS, theirs, ours, x, "Octave", deviations);
        // the deviation is real: at −2, f1 = 1/(1 + e^8), f2 = 1/2: fclcert 0.49966, Octave 0
        int at = java.util.Arrays.binarySearch(x, -2.0);
        int ds = 0;
        while (!(FIS_TERMS.get(ds)[0] + " " + FIS_TERMS.get(ds)[1]).equals("dsigmf 2 2 0.5 -2")) {
            ds++;
        }
        assertEquals(0.5 - 1 / (1 + Math.exp(8)), ours[ds][at], 1e-12);
        assertEquals(0.0, theirs[ds][at]);
        // and fclcert's reader says so (FCL-W316) for that term only: 3 -4 1.5 5 differs by less than 1e-9
        List<String> said = Analysis.analyze(new FisReader(), "shapes.fis", text).diagnostics().stream()
                .filter(d -> d.code().equals("FCL-W316")).map(d -> d.message()).toList();
        assertEquals(1, said.size(), said.toString());
        assertTrue(said.get(0).startsWith("dsigmf 't" + (ds + 1) + "' of 'x' is read as fuzzylite reads it: where its"
                + " second sigmoid exceeds its first (by up to 0.730 at 0.4"), said.toString());
        // fclcert's FIS writer, on the program read, gives Octave the same functions (FisWriter's order is the reader's)
        Path again = dir.resolve("written.fis");
        Files.writeString(again, written(new FisReader(), text, Dialect.FIS), StandardCharsets.UTF_8);
        Compared w = compare(FIS_TERMS, octave(again, FIS_TERMS.size(), x, dir), ours, x, "Octave (written)", deviations);
        assertEquals(FIS_TERMS.size() * x.length, w.points());
        System.out.println("Octave evalmf: " + FIS_TERMS.size() + " membership functions, " + c.points()
                + " points, largest difference " + c.max() + " (dsigmf against Octave's clamped formula), written by FisWriter "
                + w.max() + " " + c.worst());
        assertEquals(FIS_TERMS.size() * x.length, c.points());
    }

    @Test
    void pyfuzzylitesTermsAreFclcertsReadingOfFll(@TempDir Path dir) throws Exception {
        Pyfuzzylite.assumeInstalled();
        Path python = PyfuzzyliteIut.defaultPython().orElseThrow();
        double[] x = points();
        String text = fll(FLL_TERMS);
        Path file = dir.resolve("shapes.fll");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        double[][] theirs = pyfuzzylite(python, file, FLL_TERMS.size(), x, dir);
        double[][] ours = fclcert(new FllReader(), "shapes.fll", text, FLL_TERMS.size(), x);
        Compared c = compare(FLL_TERMS, theirs, ours, x, "pyfuzzylite", Map.of());
        // fclcert's FLL writer, on the program read, gives pyfuzzylite the same terms
        Path again = dir.resolve("written.fll");
        Files.writeString(again, written(new FllReader(), text, Dialect.FLL), StandardCharsets.UTF_8);
        Compared w = compare(FLL_TERMS, pyfuzzylite(python, again, FLL_TERMS.size(), x, dir), ours, x,
                "pyfuzzylite (written)", Map.of());
        assertEquals(FLL_TERMS.size() * x.length, w.points());
        System.out.println("pyfuzzylite membership: " + FLL_TERMS.size() + " terms, " + c.points()
                + " points, largest difference " + c.max() + ", written by FllWriter " + w.max() + " " + c.worst());
        assertEquals(FLL_TERMS.size() * x.length, c.points());
    }
    /** pyfuzzylite's membership of each term of input x of the FLL file, at each point: [term][point]. */
    private static double[][] pyfuzzylite(Path python, Path fll, int terms, double[] x, Path dir) throws Exception {
        Path script = dir.resolve("shapes.py");
        Files.writeString(script, "import sys\nimport fuzzylite as fl\n"
                + "engine = fl.FllImporter().from_string(open(sys.argv[1]).read())\n"
                + "xs = [float(v) for v in '" + list(x) + "'.split()]\n"
                + "for t in engine.input_variable('x').terms:\n"
                + "    print(' '.join(repr(float(t.membership(v))) for v in xs))\n", StandardCharsets.UTF_8);
        return run(List.of(python.toString(), script.toString(), fll.toString()), terms, x.length);
    }

    /** fuzzylite's own FIS functions, beyond MATLAB's (its FisImporter's names; Octave has none of them). */
    private static final List<String[]> FUZZYLITE_FIS_TERMS = List.of(
            new String[] {"rampmf", "-4 6"}, new String[] {"rampmf", "5 -3"}, new String[] {"rectmf", "-3 4"},
            new String[] {"concavemf", "1 6"}, new String[] {"concavemf", "4 -2"},
            new String[] {"cosinemf", "2 7"}, new String[] {"cosinemf", "-5 3"},
            new String[] {"spikemf", "1 4"}, new String[] {"spikemf", "-2 0.5"},
            new String[] {"discretemf", "-10 0 -2 1 5 0.3 12 0"});

    /**
     * fuzzylite 6.0's own reading of FIS (its FisImporter, through its command line, exporting FLL, whose terms
     * pyfuzzylite then evaluates) is fclcert's: every MATLAB function above and fuzzylite's additions, dsigmf
     * included (|f1 − f2| on both sides). Parameters have at most three decimals, which fuzzylite's FLL keeps.
     */
    @Test
    void fuzzylitesReadingOfFisIsFclcerts(@TempDir Path dir) throws Exception {
        Path binary = Path.of("/usr/bin/fuzzylite");
        if (!Files.isExecutable(binary)) {
            if (System.getenv("CI") != null) {
                fail("CI is set but fuzzylite is not installed (scripts/ensure-fuzzylite installs it)");
            }
            assumeTrue(false, "fuzzylite is not installed (scripts/ensure-fuzzylite)");
        }
        Pyfuzzylite.assumeInstalled();
        Path python = PyfuzzyliteIut.defaultPython().orElseThrow();
        List<String[]> terms = new ArrayList<>(FIS_TERMS);
        terms.addAll(FUZZYLITE_FIS_TERMS);
        double[] x = points();
        String text = fis(terms);
        Path file = dir.resolve("shapes.fis");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        Path fll = dir.resolve("shapes.fll");
        Process p = new ProcessBuilder(binary.toString(), "-i", file.toString(), "-if", "fis", "-o", fll.toString(),
                "-of", "fll").redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(Path.of("/dev/null")
                .toFile())).start();
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "fuzzylite did not end");
        assertTrue(Files.isRegularFile(fll), said);
        double[][] theirs = pyfuzzylite(python, fll, terms.size(), x, dir);
        double[][] ours = fclcert(new FisReader(), "shapes.fis", text, terms.size(), x);
        Compared c = compare(terms, theirs, ours, x, "fuzzylite FIS", Map.of());
        System.out.println("fuzzylite 6 FisImporter + pyfuzzylite membership: " + terms.size() + " FIS functions, "
                + c.points() + " points, largest difference " + c.max() + " " + c.worst());
        assertEquals(terms.size() * x.length, c.points());
    }
    /** Octave's evalmf of each membership function of input 1 of the FIS file as readfis reads it: [term][point]. */
    private static double[][] octave(Path fis, int terms, double[] x, Path dir) throws Exception {
        Path script = dir.resolve("shapes.m");
        Files.writeString(script, "pkg load fuzzy-logic-toolkit\nfis = readfis('" + fis + "');\nx = [" + list(x)
                + "];\nfor k = 1:numel(fis.input(1).mf)\n  mf = fis.input(1).mf(k);\n"
                + "  printf('%.17g ', evalmf(x, mf.params, mf.type)); printf('\\n');\nend\n", StandardCharsets.UTF_8);
        return run(List.of("octave-cli", "-q", "--no-gui", script.toString()), terms, x.length);
    }

    /** What fclcert's writer for the dialect writes of the program fclcert reads from the text. */
    private static String written(FclReader reader, String text, Dialect to) {
        Program program = Analysis.analyze(reader, "shapes", text).program().orElseThrow();
        return DialectWriters.writer(to).write(program).text();
    }
}
