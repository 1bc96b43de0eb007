package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fclcert.check.Analysis;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/**
 * The generated code of a MIN/MAX block ({@link MinMaxKernel}) against the array loops of
 * {@link CompiledEvaluator} it replaces: on random Mamdani programs (triangles, trapezoids, ramps both ways,
 * shoulders, other points, singletons; IS NOT; weights; ACT MIN and PROD; CoG on chains and on other
 * terms, LM; singleton CoGS to REAL and INT outputs; DEFAULT and NC), one instance on each path, the same
 * steps: the same outputs bit for bit, and the same evaluation errors. Inputs run over and beyond the terms
 * and hit their points exactly, where the clamps and the ties decide.
 */
class MinMaxKernelTest {
    private static final int PROGRAMS = 300;
    private static final int STEPS = 60;

    @Test
    void generatedCodeComputesWhatTheArrayLoopsComputeBitForBit() throws Exception {
        int generated = 0;
        int compared = 0;
        for (int p = 0; p < PROGRAMS; p++) {
            Random rnd = new Random(61131_7L + p);
            String text = program(rnd);
            Analysis a = Analysis.analyze(StrictReader.openLevel(), "k" + p, text);
            Program program = a.program().orElseThrow(() -> new AssertionError(a.diagnostics() + "\n" + text));
            LoadedProgram loaded = Evaluator.load(program);
            CompiledEvaluator loops = loaded.newCompiledInstance();
            CompiledEvaluator code = loaded.newCompiledInstance();
            assertTrue(code.generateAtNextEvaluation(), "not a MIN/MAX block:\n" + text);
            for (int s = 0; s < STEPS; s++) {
                double[] in = {input(rnd), input(rnd), Math.rint(input(rnd))};
                String loopsError = step(loops, in);
                String codeError = step(code, in);
                assertEquals(loopsError, codeError, "program " + p + " step " + s + "\n" + text);
                for (int o = 0; o < loops.outputNames().size(); o++) {
                    double want = loops.output(o);
                    double got = code.output(o);
                    assertEquals(0, Double.compare(want, got), "program " + p + " step " + s + " output "
                            + loops.outputNames().get(o) + ": loops " + want + ", code " + got + "\n" + text);
                }
                compared++;
            }
            generated += code.generated() ? 1 : 0;
        }
        assertEquals(PROGRAMS, generated, "every program ran on its generated code");
        assertEquals(PROGRAMS * STEPS, compared);
    }

    @Test
    void aBlockTooLargeForTheJitGetsCompactCodeOrNone() throws Exception {
        // 3 000 rules of three operands: over the JIT's method size in either form, so the loops evaluate it
        StringBuilder rules = new StringBuilder();
        for (int r = 0; r < 3000; r++) {
            rules.append("RULE ").append(r).append(" : IF a IS t").append(r % 3).append(" AND b IS t").append(r % 2)
                    .append(" AND a IS NOT t").append((r + 1) % 3).append(" THEN y IS s").append(r % 3).append(";\n");
        }
        CompiledEvaluator big = instance(header() + rules + "END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        assertTrue(big.generateAtNextEvaluation());
        step(big, new double[] {2, 7, 0});
        assertTrue(!big.generated(), "3 000 rules fit no method the JIT compiles");
        // 150 such rules fit only in the compact form (calls of Math.min/max): still generated, same results
        StringBuilder some = new StringBuilder();
        for (int r = 0; r < 150; r++) {
            some.append("RULE ").append(r).append(" : IF a IS t").append(r % 3).append(" AND b IS t").append(r % 2)
                    .append(" AND a IS NOT t").append((r + 1) % 3).append(" THEN y IS s").append(r % 3).append(";\n");
        }
        String text = header() + some + "END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
        CompiledEvaluator loops = instance(text);
        CompiledEvaluator code = instance(text);
        assertTrue(code.generateAtNextEvaluation());
        for (double a = -1; a <= 11; a += 0.25) {
            step(loops, new double[] {a, 10 - a, 0});
            step(code, new double[] {a, 10 - a, 0});
            assertEquals(0, Double.compare(loops.output(0), code.output(0)), "a = " + a);
        }
        assertTrue(code.generated());
    }

    private static String header() {
        return """
                FUNCTION_BLOCK big
                VAR_INPUT a : REAL; b : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY a TERM t0 := (0, 1) (5, 0); TERM t1 := (0, 0) (5, 1) (10, 0); TERM t2 := (5, 0) (10, 1);
                END_FUZZIFY
                FUZZIFY b TERM t0 := (0, 0) (10, 1); TERM t1 := (0, 1) (10, 0); END_FUZZIFY
                DEFUZZIFY y TERM s0 := 0; TERM s1 := 50; TERM s2 := 100; METHOD : CoGS; DEFAULT := -1;
                END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACCU : MAX;
                """;
    }

    private static CompiledEvaluator instance(String text) throws Exception {
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "big", text);
        return Evaluator.load(a.program().orElseThrow(() -> new AssertionError(a.diagnostics()))).newCompiledInstance();
    }

