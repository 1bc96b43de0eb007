package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;
import java.util.Random;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.junit.jupiter.api.Test;

/**
 * {@link SetBuilder}'s sweep (MAX over MIN or PROD activations) held to its general construction bit for bit, on
 * random sets: the agreement tests compare the kernel with the interpreter, which both take the sweep, so only a
 * comparison with the general construction ({@link SetBuilder#buildGeneral}) can see a difference. The sets are
 * drawn to sit on the construction's decision points: abscissas on a coarse grid (points of different terms at one
 * abscissa, vertical edges and jumps, touching supports), degrees and levels from {0, 1/4, 1/2, 3/4, 1} (a level
 * equal to a vertex degree, equal levels, levels 0 and 1) or random, terms that do not end at 0, intervals that cut
 * terms, PROD and MIN mixed, rule weights below 1, and -0.0 beside 0.0.
 */
class SetBuilderSweepTest {
    private static final double[] DEGREES = {0, 0.25, 0.5, 0.75, 1};

    @Test
    void theSweepEmitsExactlyTheVerticesOfTheGeneralConstruction() {
        Random r = new Random(20261204);
        SetBuilder sweep = new SetBuilder();
        SetBuilder general = new SetBuilder();
        int swept = 0;
        int cases = 200_000;
        for (int k = 0; k < cases; k++) {
            int terms = 1 + r.nextInt(5);
            Shape[] shapes = new Shape[terms];
            double[][] x = new double[terms][];
            double[][] y = new double[terms][];
            boolean grid = r.nextInt(4) != 0;
            for (int s = 0; s < terms; s++) {
                shapes[s] = randomTerm(r, grid);
                x[s] = shapes[s].sortedX;
                y[s] = shapes[s].sortedY;
            }
            double lo = grid ? r.nextInt(5) - 2 : r.nextDouble() * 4 - 2;
            double hi = lo + (r.nextInt(8) == 0 ? 0 : grid ? 1 + r.nextInt(12) : r.nextDouble() * 12);
            if (r.nextInt(50) == 0) {
                lo = -0.0;
            }
            sweep.act.clear();
            general.act.clear();
            int contributions = r.nextInt(6);
            for (int c = 0; c < contributions; c++) {
                int s = r.nextInt(terms);
                double level = r.nextInt(3) == 0 ? r.nextDouble() : DEGREES[r.nextInt(DEGREES.length)];
                double weight = r.nextInt(4) == 0 ? DEGREES[1 + r.nextInt(4)] : 1.0;
                ActivationMethod act = r.nextInt(3) == 0 ? ActivationMethod.PROD : ActivationMethod.MIN;
                sweep.act.add(s, level, weight, act);
                general.act.add(s, level, weight, act);
            }
            sweep.build(AccumulationMethod.MAX, lo, hi, x, y, shapes);
            general.buildGeneral(AccumulationMethod.MAX, lo, hi, x, y, shapes);
            if (sweep.swept) {
                swept++;
            }
            if (!sameVertices(sweep, general)) {
                fail("case " + k + ": the sweep gives " + vertices(sweep) + ", the general construction "
                        + vertices(general) + "; terms " + describe(x, y) + ", interval [" + lo + ", " + hi + "]");
            }
        }
        // nearly every case with a contribution and an interval takes the sweep (the rest: more than 32 breakpoints)
        assertTrue(swept > cases / 2, "the sweep was taken in " + swept + " of " + cases + " cases");
    }

    /** A case worked by hand, so the two constructions are not only equal to each other. */
    @Test
    void twoClippedTrianglesByHand() {
        Shape small = triangle(0, 20, 40);
        Shape medium = triangle(30, 50, 70);
        Shape[] shapes = {small, medium};
        double[][] x = {small.sortedX, medium.sortedX};
        double[][] y = {small.sortedY, medium.sortedY};
        SetBuilder set = new SetBuilder();
        // 'small' clipped at 0.6, 'medium' at 0.2: (0,0) (12,.6) (28,.6) (30,.5) (34,.3) (36,.2) (66,.2) (70,0)
        // (100,0): small's clip crossings at 12 and 28, medium's at 34 and 66, medium's foot at 30 (small is .5
        // there), and the envelope's corner at 36 where small's falling edge meets medium's plateau
        set.act.add(0, 0.6, 1.0, ActivationMethod.MIN);
        set.act.add(1, 0.2, 1.0, ActivationMethod.MIN);
        set.build(AccumulationMethod.MAX, 0, 100, x, y, shapes);
        assertTrue(set.swept);
        double[] wantX = {0, 12, 28, 30, 34, 36, 66, 70, 100};
        double[] wantY = {0, 0.6, 0.6, 0.5, 0.3, 0.2, 0.2, 0, 0};
        assertEquals(wantX.length, set.np, vertices(set));
        for (int i = 0; i < wantX.length; i++) {
            assertEquals(wantX[i], set.px[i], 1e-12, vertices(set));
            assertEquals(wantY[i], set.py[i], 1e-15, vertices(set));
        }
        // the corner: small's edge 1 - (u - 20)/20 = 0.2 at u = 36
        assertEquals(36.0, set.px[5], 1e-12);
    }

    private static Shape triangle(double a, double b, double c) {
        return new Shape(false, new double[] {a, b, c}, new int[] {-1, -1, -1}, new double[] {0, 1, 0},
                new int[] {-1, -1, -1});
    }

    private static Shape randomTerm(Random r, boolean grid) {
        int n = 1 + r.nextInt(5);
        double[] px = new double[n];
        double[] py = new double[n];
        double at = grid ? r.nextInt(6) - 3 : r.nextDouble() * 6 - 3;
        for (int i = 0; i < n; i++) {
            if (i > 0) {
                // a vertical edge (two points at one abscissa) one time in five
                at += r.nextInt(5) == 0 ? 0 : grid ? 1 + r.nextInt(3) : r.nextDouble() * 3;
            }
            px[i] = at == 0 && r.nextInt(4) == 0 ? -0.0 : at;
            py[i] = r.nextInt(4) == 0 ? r.nextDouble() : DEGREES[r.nextInt(DEGREES.length)];
        }
        if (n > 2 && r.nextBoolean()) {
            py[0] = 0;        // most terms end at 0, as triangles and trapezoids do
            py[n - 1] = 0;
        }
        int[] none = new int[n];
        Arrays.fill(none, -1);
        return new Shape(false, px, none, py, none);
    }

    private static boolean sameVertices(SetBuilder a, SetBuilder b) {
        if (a.np != b.np) {
            return false;
        }
        for (int i = 0; i < a.np + 2 && i < Math.min(a.py.length, b.py.length); i++) {
            if (i < a.np && Double.doubleToRawLongBits(a.px[i]) != Double.doubleToRawLongBits(b.px[i])) {
                return false;
            }
            if (Double.doubleToRawLongBits(a.py[i]) != Double.doubleToRawLongBits(b.py[i])) {
                return false;
            }
        }
        return true;
    }

    private static String vertices(SetBuilder s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.np; i++) {
            b.append('(').append(s.px[i]).append(", ").append(s.py[i]).append(") ");
        }
        return b.toString();
    }

    private static String describe(double[][] x, double[][] y) {
        StringBuilder b = new StringBuilder();
        for (int s = 0; s < x.length; s++) {
            b.append(s).append(':');
            for (int i = 0; i < x[s].length; i++) {
                b.append(" (").append(x[s][i]).append(", ").append(y[s][i]).append(')');
            }
            b.append("; ");
        }
        return b.toString();
    }
}
