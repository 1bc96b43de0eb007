package org.fclcert.model;

/**
 * {@code ACT:} algorithms: those of Table 4, and the other t-norms fuzzylite activates by (Open Level, Table 10,
 * O-ACT-OTHER-NORM), which the strict reader rejects. A rule of degree d activates a term μ as T(d, μ(u)), T the
 * t-norm of the AND algorithm of the same name ({@link #tNorm()}).
 */
public enum ActivationMethod {
    MIN,
    PROD,
    /** Bounded difference, max(0, d + μ − 1) (fuzzylite). */
    BDIF,
    /** Einstein product (fuzzylite). */
    EPROD,
    /** Hamacher product (fuzzylite). */
    HPROD,
    /** Drastic product (fuzzylite). */
    DPROD,
    /** Nilpotent minimum (fuzzylite). */
    NMIN;

    /** True for the methods of Table 4. */
    public boolean standard() {
        return this == MIN || this == PROD;
    }

    /** The t-norm: the AND algorithm of the same name. */
    public AndAlgorithm tNorm() {
        return AndAlgorithm.valueOf(name());
    }
}