    private static String step(CompiledEvaluator fb, double[] in) {
        try {
            for (int i = 0; i < fb.inputNames().size(); i++) {
                fb.setInput(i, in[i]);
            }
            fb.evaluate();
            return null;
        } catch (EvaluationException e) {
            return e.code();
        }
    }

    private static double input(Random rnd) {
        // whole numbers hit term points exactly; the rest fall between them or beyond
        return rnd.nextInt(3) == 0 ? rnd.nextInt(14) - 2 : -2 + 14 * rnd.nextDouble();
    }

    /** A random MIN/MAX program: inputs x1, x2 (REAL), n (INT); outputs y (points), z (REAL), zi (INT). */
    static String program(Random rnd) {
        StringBuilder s = new StringBuilder("FUNCTION_BLOCK k\nVAR_INPUT x1 : REAL; x2 : REAL; n : INT; END_VAR\n"
                + "VAR_OUTPUT y : REAL; z : REAL; zi : INT; END_VAR\n");
        String[] inputs = {"x1", "x2", "n"};
        int[] termCount = new int[3];
        for (int i = 0; i < 3; i++) {
            termCount[i] = 2 + rnd.nextInt(3);
            s.append("FUZZIFY ").append(inputs[i]).append('\n');
            for (int t = 0; t < termCount[i]; t++) {
                s.append("  TERM t").append(t).append(" := ").append(inputTerm(rnd)).append(";\n");
            }
            s.append("END_FUZZIFY\n");
        }
        boolean chain = rnd.nextBoolean();
        int outTerms = 2 + rnd.nextInt(4);
        s.append("DEFUZZIFY y\n");
        double x = rnd.nextInt(20);
        for (int t = 0; t < outTerms; t++) {
            s.append("  TERM o").append(t).append(" := ");
            if (chain) {
                // a fuzzy partition: neighbours overlap, the earlier only falling, the later only rising there
                double w = 10 + rnd.nextInt(20);
                double flat = rnd.nextInt(3) == 0 ? rnd.nextInt(10) : 0;
                boolean shoulderLeft = t == 0 && rnd.nextInt(3) == 0;
                boolean shoulderRight = t == outTerms - 1 && rnd.nextInt(3) == 0;
                List<String> pts = new ArrayList<>();
                if (!shoulderLeft) {
                    pts.add(pt(x, 0));
                }
                pts.add(pt(x + w, 1));
                if (flat > 0) {
                    pts.add(pt(x + w + flat, 1));
                }
                if (!shoulderRight) {
                    pts.add(pt(x + w + flat + w, 0));
                }
                s.append(String.join(" ", pts));
                x += w + flat + rnd.nextInt((int) w + 1);   // the next starts at or before this one's end... or after
            } else {
                s.append(pt(x, 0)).append(' ').append(pt(x + 5 + rnd.nextInt(30), 1)).append(' ')
                        .append(pt(x + 40 + rnd.nextInt(30), rnd.nextInt(2) == 0 ? 0 : 0.5)).append(' ')
                        .append(pt(x + 75, 0));
                x += rnd.nextInt(15);
            }
            s.append(";\n");
        }
        String method = rnd.nextInt(4) == 0 ? "LM" : "CoG";
        s.append("  METHOD : ").append(method).append(";\n  DEFAULT := ").append(rnd.nextInt(4) == 0 ? "NC" : "-7")
                .append(";\n  RANGE := (").append(rnd.nextInt(15)).append(" .. ").append(100 + rnd.nextInt(60))
                .append(");\nEND_DEFUZZIFY\n");
        for (String out : new String[] {"z", "zi"}) {
            s.append("DEFUZZIFY ").append(out).append('\n');
            for (int t = 0; t < 3; t++) {
                s.append("  TERM s").append(t).append(" := ").append(num(Math.rint(rnd.nextDouble() * 200 - 100)))
                        .append(";\n");
            }
            s.append("  METHOD : CoGS;\n  DEFAULT := ").append(rnd.nextInt(3) == 0 ? "NC" : "3").append(";\n")
                    .append("END_DEFUZZIFY\n");
        }
        s.append("RULEBLOCK r\n  AND : MIN;\n  ACT : ").append(rnd.nextBoolean() ? "MIN" : "PROD")
                .append(";\n  ACCU : MAX;\n");
        int rules = 1 + rnd.nextInt(12);
        String[] outWeight = new String[outTerms];
        for (int o = 0; o < outTerms; o++) {
            outWeight[o] = weight(rnd);
        }
        boolean[][] used = new boolean[3][];
        for (int i = 0; i < 3; i++) {
            used[i] = new boolean[termCount[i]];
        }
        for (int r = 0; r < rules; r++) {
            s.append("  RULE ").append(r).append(" : IF ");
            int operands = 1 + rnd.nextInt(3);
            for (int k = 0; k < operands; k++) {
                int i = rnd.nextInt(3);
                int t = rnd.nextInt(termCount[i]);
                used[i][t] = true;
                s.append(k > 0 ? " AND " : "").append(inputs[i]).append(rnd.nextInt(5) == 0 ? " IS NOT t" : " IS t")
                        .append(t);
            }
            int o = rnd.nextInt(outTerms);
            s.append(" THEN y IS o").append(o).append(outWeight[o]);     // one weight per term: merged (ACCU MAX)
            if (r == 0 || rnd.nextBoolean()) {
                s.append(", z IS s").append(rnd.nextInt(3)).append(weight(rnd));
            }
            if (r == 0 || rnd.nextBoolean()) {
                s.append(", zi IS s").append(rnd.nextInt(3));
            }
            s.append(";\n");
        }
        s.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        return s.toString();
    }

