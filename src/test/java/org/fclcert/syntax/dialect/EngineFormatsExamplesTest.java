package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Located;
import org.fclcert.model.Program;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;
import org.junit.jupiter.api.Test;

/**
 * Every {@code .fll} and {@code .fis} of the Debian fuzzylite package's examples (read where installed, never
 * copied): recognised by {@code --dialect auto} and read, or refused with a located error of the expected code;
 * each evaluating alike to its twins in the other formats — the same engine as fuzzylite's own exporter wrote it in
 * FLL, FIS and fuzzylite FCL (read by the fuzzylite dialect), so three texts of one engine cross-check the readers;
 * each whose conversion to standard FCL is exact evaluating alike to it; and fclcert's values against fuzzylite's
 * own outputs in the {@code .fld} files. Skipped outside CI when the package is absent; with CI set, its absence
 * fails.
 */
class EngineFormatsExamplesTest {
    private static final Path EXAMPLES = Path.of("/usr/share/doc/fuzzylite/examples");

    /** The files fclcert does not read, with the code of the located error that says why. */
    private static final Map<String, String> NOT_READ = Map.of(
            // lock-range on an input: fuzzylite clamps the input, which fclcert does not evaluate
            "hybrid/tipper.fll", "FCL-S308",
            // the chained FLL engines lose their chaining in FIS: rules with every input index 0
            "mamdani/Laundry.fis", "FCL-S308",
            "mamdani/SimpleDimmerChained.fis", "FCL-S308",
            "mamdani/SimpleDimmerInverse.fis", "FCL-S308");

    private static List<Path> files(String extension) throws IOException {
        if (!Files.isDirectory(EXAMPLES)) {
            if (System.getenv("CI") != null) {
                fail("CI is set but " + EXAMPLES + " is missing (scripts/ensure-fuzzylite installs the package)");
            }
            assumeTrue(false, EXAMPLES + " is missing: the fuzzylite package is not installed");
        }
        try (Stream<Path> s = Files.walk(EXAMPLES)) {
            return s.filter(p -> p.toString().endsWith(extension)).sorted().toList();
        }
    }

    private static String name(Path p) {
        return EXAMPLES.relativize(p).toString().replace('\\', '/');
    }

    private static Analysis readAuto(Path p, Dialect expected) throws IOException {
        String text = Files.readString(p);
        DialectReaders.Choice choice = DialectReaders.auto(text);
        assertFalse(choice.unsure(), () -> name(p) + ": " + choice.explanation());
        assertEquals(expected, choice.dialect(), () -> name(p) + ": " + choice.explanation());
        return Analysis.analyze(choice.reader(), name(p), text);
    }

    @Test
    void everyFileIsRecognisedAndEachReadsOrGetsALocatedReason() throws IOException {
        int fll = 0;
        int fis = 0;
        for (Path p : files(".fll")) {
            fll += readOrRefused(p, Dialect.FLL);
        }
        for (Path p : files(".fis")) {
            fis += readOrRefused(p, Dialect.FIS);
        }
        assertEquals(31 - 1, fll, "FLL files read");
        assertEquals(29 - 3, fis, "FIS files read");
    }

    private static int readOrRefused(Path p, Dialect d) throws IOException {
        Analysis a = readAuto(p, d);
        String expected = NOT_READ.get(name(p));
        if (expected == null) {
            assertTrue(a.program().isPresent(), () -> name(p) + ": " + a.diagnostics());
            return 1;
        }
        assertTrue(a.program().isEmpty(), name(p) + " was expected not to read");
        assertTrue(a.diagnostics().stream().anyMatch(x -> x.code().equals(expected) && x.location().line() > 0),
                () -> name(p) + ": " + a.diagnostics());
        return 0;
    }

