package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.math.BigDecimal;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.OrAlgorithm;
import org.junit.jupiter.api.Test;

/**
 * NMIN and NMAX choose by whether x + y exceeds 1. With exact operands the filter decides that choice exactly
 * (Norms.sumAgainstOne), also where the double sum rounds to 1; it hands the evaluation to the exact path only
 * where the double's choice is the wrong one.
 */
class NilpotentBoundsTest {
    /** The sign of x + y - 1 in BigDecimal, which holds every double exactly: the independent check. */
    private static int exactly(double x, double y) {
        return new BigDecimal(x).add(new BigDecimal(y)).compareTo(BigDecimal.ONE);
    }

    @Test
    void theSumIsComparedWithOneExactly() {
        double justAboveHalf = 0.5 + 0x1.0p-53;    // a double; with 0.5 the sum is 1 + 2^-53, which rounds to 1
        double[][] pairs = {{0.25, 0.75}, {0.5, 0.5}, {0.1, 0.9}, {0.5, justAboveHalf}, {0.3, 0.7}, {0.2, 0.6},
            {0.75, 0.5}, {0, 1}, {1, 1}, {0, 0}, {0.6, 0.4}, {Math.nextDown(0.5), 0.5}};
        for (double[] p : pairs) {
            assertEquals(exactly(p[0], p[1]), Norms.sumAgainstOne(p[0], p[1]), p[0] + " + " + p[1]);
        }
        assertEquals(1.0, 0.5 + justAboveHalf, "the double sum rounds to 1");
        assertEquals(1, Norms.sumAgainstOne(0.5, justAboveHalf));
        assertEquals(1, Norms.sumAgainstOne(0.1, 0.9), "0.1 and 0.9 as doubles sum to 1 + 2.8e-17");
        assertEquals(-1, Norms.sumAgainstOne(Math.nextDown(0.5), 0.5));
    }

    @Test
    void exactOperandsDecideUnlessTheDoubleChoosesWrongly() {
        // exactly 1: NMIN gives 0 and NMAX gives 1, decided (bound 0)
        assertEquals(0.0, Norms.and(AndAlgorithm.NMIN, 0.25, 0.75));
        assertEquals(0.0, Norms.andError(AndAlgorithm.NMIN, 0.25, 0, 0.75, 0, 0.0));
        assertEquals(1.0, Norms.or(OrAlgorithm.NMAX, 0.25, 0.75));
        assertEquals(0.0, Norms.orError(OrAlgorithm.NMAX, 0.25, 0, 0.75, 0, 1.0));
        // an exact 0 beside a 1 (an accumulation's first contribution): NMAX(0, 1) = 1, decided
        assertEquals(0.0, Norms.orError(OrAlgorithm.NMAX, 0, 0, 1, 0, 1.0));
        // above and below 1 by far
        assertEquals(0.0, Norms.andError(AndAlgorithm.NMIN, 0.75, 0, 0.5, 0, 0.5));
        assertEquals(0.0, Norms.orError(OrAlgorithm.NMAX, 0.25, 0, 0.5, 0, 0.5));
        // the double sum rounds to 1 where the exact one exceeds it: the double's NMIN (0) is wrong (exactly 0.5),
        // so undecided; its NMAX (1) is right, since the exact sum is not below 1
        double a = 0.5 + 0x1.0p-53;
        assertEquals(0.0, Norms.and(AndAlgorithm.NMIN, 0.5, a));
        assertEquals(Double.POSITIVE_INFINITY, Norms.andError(AndAlgorithm.NMIN, 0.5, 0, a, 0, 0.0));
        assertEquals(0.0, Norms.orError(OrAlgorithm.NMAX, 0.5, 0, a, 0, 1.0));
        // an exact 0 or 1 beside a degree with a bound: NMIN(0, d) = 0, NMAX(0, d) = d, NMAX(1, d) = 1 for every
        // degree d, so the other operand's bound (or none) is the result's
        assertEquals(0.0, Norms.andError(AndAlgorithm.NMIN, 0, 0, 1.0, 1e-16, 0.0));
        assertEquals(1e-16, Norms.orError(OrAlgorithm.NMAX, 0, 0, 1.0, 1e-16, 1.0));
        assertEquals(3e-17, Norms.orError(OrAlgorithm.NMAX, 0.6, 3e-17, 0, 0, 0.6));
        assertEquals(0.0, Norms.orError(OrAlgorithm.NMAX, 0.4, 1e-16, 1, 0, 1.0));
        // operands with bounds keep the interval test: within R + their bounds of 1 is undecided
        assertEquals(Double.POSITIVE_INFINITY, Norms.andError(AndAlgorithm.NMIN, 0.25, 1e-17, 0.75, 0, 0.0));
        assertEquals(Double.POSITIVE_INFINITY, Norms.orError(OrAlgorithm.NMAX, 0.25, 0, 0.75, 1e-17, 1.0));
    }
}
