package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.DefuzzificationMethod;
import org.junit.jupiter.api.Test;

/**
 * The chain construction ({@link TermChain}, {@link SetBuilder#buildChain}) builds the function the general
 * construction builds: on random chains of terms (triangles, trapezoids, unimodal terms of up to six points,
 * shoulders at the ends, a range cutting the outer terms or not, levels and weights random and at the terms'
 * own degrees, MIN and PROD mixed) both sets are compared at every vertex of either, and their areas and centres
 * of gravity; and layouts that are not chains are refused.
 */
class TermChainTest {
    @Test
    void theChainBuildsTheGeneralConstructionsSet() {
        Random rnd = new Random(20261206);
        int chains = 0;
        int built = 0;
        int overlaps = 0;
        for (int trial = 0; trial < 20_000; trial++) {
            int m = 1 + rnd.nextInt(5);
            List<double[][]> terms = chain(rnd, m);
            Shape[] shapes = new Shape[m];
            double[][] x = new double[m][];
            double[][] y = new double[m][];
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int t = 0; t < m; t++) {
                double[][] p = terms.get(t);
                int[] none = new int[p[0].length];
                java.util.Arrays.fill(none, -1);
                shapes[t] = new Shape(false, p[0], none, p[1], none);
                x[t] = shapes[t].sortedX;
                y[t] = shapes[t].sortedY;
                min = Math.min(min, x[t][0]);
                max = Math.max(max, x[t][x[t].length - 1]);
            }
            TermChain chain = TermChain.of(output(m), shapes);
            StringBuilder desc = new StringBuilder();
            for (double[][] p : terms) {
                desc.append(java.util.Arrays.toString(p[0])).append(java.util.Arrays.toString(p[1])).append(' ');
            }
            assertNotNull(chain, "trial " + trial + ": a chain by construction: " + desc);
            chains++;
            double w = max - min;
            double lo = rnd.nextBoolean() ? min - rnd.nextInt(3) : min + w * rnd.nextDouble() * 0.3;
            double hi = rnd.nextBoolean() ? max + rnd.nextInt(3) : max - w * rnd.nextDouble() * 0.3;
            SetBuilder general = new SetBuilder();
            SetBuilder chained = new SetBuilder();
            for (int t = 0; t < m; t++) {
                if (rnd.nextInt(4) == 0) {
                    continue;
                }
                double level = rnd.nextInt(3) == 0 ? y[t][rnd.nextInt(y[t].length)] : rnd.nextInt(3) == 0 ? 1.0
                        : rnd.nextDouble();
                if (!(level > 0)) {
                    level = 0.5;
                }
                double weight = rnd.nextInt(3) == 0 ? rnd.nextDouble() * 0.9 + 0.1 : 1.0;
                ActivationMethod act = rnd.nextInt(4) == 0 ? ActivationMethod.PROD : ActivationMethod.MIN;
                general.act.add(t, level, weight, act);
                chained.act.add(t, level, weight, act);
            }
            general.build(AccumulationMethod.MAX, lo, hi, x, y, shapes);
            assertTrue(chained.buildChain(chain, lo, hi, x, y), "trial " + trial);
            built++;
            double tol = 1e-12;
            final int at = trial;
            for (SetBuilder s : new SetBuilder[] {general, chained}) {
                for (int j = 0; j < s.np; j++) {
                    double u = s.px[j];
                    assertEquals(Pwl.degree(general.px, general.py, general.np, u),
                            Pwl.degree(chained.px, chained.py, chained.np, u), tol, () -> "trial " + at + " at " + u
                            + ": " + desc + "\nlevels " + describe(general.act) + " range " + lo + ".." + hi
                            + "\ngeneral " + vertices(general) + "\nchained " + vertices(chained));
                }
            }
            for (int j = 1; j < chained.np; j++) {
                assertTrue(chained.px[j] >= chained.px[j - 1], "trial " + trial + ": vertices in order");
            }
            if (chained.np < general.np) {
                overlaps++;
            }
            double[] area = new double[1];
            double[] areaGeneral = new double[1];
            double cog = Defuzzifier.centreOfGravity(chained.px, chained.py, chained.np, area);
            double cogGeneral = Defuzzifier.centreOfGravity(general.px, general.py, general.np, areaGeneral);
            assertEquals(areaGeneral[0], area[0], 1e-12 * (hi - lo), "trial " + trial);
            if (areaGeneral[0] > 1e-9 * (hi - lo)) {
                assertEquals(cogGeneral, cog, 1e-9 * Math.max(1, Math.abs(hi) + Math.abs(lo)), "trial " + trial);
            }
            if (general.np > 0) {
                assertEquals(general.px[0], chained.px[0], "trial " + trial + ": from the range's start");
                assertEquals(general.px[general.np - 1], chained.px[chained.np - 1], "trial " + trial + ": to its end");
            }
        }
        assertEquals(20_000, chains);
        assertEquals(20_000, built);
        assertTrue(overlaps > 5_000, "the chain leaves out vertices on most sets: " + overlaps);
    }

    @Test
    void threeRuleCogByHand() {
        // the benchmark's output (PeerPrograms.cog3Standard): small clipped at 0.6, medium at 0.4 over 0..100.
        // small: area 40·0.6 − 20·0.36 = 16.8, moment 20·16.8 = 336 (symmetric about 20); medium: 40·0.4 − 20·0.16
        // = 12.8, moment 50·12.8 = 640. Overlap on [30, 40]: small falls (40 − u)/20, medium rises (u − 30)/20, both
        // below their levels there until u = 38 (medium reaches 0.4) — they cross at u = 35, degree 0.25; the
        // lower of the two there is the triangle (30, 0) (35, 0.25) (40, 0): area 1.25, moment 35·1.25 = 43.75.
        // CoG = (336 + 640 − 43.75) / (16.8 + 12.8 − 1.25) = 932.25 / 28.35.
        Shape[] shapes = {
            shape(new double[] {0, 20, 40}, new double[] {0, 1, 0}),
            shape(new double[] {30, 50, 70}, new double[] {0, 1, 0}),
            shape(new double[] {60, 80, 100}, new double[] {0, 1, 0})};
        double[][] x = {shapes[0].sortedX, shapes[1].sortedX, shapes[2].sortedX};
        double[][] y = {shapes[0].sortedY, shapes[1].sortedY, shapes[2].sortedY};
        TermChain chain = TermChain.of(output(3), shapes);
        SetBuilder s = new SetBuilder();
        s.act.add(1, 0.4, 1.0, ActivationMethod.MIN);
        s.act.add(0, 0.6, 1.0, ActivationMethod.MIN);
        assertTrue(s.buildChain(chain, 0, 100, x, y));
        double[] want = {0, 0, 12, 0.6, 28, 0.6, 35, 0.25, 38, 0.4, 62, 0.4, 70, 0, 100, 0};
        assertEquals(want.length / 2, s.np);
        for (int j = 0; j < s.np; j++) {
            assertEquals(want[2 * j], s.px[j], 1e-12, "u of vertex " + j);
            assertEquals(want[2 * j + 1], s.py[j], 1e-15, "degree of vertex " + j);
        }
        assertEquals(932.25 / 28.35, Defuzzifier.centreOfGravity(s.px, s.py, s.np), 1e-12);
    }

    @Test
    void aStepWithNothingFiredAfterOneWithASetHasNoArea() {
        Shape[] shapes = {shape(new double[] {0, 5, 10}, new double[] {0, 1, 0})};
        double[][] x = {shapes[0].sortedX};
        double[][] y = {shapes[0].sortedY};
        TermChain chain = TermChain.of(output(1), shapes);
        SetBuilder s = new SetBuilder();
        s.act.add(0, 0.5, 1.0, ActivationMethod.MIN);
        assertTrue(s.buildChain(chain, 0, 10, x, y));
        double[] area = new double[1];
        assertEquals(5.0, Defuzzifier.centreOfGravity(s.px, s.py, s.np, area), 1e-12);
        assertEquals(3.75, area[0], 1e-12);
        s.act.clear();
        assertTrue(s.buildChain(chain, 0, 10, x, y));
        assertEquals(0, s.np);
        assertTrue(Double.isNaN(Defuzzifier.centreOfGravity(s.px, s.py, s.np, area)), "no set, no centre (DEFAULT applies)");
        assertEquals(0.0, area[0]);
    }

    @Test
    void layoutsThatAreNotChainsAreRefused() {
        double[] z = {0, 1, 0};
        // three terms over one place
        assertNull(TermChain.of(output(3), new Shape[] {shape(new double[] {0, 5, 10}, z),
            shape(new double[] {2, 6, 12}, z), shape(new double[] {4, 8, 14}, z)}));
        // neighbours that overlap where the right one already falls
        assertNull(TermChain.of(output(2), new Shape[] {shape(new double[] {0, 5, 10}, z),
            shape(new double[] {1, 2, 9}, z)}));
        // a shoulder inside the chain
        assertNull(TermChain.of(output(2), new Shape[] {shape(new double[] {0, 5, 10}, z),
            shape(new double[] {8, 9}, new double[] {1, 0})}));
        // a term that falls and rises again
        assertNull(TermChain.of(output(1), new Shape[] {shape(new double[] {0, 1, 2, 3, 4},
            new double[] {0, 1, 0.2, 1, 0})}));
        // a jump
        assertNull(TermChain.of(output(1), new Shape[] {shape(new double[] {0, 1, 1, 3},
            new double[] {0, 0.5, 1, 0})}));
        // a partition is one
        assertNotNull(TermChain.of(output(3), new Shape[] {shape(new double[] {0, 5}, new double[] {1, 0}),
            shape(new double[] {0, 5, 10}, z), shape(new double[] {5, 10}, new double[] {0, 1})}));
    }

    @Test
    void twoContributionsOnOneTermAreLeftToTheGeneralConstruction() {
        Shape[] shapes = {shape(new double[] {0, 5, 10}, new double[] {0, 1, 0})};
        TermChain chain = TermChain.of(output(1), shapes);
        SetBuilder s = new SetBuilder();
        s.act.add(0, 0.4, 1.0, ActivationMethod.MIN);
        s.act.add(0, 0.6, 0.5, ActivationMethod.MIN);
        assertFalse(s.buildChain(chain, 0, 10, new double[][] {shapes[0].sortedX}, new double[][] {shapes[0].sortedY}));
        assertEquals(0, s.np);
    }

    private static String vertices(SetBuilder s) {
        StringBuilder b = new StringBuilder();
        for (int j = 0; j < s.np; j++) {
            b.append('(').append(s.px[j]).append(", ").append(s.py[j]).append(") ");
        }
        return b.toString();
    }

    private static String describe(Activations a) {
        StringBuilder b = new StringBuilder();
        for (int j = 0; j < a.n; j++) {
            b.append(a.shape[j]).append(':').append(a.level[j]).append('x').append(a.weight[j])
                    .append(a.prod[j] ? "P " : "M ");
        }
        return b.toString();
    }

    /** m terms in a chain: unimodal, each overlapping only its neighbours, on their slopes. */
    private static List<double[][]> chain(Random rnd, int m) {
        List<double[][]> out = new ArrayList<>();
        double at = rnd.nextInt(20) - 10;
        boolean coarse = rnd.nextBoolean();
        double prevEnd = Double.NEGATIVE_INFINITY;
        for (int t = 0; t < m; t++) {
            // rise from `start` to a top (one point or a plateau), fall to `end`
            boolean leftShoulder = t == 0 && rnd.nextInt(3) == 0;
            boolean rightShoulder = t == m - 1 && rnd.nextInt(3) == 0;
            double riseW = step(rnd, coarse);
            double topW = rnd.nextBoolean() && !(leftShoulder && rightShoulder) ? 0 : step(rnd, coarse);
            double fallW = step(rnd, coarse);
            double start = t == 0 ? at : Math.max(prevTop(out), prevEnd - riseW * rnd.nextDouble());
            if (t > 0 && rnd.nextInt(4) == 0) {
                start = prevEnd;       // touching, no overlap
            }
            if (coarse) {
                start = Math.ceil(start * 4) / 4;
            }
            double top = start + riseW;
            if (t > 0 && top < prevEnd) {
                top = prevEnd;
            }
            double top2 = top + topW;
            double end = top2 + fallW;
            double peak = rnd.nextInt(3) == 0 ? 0.25 + 0.75 * rnd.nextDouble() : 1.0;
            List<double[]> pts = new ArrayList<>();
            if (!leftShoulder) {
                pts.add(new double[] {start, 0});
                if (rnd.nextInt(3) == 0) {
                    pts.add(new double[] {(start + top) / 2, peak * rnd.nextDouble()});
                }
            }
            pts.add(new double[] {top, peak});
            if (top2 > top) {
                pts.add(new double[] {top2, peak});
            }
            if (!rightShoulder) {
                if (rnd.nextInt(3) == 0) {
                    pts.add(new double[] {(top2 + end) / 2, peak * rnd.nextDouble()});
                }
                pts.add(new double[] {end, 0});
            }
            double[][] p = new double[2][pts.size()];
            for (int i = 0; i < pts.size(); i++) {
                p[0][i] = pts.get(i)[0];
                p[1][i] = pts.get(i)[1];
            }
            out.add(p);
            prevEnd = end;
        }
        return out;
    }

    /** The x where the last term's top ends (its fall begins): a next term may start there at the earliest. */
    private static double prevTop(List<double[][]> out) {
        double[][] p = out.get(out.size() - 1);
        double[] y = p[1];
        int top = 0;
        for (int i = 0; i < y.length; i++) {
            if (y[i] >= y[top]) {
                top = i;
            }
        }
        return p[0][top];
    }

    private static double step(Random rnd, boolean coarse) {
        return coarse ? 0.25 * (1 + rnd.nextInt(12)) : 0.1 + 5 * rnd.nextDouble();
    }

    private static Shape shape(double[] x, double[] y) {
        int[] none = new int[x.length];
        java.util.Arrays.fill(none, -1);
        return new Shape(false, x, none, y, none);
    }

    private static OutputPlan output(int m) {
        int[] shapes = new int[m];
        for (int t = 0; t < m; t++) {
            shapes[t] = t;
        }
        return new OutputPlan("y", 0, DefuzzificationMethod.COG, false, true, 0, 1, shapes, new String[m], false, 0,
                AccumulationMethod.MAX, new int[0], new int[0], new boolean[0], 0, new ActivationMethod[0]);
    }
}