    /** An interior grid over each input's RANGE: n points per input, at most 400 in all. */
    private static List<double[]> grid(FunctionBlock fb) {
        List<Variable> inputs = fb.variables(VariableKind.INPUT);
        int n = inputs.size() == 1 ? 41 : inputs.size() == 2 ? 13 : 5;
        List<double[]> rows = new ArrayList<>();
        rows.add(new double[0]);
        for (Variable v : inputs) {
            Fuzzification f = fb.fuzzifications().stream().filter(x -> x.variable().equals(v.name())).findFirst()
                    .orElseThrow();
            double lo = f.declaredRange().orElseThrow().min().value();
            double hi = f.declaredRange().orElseThrow().max().value();
            List<double[]> next = new ArrayList<>();
            for (double[] r : rows) {
                for (int i = 0; i < n; i++) {
                    double[] m = java.util.Arrays.copyOf(r, r.length + 1);
                    m[r.length] = lo + (hi - lo) * (i + 0.5) / n;
                    next.add(m);
                }
            }
            rows = next;
        }
        return rows;
    }

    /** The outputs in declaration order, the inputs given in declaration order. */
    private static double[] evaluate(Program program, double[] inputs) throws EvaluationException {
        FunctionBlock fb = program.functionBlocks().get(0);
        FunctionBlockInstance x = Evaluator.load(program).newInstance();
        List<Variable> in = fb.variables(VariableKind.INPUT);
        for (int i = 0; i < inputs.length; i++) {
            x.set(in.get(i).name(), inputs[i]);
        }
        x.evaluate();
        Map<String, Double> out = x.outputs();
        return fb.variables(VariableKind.OUTPUT).stream().mapToDouble(v -> out.get(v.name())).toArray();
    }

    /** A number as fuzzylite writes it ({@code nan}, {@code inf}). */
    private static double number(String s) {
        return switch (s) {
            case "nan", "-nan" -> Double.NaN;
            case "inf" -> Double.POSITIVE_INFINITY;
            case "-inf" -> Double.NEGATIVE_INFINITY;
            default -> Double.parseDouble(s);
        };
    }

    /** Whether two values are equal, NaN equal to NaN. */
    private static boolean same(double a, double b, double tolerance) {
        return Double.isNaN(a) ? Double.isNaN(b) : !Double.isNaN(b) && Math.abs(a - b) <= tolerance;
    }

    @Test
    void theTwinsOfOneEngineEvaluateAlikeOnAGrid() throws Exception {
        int pairs = 0;
        int values = 0;
        List<String> sumTwins = new ArrayList<>();
        List<String> notTwins = new ArrayList<>();
        for (Path fll : files(".fll")) {
            Analysis a = readAuto(fll, Dialect.FLL);
            if (a.program().isEmpty()) {
                continue;
            }
            String stem = fll.toString().substring(0, fll.toString().length() - 4);
            for (String twin : List.of(".fcl", ".fis")) {
                Path other = Path.of(stem + twin);
                if (!Files.exists(other) || NOT_READ.containsKey(name(other))) {
                    continue;
                }
                Analysis b = readAuto(other, twin.equals(".fcl") ? Dialect.FUZZYLITE : Dialect.FIS);
                assertTrue(b.program().isPresent(), () -> name(other) + ": " + b.diagnostics());
                if (b.diagnostics().stream().anyMatch(x -> x.code().equals("FCL-W314")
                        && x.message().startsWith("AggMethod 'sum'"))) {
                    // MATLAB's 'sum' (read as Octave reads it) where fuzzylite's import wrote AlgebraicSum in the FLL
                    sumTwins.add(name(other));
                    continue;
                }
                if (b.program().get().functionBlocks().get(0).variables().size()
                        != a.program().get().functionBlocks().get(0).variables().size()) {
                    notTwins.add(name(other));          // another engine under the same name
                    continue;
                }
                pairs++;
                for (double[] row : grid(a.program().get().functionBlocks().get(0))) {
                    double[] x = evaluate(a.program().get(), row);
                    double[] y = evaluate(b.program().get(), row);
                    assertEquals(x.length, y.length, name(other));
                    for (int k = 0; k < x.length; k++) {
                        // fuzzylite's exporters write 3 decimals: the twins' parameters may differ in the 4th
                        double scale = Math.max(1, Math.abs(x[k]));
                        int kk = k;
                        assertTrue(same(x[k], y[k], 1e-9 * scale), () -> name(fll) + " vs " + name(other) + " output "
                                + kk + " at " + java.util.Arrays.toString(row) + ": " + x[kk] + " vs " + y[kk]);
                        values++;
                    }
                }
            }
        }
        System.out.println("FLL/FIS/FCL twins: " + pairs + " pairs, " + values + " values alike; left out for"
                + " FCL-W314: " + sumTwins + "; other engines of the same name: " + notTwins);
        assertEquals(List.of("original/mamdani/octave/mamdani_tip_calculator.fis"), sumTwins);
        assertEquals(List.of("original/tsukamoto/tsukamoto.fis"), notTwins);
        assertTrue(pairs >= 40, "pairs compared: " + pairs);
    }

