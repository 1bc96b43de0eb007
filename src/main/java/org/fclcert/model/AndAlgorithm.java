package org.fclcert.model;

/** Algorithms for the AND operator (Table 3), each paired with its De Morgan OR algorithm. */
public enum AndAlgorithm {
    MIN,
    PROD,
    BDIF,
    /** Einstein product xy / (2 − (x + y − xy)) (dialects only, O-OTHER-NORM). */
    EPROD,
    /** Hamacher product xy / (x + y − xy), 0 at 0 and 0 (dialects only). */
    HPROD,
    /** Drastic product: the other when one is 1, else 0 (dialects only). */
    DPROD,
    /** Nilpotent minimum: min(x, y) when x + y &gt; 1, else 0 (dialects only). */
    NMIN;

    /** True for the algorithms of Table 3. */
    public boolean standard() {
        return this == MIN || this == PROD || this == BDIF;
    }

    /** The OR algorithm that makes a De Morgan pair with this one (Table 3). */
    public OrAlgorithm pair() {
        return switch (this) {
            case MIN -> OrAlgorithm.MAX;
            case PROD -> OrAlgorithm.ASUM;
            case BDIF -> OrAlgorithm.BSUM;
            case EPROD -> OrAlgorithm.ESUM;
            case HPROD -> OrAlgorithm.HSUM;
            case DPROD -> OrAlgorithm.DSUM;
            case NMIN -> OrAlgorithm.NMAX;
        };
    }
}
