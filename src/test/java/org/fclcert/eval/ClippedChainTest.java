package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.fclcert.check.Analysis;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/**
 * CoG over a chain of terms ({@link ClippedChain}) against the general sweep of the reference instance
 * ({@link FunctionBlockInstance}, {@link SetBuilder}): random fuzzy partitions of triangles, trapezoids and
 * shoulders whose neighbours overlap by random amounts (or touch, or leave gaps), cut by a random RANGE,
 * activated by MIN or PROD with a weight per term, on random inputs; the two agree to
 * {@link CompiledEvaluatorAgreementTest#AGREEMENT} of the interval's width, DEFAULT included. Also by hand:
 * the 3.5 case of the three-rule program, and what is not a chain.
 */
class ClippedChainTest {

    @Test
    void chainCogAgreesWithTheGeneralSweep() throws Exception {
        int chains = 0;
        int steps = 0;
        for (int p = 0; p < 400; p++) {
            Random rnd = new Random(17_2026L + p);
            String text = partition(rnd);
            Analysis a = Analysis.analyze(StrictReader.openLevel(), "chain" + p, text);
            LoadedProgram loaded = Evaluator.load(a.program().orElseThrow(() -> new AssertionError(a.diagnostics()
                    + "\n" + text)));
            CompiledEvaluator fast = loaded.newCompiledInstance();
            FunctionBlockInstance ref = loaded.newInstance();
            assertTrue(fast.usesChain(0), "not a chain:\n" + text);
            chains++;
            for (int s = 0; s < 25; s++) {
                double x1 = rnd.nextInt(4) == 0 ? rnd.nextInt(11) : rnd.nextDouble() * 10;
                double x2 = rnd.nextInt(4) == 0 ? rnd.nextInt(11) : rnd.nextDouble() * 10;
                fast.setInput(0, x1);
                fast.setInput(1, x2);
                fast.evaluate();
                ref.set("x1", x1);
                ref.set("x2", x2);
                ref.evaluate();
                double want = ref.get("y");
                double got = fast.output(0);
                assertTrue(Double.compare(want, got) == 0
                        || Math.abs(want - got) <= CompiledEvaluatorAgreementTest.AGREEMENT * 300,
                        "program " + p + " at (" + x1 + ", " + x2 + "): sweep " + want + ", chain " + got + "\n" + text);
                steps++;
            }
        }
        assertEquals(400, chains);
        assertEquals(400 * 25, steps);
    }

    @Test
    void twoHalfClippedTrianglesByHand() throws Exception {
        // the three-rule program at x = 3.5: small and medium both clipped at 1/2, overlapping on 30..40; the
        // overlap below both (the triangle 30-35-40 of height 1/4) counts once
        CompiledEvaluator fb = instance("""
                FUNCTION_BLOCK cog3
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM low := (0, 0) (2, 1) (5, 0); TERM mid := (2, 0) (5, 1) (8, 0);
                    TERM high := (5, 0) (8, 1) (10, 0); END_FUZZIFY
                DEFUZZIFY y TERM small := (0, 0) (20, 1) (40, 0); TERM medium := (30, 0) (50, 1) (70, 0);
                    TERM large := (60, 0) (80, 1) (100, 0); METHOD : CoG; DEFAULT := 0; RANGE := (0 .. 100);
                END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACT : MIN; ACCU : MAX;
                    RULE 1 : IF x IS low THEN y IS small; RULE 2 : IF x IS mid THEN y IS medium;
                    RULE 3 : IF x IS high THEN y IS large;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """);
        assertTrue(fb.usesChain(0));
        fb.setInput(0, 3.5);
        fb.evaluate();
        assertEquals((15 * 20 + 15 * 50 - 1.25 * 35) / (30 - 1.25), fb.output(0), 1e-13);
        fb.setInput(0, 11);      // nothing fires: DEFAULT
        fb.evaluate();
        assertEquals(0.0, fb.output(0), 0.0);
    }

    @Test
    void aClipLevelTooSmallToMoveTheFeetStillRisesAtThem() throws Exception {
        // found by fclcert fuzz: x = -109.999994 gives mu(x) = 6e-6/110, cubed by AND PROD, about 1.6e-22; the
        // clipped triangle is then a trapezoid over -50..63 whose top spans all but ~1e-20 of it, so its centre of
        // gravity is (-50 + 63) / 2 = 6.5 (by hand; the reference and the exact path agree). The chain's crossings
        // a + (b - a)L and d - (d - c)L round to the feet themselves; read as a ramp from (-50, 0) to (63, h) the
        // set gave (-50 + 2 * 63) / 3 = 25.33.
        CompiledEvaluator fb = instance("""
                FUNCTION_BLOCK tiny
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM t := (-110, 0) (0, 1); END_FUZZIFY
                DEFUZZIFY y TERM t := (-50, 0) (0, 1) (63, 0); METHOD : CoG; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r AND : PROD; ACCU : MAX;
                    RULE 1 : IF x IS t AND x IS t AND x IS t THEN y IS t;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """);
        assertTrue(fb.usesChain(0));
        fb.setInput(0, -109.999994);
        fb.evaluate();
        assertEquals(6.5, fb.output(0), 1e-12);
    }