    @Test
    void eachExactConversionEvaluatesAlikeOnAGrid() throws Exception {
        List<String> converted = new ArrayList<>();
        List<String> notConverted = new ArrayList<>();
        int values = 0;
        List<Path> all = new ArrayList<>(files(".fll"));
        all.addAll(files(".fis"));
        for (Path p : all) {
            Analysis a = readAuto(p, p.toString().endsWith(".fll") ? Dialect.FLL : Dialect.FIS);
            if (a.program().isEmpty()) {
                continue;
            }
            StandardConversion.Result r = new StandardConversion().convert(a.program().get());
            // fuzzylite's engines default to nan, which no standard DEFAULT expresses (written as 0): compared
            // where a rule fired
            boolean onlyNan = r.findings().stream().filter(f -> f.kind() instanceof StandardConversion.Kind.NotExpressible)
                    .allMatch(f -> f.construct().equals("O-DEFAULT-NAN"));
            if (!onlyNan) {
                notConverted.add(name(p));
                continue;
            }
            String text = new CanonicalWriter().write(r.program());
            Analysis back = Analysis.analyze(new StrictReader(), name(p), text);
            assertTrue(back.program().isPresent(), () -> name(p) + ": " + back.diagnostics() + "\n" + text);
            converted.add(name(p));
            for (double[] row : grid(a.program().get().functionBlocks().get(0))) {
                double[] x = evaluate(a.program().get(), row);
                double[] y = evaluate(back.program().get(), row);
                for (int k = 0; k < x.length; k++) {
                    if (!Double.isNaN(x[k])) {
                        // the same meaning evaluated from two texts: equal but for the last bits of a different order of operations
                        assertEquals(x[k], y[k], 4 * Math.ulp(Math.max(Math.abs(x[k]), 1.0)), name(p) + " output " + k + " at " + java.util.Arrays.toString(row));
                        values++;
                    }
                }
            }
        }
        System.out.println("FLL/FIS examples converting exactly (but for DEFAULT nan): " + converted + "; " + values
                + " values alike; not expressible in standard FCL: " + notConverted);
        assertTrue(converted.size() >= 10, "converted " + converted);
    }