    private static String weight(Random rnd) {
        return rnd.nextInt(3) == 0 ? " WITH " + new String[] {"0.5", "0.8", "0.25", "1.0"}[rnd.nextInt(4)] : "";
    }

    private static String inputTerm(Random rnd) {
        double a = rnd.nextInt(8);
        double b = a + 1 + rnd.nextInt(4);
        double c = b + rnd.nextInt(3);
        double d = c + 1 + rnd.nextInt(4);
        return switch (rnd.nextInt(7)) {
            case 0 -> pt(a, 0) + " " + pt(b, 1) + " " + pt(d, 0);                    // triangle
            case 1 -> pt(a, 0) + " " + pt(b, 1) + " " + pt(c + 1, 1) + " " + pt(d + 1, 0);   // trapezoid
            case 2 -> pt(a, 0) + " " + pt(b, 1);                                     // ramp up
            case 3 -> pt(a, 1) + " " + pt(b, 0);                                     // ramp down
            case 4 -> pt(a, 0) + " " + pt(b, 0.4) + " " + pt(d, 0.9);                // other points
            case 5 -> num(a);                                                        // singleton
            default -> pt(a - 1, 0) + " " + pt(a, 0) + " " + pt(b, 1) + " " + pt(c, 1);   // zeros, then ones
        };
    }

    private static String pt(double x, double y) {
        return "(" + num(x) + ", " + num(y) + ")";
    }

    private static String num(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%s", v);
    }
}
