package org.fclcert.harness;

import org.fclcert.corpus.OutputScales;
import org.fclcert.corpus.Tolerance;

/** Tolerances for tests and simple uses. */
public final class Tolerances {
    private Tolerances() {
    }

    /** The corpus's exact class ({@link Tolerance#EXACT}): |error| ≤ 1e-9 · max(1, |expected|). */
    public static OutputTolerance exact() {
        return new CorpusTolerance(Tolerance.EXACT, OutputScales.none());
    }

    /** |error| ≤ bound, for every output. */
    public static OutputTolerance absolute(String name, double bound) {
        return new OutputTolerance() {
            @Override
            public String describe() {
                return name + " (±" + bound + ")";
            }

            @Override
            public double allowedError(String output, double expected) {
                return bound;
            }
        };
    }
}