    /**
     * fclcert's values of each FLL engine against fuzzylite's own in its {@code .fld} file (the engine's inputs and
     * outputs, 9 decimals). Weighted averages (COGS, COGSS: Takagi–Sugeno and Tsukamoto) are exact arithmetic in
     * fuzzylite too; CoG and the maxima fuzzylite samples (200 points in these engines), so they are compared to
     * a fraction of the output's range. Left out, each for a deviation of fuzzylite the reader warns about: FCL-W306
     * (COGS counted per rule), FCL-W310 (weights before activation), FCL-W311 (MM) and FCL-W312 (fuzzylite 6.0's
     * inverses).
     */
    @Test
    void fclcertAgreesWithFuzzylitesOwnOutputsWhereSamplingDoesNotApply() throws Exception {
        double exactWorst = 0;
        double sampledWorst = 0;
        String sampledWhere = "";
        String exactWhere = "";
        int exact = 0;
        int sampled = 0;
        int files = 0;
        for (Path fld : files(".fld")) {
            Path fll = Path.of(fld.toString().replaceAll("\\.fld$", ".fll"));
            Analysis a = readAuto(fll, Dialect.FLL);
            if (a.program().isEmpty()) {
                continue;
            }
            Program program = a.program().get();
            FunctionBlock fb = program.functionBlocks().get(0);
            List<Variable> outs = fb.variables(VariableKind.OUTPUT);
            int inputs = fb.variables(VariableKind.INPUT).size();
            List<String> lines = Files.readAllLines(fld);
            files++;
            for (int k = 0; k < outs.size(); k++) {
                String out = outs.get(k).name();
                Defuzzification d = fb.defuzzifications().stream().filter(x -> x.variable().equals(out)).findFirst()
                        .orElseThrow();
                boolean warned = a.diagnostics().stream().anyMatch(x -> List.of("FCL-W306", "FCL-W310", "FCL-W311",
                        "FCL-W312").contains(x.code()));
                if (warned) {
                    continue;
                }
                DefuzzificationMethod m = d.method().map(Located::value).orElse(DefuzzificationMethod.COG);
                boolean weighted = m == DefuzzificationMethod.COGS || m == DefuzzificationMethod.COGSS
                        || m == DefuzzificationMethod.TSUKAMOTO;
                double range = d.range().map(r -> r.max().value() - r.min().value()).orElse(1.0);
                for (int row = 1; row < lines.size(); row += 4) {
                    String[] w = lines.get(row).strip().split("\\s+");
                    double[] in = new double[inputs];
                    for (int i = 0; i < inputs; i++) {
                        in[i] = number(w[i]);
                    }
                    double theirs = number(w[inputs + k]);
                    double ours;
                    try {
                        ours = evaluate(program, in)[k];
                    } catch (EvaluationException e) {
                        ours = Double.NaN;           // sin(x)/x at 0 (FCL-V005): fuzzylite has nan there too
                    }
                    if (Double.isNaN(theirs) || Double.isNaN(ours)) {
                        // fuzzylite takes a degree below 1e-6 for none: NaN there may be a degree fclcert counts
                        continue;
                    }
                    double diff = Math.abs(theirs - ours);
                    if (weighted) {
                        exact++;
                        if (diff / Math.max(1, Math.abs(theirs)) > exactWorst) {
                            exactWorst = diff / Math.max(1, Math.abs(theirs));
                            exactWhere = name(fld) + " " + out + " at " + java.util.Arrays.toString(in) + ": fuzzylite "
                                    + theirs + ", fclcert " + ours;
                        }
                        assertTrue(diff <= 1e-6 * Math.max(1, Math.abs(theirs)), name(fld) + " " + out + " at "
                                + java.util.Arrays.toString(in) + ": fuzzylite " + theirs + ", fclcert " + ours);
                    } else {
                        sampled++;
                        if (diff / range > sampledWorst) {
                            sampledWorst = diff / range;
                            sampledWhere = name(fld) + " " + out + " at " + java.util.Arrays.toString(in) + ": fuzzylite "
                                    + theirs + ", fclcert " + ours;
                        }
                    }
                }
            }
        }
        System.out.println(".fld: " + files + " files; " + exact + " weighted-average values agree to "
                + exactWorst + " (relative, largest at " + exactWhere + "); " + sampled + " sampled values (CoG, CoA, LM, RM) within "
                + sampledWorst + " of the range, largest at " + sampledWhere);
        assertTrue(exact > 1000 && sampled > 1000, "compared " + exact + " and " + sampled);
        assertTrue(sampledWorst < 0.01, "sampled values within 1% of the range: " + sampledWorst + " at " + sampledWhere);
    }
}
