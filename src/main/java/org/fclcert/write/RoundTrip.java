package org.fclcert.write;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Program;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.DialectReaders;

/**
 * A written program read back with fclcert's reader of its dialect (and checked), and evaluated against the
 * original with the reference evaluator, both sides: on given steps (a corpus case's vectors) and on a grid
 * over every function block's inputs.
 *
 * @param written      what was written
 * @param readBack     the program read back, when the text read and passed the checks
 * @param diagnostics  the diagnostics of reading the text back (its errors say why it did not read)
 * @param comparisons  how many (step, output) pairs were compared
 * @param mismatches   the first {@value #SHOWN} disagreements
 * @param mismatchCount every disagreement
 * @param problems     what kept a comparison from being made (a block missing, an evaluation error), in words
 */
public record RoundTrip(Written written, Optional<Program> readBack, List<Diagnostic> diagnostics, int comparisons,
        List<Mismatch> mismatches, int mismatchCount, List<String> problems) {
    static final int SHOWN = 10;
    /** Relative tolerance of equal: written numbers read back bit for bit, but a reordered product may round once more. */
    public static final double TOLERANCE = 1e-9;

    public RoundTrip {
        diagnostics = List.copyOf(diagnostics);
        mismatches = List.copyOf(mismatches);
        problems = List.copyOf(problems);
    }

    /** True when the text read back and every comparison agreed. */
    public boolean equal() {
        return readBack.isPresent() && mismatchCount == 0 && problems.isEmpty();
    }

    /** One disagreement: an output at one step of one block. */
    public record Mismatch(String block, Map<String, Double> inputs, String output, double original, double written) {
        @Override
        public String toString() {
            StringBuilder at = new StringBuilder();
            inputs.forEach((k, v) -> at.append(at.isEmpty() ? "" : ", ").append(k).append('=').append(v));
            return "function block " + block + " at " + (at.isEmpty() ? "no inputs" : at) + ": " + output + " is "
                    + original + " in the original, " + written + " as written";
        }
    }

    /** One sentence for a report: equal on n comparisons, or the first reason it is not. */
    public String summary() {
        if (readBack.isEmpty()) {
            return "the written text does not read back: " + diagnostics.stream().filter(Diagnostic::isError)
                    .findFirst().map(Diagnostic::toString).orElse("(no diagnostic)");
        }
        if (!problems.isEmpty()) {
            return problems.get(0);
        }
        if (mismatchCount == 0) {
            return "read back and evaluated equal to the original on " + comparisons + " comparisons";
        }
        return mismatchCount + " of " + comparisons + " comparisons differ; first: " + mismatches.get(0);
    }

    /** Reads {@code written} back and compares it with {@code original} on the grid, then on {@code steps}. */
    static RoundTrip of(Program original, Written written, String block, List<Map<String, Double>> steps) {
        Analysis back = Analysis.analyze(DialectReaders.reader(written.dialect()), original.sourceName() + " (as "
                + written.dialect().cliName() + ")", written.text());
        if (back.hasErrors() || back.program().isEmpty()) {
            return new RoundTrip(written, Optional.empty(), back.diagnostics(), 0, List.of(), 0, List.of());
        }
        Program read = back.program().get();
        Comparer c = new Comparer();
        try {
            LoadedProgram a = Evaluator.load(original);
            LoadedProgram b = Evaluator.load(read);
            for (FunctionBlock fb : original.functionBlocks()) {
                if (!steps.isEmpty() && (block == null ? fb == original.functionBlocks().get(0)
                        : org.fclcert.model.Names.same(block, fb.name()))) {
                    c.run(a, b, fb, steps);
                }
                c.run(a, b, fb, grid(fb));
            }
        } catch (IllegalArgumentException e) {
            c.problems.add("the reference evaluator cannot load the program: " + e.getMessage());
        }
        return new RoundTrip(written, Optional.of(read), back.diagnostics(), c.comparisons, c.mismatches, c.count,
                c.problems);
    }

    private static final class Comparer {
        int comparisons;
        int count;
        final List<Mismatch> mismatches = new ArrayList<>();
        final List<String> problems = new ArrayList<>();

        void run(LoadedProgram a, LoadedProgram b, FunctionBlock fb, List<Map<String, Double>> steps) {
            try {
                FunctionBlockInstance x = a.newInstance(fb.name());
                FunctionBlockInstance y;
                try {
                    y = b.newInstance(fb.name());
                } catch (EvaluationException e) {
                    problems.add("function block " + fb.name() + " is missing from the written program");
                    return;
                }
                for (Map<String, Double> step : steps) {
                    for (Map.Entry<String, Double> in : step.entrySet()) {
                        x.set(in.getKey(), in.getValue());
                        y.set(in.getKey(), in.getValue());
                    }
                    String refusedX = EvaluationException.refusalOf(x::evaluate);
                    String refusedY = EvaluationException.refusalOf(y::evaluate);
                    if (refusedX != null || refusedY != null) {
                        // a step the program cannot evaluate (an output beyond its type: a corpus step that must be
                        // refused) is the same when both texts refuse it with the same code
                        comparisons++;
                        if (!java.util.Objects.equals(refusedX, refusedY)) {
                            problems.add("function block " + fb.name() + ", step " + step + ": the original "
                                    + (refusedX == null ? "evaluates it" : "refuses it with " + refusedX)
                                    + ", the written program " + (refusedY == null ? "evaluates it"
                                    : "refuses it with " + refusedY));
                            return;
                        }
                        continue;
                    }
                    for (String output : x.outputNames()) {
                        comparisons++;
                        double u = x.get(output);
                        double v = y.get(output);
                        if (!same(u, v)) {
                            if (count++ < SHOWN) {
                                mismatches.add(new Mismatch(fb.name(), step, output, u, v));
                            }
                        }
                    }
                }
            } catch (EvaluationException e) {
                problems.add("function block " + fb.name() + ": evaluation failed: " + e.getMessage());
            }
        }
    }

    static boolean same(double u, double v) {
        if (Double.isNaN(u) || Double.isNaN(v)) {
            return Double.isNaN(u) && Double.isNaN(v);
        }
        return u == v || Math.abs(u - v) <= TOLERANCE * Math.max(1, Math.max(Math.abs(u), Math.abs(v)));
    }

    /**
     * Input steps over every input's interval (its RANGE as a dialect declared it, else its terms' span) widened
     * by a tenth on each side: n points per input with n^k at most about 2000, at least 2 (a block of many inputs
     * gets 2000 points drawn with a fixed seed instead).
     */
    static List<Map<String, Double>> grid(FunctionBlock fb) {
        List<Variable> inputs = fb.variables(VariableKind.INPUT);
        BlockContext cx = new BlockContext(fb, new Findings(""));
        double[][] spans = new double[inputs.size()][];
        for (int k = 0; k < inputs.size(); k++) {
            Optional<Fuzzification> f = fb.fuzzification(inputs.get(k).name());
            double[] s = f.map(cx::inputSpan).orElse(new double[] {0, 1});
            double w = s[1] - s[0] > 0 ? s[1] - s[0] : 1;
            double[] span = Double.isFinite(w) ? new double[] {s[0] - w / 10, s[1] + w / 10}
                    // terms spanning most of the doubles (O-DEGREES-0-1-071): the width overflows, and the grid with it
                    : new double[] {s[0] - (s[1] / 2 - s[0] / 2) / 5, s[1] + (s[1] / 2 - s[0] / 2) / 5};
            // only values the input can hold (REAL's range, an integer type's): others are refused, not compared
            org.fclcert.model.DataType type = inputs.get(k).type();
            spans[k] = new double[] {Math.max(type.min(), span[0]), Math.min(type.max(), span[1])};
        }
        List<Map<String, Double>> steps = new ArrayList<>();
        int k = inputs.size();
        if (k == 0) {
            steps.add(Map.of());
            return steps;
        }
        int n = Math.max(2, Math.min(41, (int) Math.floor(Math.pow(2000, 1.0 / k) + 1e-9)));
        if (Math.pow(n, k) > 4096) {
            Random random = new Random(61131);
            for (int i = 0; i < 2000; i++) {
                Map<String, Double> step = new LinkedHashMap<>();
                for (int j = 0; j < k; j++) {
                    step.put(inputs.get(j).name(), at(spans[j], random.nextDouble(), 1));
                }
                steps.add(step);
            }
            return steps;
        }
        int[] index = new int[k];
        while (true) {
            Map<String, Double> step = new LinkedHashMap<>();
            for (int j = 0; j < k; j++) {
                step.put(inputs.get(j).name(), at(spans[j], index[j], n - 1));
            }
            steps.add(step);
            int j = 0;
            while (j < k && ++index[j] == n) {
                index[j++] = 0;
            }
            if (j == k) {
                return steps;
            }
        }
    }

    /**
     * The point num/den into the span: lo + (hi − lo)·num/den in that order (the grid's doubles as they always were),
     * or, where hi − lo overflows, lo·(1 − t) + hi·t.
     */
    private static double at(double[] span, double num, int den) {
        double w = span[1] - span[0];
        if (Double.isFinite(w)) {
            return span[0] + w * num / den;
        }
        double t = num / den;
        return span[0] * (1 - t) + span[1] * t;
    }
}
