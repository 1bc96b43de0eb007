package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Fresh inputs are drawn inside the span also when the span is wider than the largest double. */
class FreshVectorsPickTest {
    @Test
    void aSpanWiderThanTheLargestDoubleGivesFinitePointsInsideIt() {
        SplittableRandom random = new SplittableRandom(25);
        boolean below = false;
        boolean above = false;
        for (int i = 0; i < 200; i++) {
            double x = FreshVectors.pick(new double[] {-1.0e308, 1.0e308}, random);
            assertTrue(Double.isFinite(x) && x >= -1.0e308 && x <= 1.0e308, "picked " + x);
            below |= x < 0;
            above |= x > 0;
        }
        assertTrue(below && above, "points on both sides of 0");
    }

    @Test
    void anOrdinarySpanIsSteppedInThousandths() {
        SplittableRandom random = new SplittableRandom(7);
        for (int i = 0; i < 200; i++) {
            double x = FreshVectors.pick(new double[] {0, 10}, random);
            assertTrue(x >= 0 && x <= 10, "picked " + x);
            assertEquals(Math.round(x * 100) / 100.0, x, 1e-12, "a multiple of 10/1000: " + x);
        }
    }
}
