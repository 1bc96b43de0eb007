package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.junit.jupiter.api.Test;

/**
 * The vertex arrays of {@link SetBuilder} are reused between evaluations; after a build the two degrees past the
 * last vertex are 0, so a read just past the set never sees a vertex of an earlier, larger set (issue 25).
 */
class SetBuilderTailTest {
    @Test
    void aSmallerSetAfterALargerOneEndsInZeroDegrees() {
        Shape small = new Shape(false, new double[] {0, 20, 40}, new int[] {-1, -1, -1},
                new double[] {0, 1, 0}, new int[] {-1, -1, -1});
        Shape medium = new Shape(false, new double[] {30, 50, 70}, new int[] {-1, -1, -1},
                new double[] {0, 1, 0}, new int[] {-1, -1, -1});
        Shape[] shapes = {small, medium};
        double[][] x = {small.sortedX, medium.sortedX};
        double[][] y = {small.sortedY, medium.sortedY};
        SetBuilder set = new SetBuilder();
        // by hand: 'small' clipped at 0.6 and 'medium' at 0.2 under MAX: (0,0) (12,.6) (28,.6) (30,.5) (34,.3)
        // (36,.2) (66,.2) (70,0) (100,0): the crossings at 12, 28, 34, 66, the envelope's corner at 36
        set.act.add(0, 0.6, 1.0, ActivationMethod.MIN);
        set.act.add(1, 0.2, 1.0, ActivationMethod.MIN);
        set.build(AccumulationMethod.MAX, 0, 100, x, y, shapes);
        assertEquals(9, set.np);
        assertArrayEquals(new double[] {0, 0.6, 0.6, 0.5, 0.3, 0.2, 0.2, 0, 0}, Arrays.copyOf(set.py, 9), 1e-15);
        assertEquals(0.0, set.py[9]);
        assertEquals(0.0, set.py[10]);
        // then 'medium' alone, scaled by PROD at 0.5: (0,0) (30,0) (50,.5) (70,0) (100,0); the earlier set's
        // degrees 0.2 at indices 5 and 6 are overwritten by 0
        set.act.clear();
        set.act.add(1, 0.5, 1.0, ActivationMethod.PROD);
        set.build(AccumulationMethod.MAX, 0, 100, x, y, shapes);
        assertEquals(5, set.np);
        assertArrayEquals(new double[] {0, 0, 0.5, 0, 0}, Arrays.copyOf(set.py, 5), 1e-15);
        assertEquals(0.0, set.py[5]);
        assertEquals(0.0, set.py[6]);
        // nothing added: no vertex, and the first two degrees are 0
        set.act.clear();
        set.build(AccumulationMethod.MAX, 0, 100, x, y, shapes);
        assertEquals(0, set.np);
        assertTrue(set.py[0] == 0 && set.py[1] == 0);
    }
}
