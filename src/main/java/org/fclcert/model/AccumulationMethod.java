package org.fclcert.model;

/**
 * {@code ACCU:} algorithms: those of Table 5, and the non-standard ones the jFuzzyLogic and fuzzylite
 * readers accept (Open Level, Table 10), which the strict reader rejects.
 */
public enum AccumulationMethod {
    MAX(true),
    BSUM(true),
    NSUM(true),
    /** Probabilistic OR, a + b − a·b (jFuzzyLogic PROBOR, fuzzylite ASUM): O-ACCU-PROBOR. */
    PROBOR(false),
    /** Unbounded sum, a + b (jFuzzyLogic SUM, also its reading of a missing ACCU; fuzzylite SUM): O-ACCU-SUM. */
    SUM(false),
    /** Einstein sum (fuzzylite): O-ACCU-OTHER-NORM, as the others below. */
    ESUM(false),
    /** Hamacher sum (fuzzylite). */
    HSUM(false),
    /** Drastic sum (fuzzylite). */
    DSUM(false),
    /** Nilpotent maximum (fuzzylite). */
    NMAX(false);

    private final boolean standard;

    AccumulationMethod(boolean standard) {
        this.standard = standard;
    }

    /** True for the methods of Table 5. */
    public boolean standard() {
        return standard;
    }

    /**
     * The s-norm of the OR algorithm of the same name for the fuzzylite norms ESUM, HSUM, DSUM and NMAX (which
     * accumulate a + b folded as S(a, b) from 0), else empty.
     */
    public java.util.Optional<OrAlgorithm> otherNorm() {
        return switch (this) {
            case ESUM, HSUM, DSUM, NMAX -> java.util.Optional.of(OrAlgorithm.valueOf(name()));
            default -> java.util.Optional.empty();
        };
    }
}
