package org.fclcert.model;

/** Algorithms for the OR operator (Table 3), each paired with its De Morgan AND algorithm. */
public enum OrAlgorithm {
    MAX,
    ASUM,
    BSUM,
    /** Einstein sum (x + y) / (1 + xy) (dialects only, O-OTHER-NORM). */
    ESUM,
    /** Hamacher sum (x + y − 2xy) / (1 − xy), 1 at 1 and 1 (dialects only). */
    HSUM,
    /** Drastic sum: the other when one is 0, else 1 (dialects only). */
    DSUM,
    /** Nilpotent maximum: max(x, y) when x + y &lt; 1, else 1 (dialects only). */
    NMAX;

    /** True for the algorithms of Table 3. */
    public boolean standard() {
        return this == MAX || this == ASUM || this == BSUM;
    }

    /** The AND algorithm that makes a De Morgan pair with this one (Table 3). */
    public AndAlgorithm pair() {
        return switch (this) {
            case MAX -> AndAlgorithm.MIN;
            case ASUM -> AndAlgorithm.PROD;
            case BSUM -> AndAlgorithm.BDIF;
            case ESUM -> AndAlgorithm.EPROD;
            case HSUM -> AndAlgorithm.HPROD;
            case DSUM -> AndAlgorithm.DPROD;
            case NMAX -> AndAlgorithm.NMIN;
        };
    }
}