    @Test
    void termsOverlappingBeyondTheirNeighbourAreNoChain() throws Exception {
        CompiledEvaluator fb = instance("""
                FUNCTION_BLOCK wide
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM a := (0, 0) (10, 1); TERM b := (0, 1) (10, 0); END_FUZZIFY
                DEFUZZIFY y TERM p := (0, 0) (10, 1) (90, 0); TERM q := (20, 0) (30, 1) (40, 0);
                    METHOD : CoG; DEFAULT := 0; RANGE := (0 .. 100);
                END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACT : MIN; ACCU : MAX;
                    RULE 1 : IF x IS a THEN y IS p; RULE 2 : IF x IS b THEN y IS q;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """);
        assertFalse(fb.usesChain(0), "q lies inside p's falling side: the general sweep, not the chain");
    }

    private static CompiledEvaluator instance(String text) throws Exception {
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "t", text);
        return Evaluator.load(a.program().orElseThrow(() -> new AssertionError(a.diagnostics()))).newCompiledInstance();
    }

    /** Two inputs with three triangles each; an output partition of 2 to 6 terms; every rule pair concludes. */
    private static String partition(Random rnd) {
        StringBuilder s = new StringBuilder("FUNCTION_BLOCK chain\nVAR_INPUT x1 : REAL; x2 : REAL; END_VAR\n"
                + "VAR_OUTPUT y : REAL; END_VAR\n");
        for (String x : new String[] {"x1", "x2"}) {
            s.append("FUZZIFY ").append(x).append(" TERM t0 := (0, 1) (4, 0); TERM t1 := (1, 0) (5, 1) (9, 0);"
                    + " TERM t2 := (6, 0) (10, 1); END_FUZZIFY\n");
        }
        int n = 2 + rnd.nextInt(5);
        s.append("DEFUZZIFY y\n");
        double end = 0;             // where the previous term reaches 0 again
        double peakEnd = 0;         // where it starts falling
        List<String> terms = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            double rise = 1 + rnd.nextInt(25);
            // start anywhere from where the previous one starts falling to a gap after it ends
            double a = t == 0 ? rnd.nextInt(30) - 10 : peakEnd + rnd.nextInt((int) (end - peakEnd) + 8);
            double b = Math.max(a + rise, end);              // rise to 1 no earlier than the previous has fallen
            double c = b + (rnd.nextInt(3) == 0 ? 1 + rnd.nextInt(10) : 0);
            double d = c + 1 + rnd.nextInt(25);
            StringBuilder pts = new StringBuilder();
            if (t == 0 && rnd.nextInt(4) == 0) {
                pts.append(pt(b, 1));                          // a left shoulder
            } else {
                pts.append(pt(a, 0)).append(' ').append(pt(b, 1));
            }
            if (c > b) {
                pts.append(' ').append(pt(c, 1));
            }
            if (!(t == n - 1 && rnd.nextInt(4) == 0)) {
                pts.append(' ').append(pt(d, 0));           // else a right shoulder
            }
            terms.add(pts.toString());
            peakEnd = c;
            end = d;
        }
        for (int t = n - 1; t >= 0; t--) {                  // declared in another order than the chain's
            s.append("  TERM o").append(t).append(" := ").append(terms.get(t)).append(";\n");
        }
        double lo = -20 + rnd.nextInt(40);
        s.append("  METHOD : CoG;\n  DEFAULT := -1;\n  RANGE := (").append((long) lo).append(" .. ")
                .append((long) (lo + 60 + rnd.nextInt(200))).append(");\nEND_DEFUZZIFY\n");
        s.append("RULEBLOCK r\n  AND : MIN;\n  ACT : ").append(rnd.nextBoolean() ? "MIN" : "PROD")
                .append(";\n  ACCU : MAX;\n");
        String[] w = new String[n];
        for (int t = 0; t < n; t++) {
            w[t] = rnd.nextInt(3) == 0 ? " WITH 0." + (1 + rnd.nextInt(9)) : "";
        }
        int r = 1;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                int o = (i + j + rnd.nextInt(2)) * (n - 1) / 5;
                s.append("  RULE ").append(r++).append(" : IF x1 IS t").append(i).append(" AND x2 IS t").append(j)
                        .append(" THEN y IS o").append(o).append(w[o]).append(";\n");
            }
        }
        for (int o = 0; o < n; o++) {       // every term concluded once at least (no unused-term warnings matter)
            s.append("  RULE ").append(r++).append(" : IF x1 IS t").append(o % 3).append(" AND x2 IS t")
                    .append((o + 1) % 3).append(" THEN y IS o").append(o).append(w[o]).append(";\n");
        }
        s.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        return s.toString();
    }

    private static String pt(double x, double y) {
        return "(" + (long) x + ", " + (long) y + ")";
    }
}
