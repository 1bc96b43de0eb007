package org.fclcert.harness;

/** Tolerances for tests and simple uses. */
public final class Tolerances {
    private Tolerances() {
    }

    /** |error| ≤ 1e-9 · max(1, |expected|). */
    public static OutputTolerance exact() {
        return new OutputTolerance() {
            @Override
            public String describe() {
                return "exact";
            }

            @Override
            public double allowedError(String output, double expected) {
                return 1e-9 * Math.max(1, Math.abs(expected));
            }
        };
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
