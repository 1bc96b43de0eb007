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
    SUM(false);

    private final boolean standard;

    AccumulationMethod(boolean standard) {
        this.standard = standard;
    }

    /** True for the methods of Table 5. */
    public boolean standard() {
        return standard;
    }
}
