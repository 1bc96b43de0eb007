package org.fclcert.model;

/** Algorithms for the OR operator (Table 3), each paired with its De Morgan AND algorithm. */
public enum OrAlgorithm {
    MAX,
    ASUM,
    BSUM;

    /** The AND algorithm that makes a De Morgan pair with this one (Table 3). */
    public AndAlgorithm pair() {
        return switch (this) {
            case MAX -> AndAlgorithm.MIN;
            case ASUM -> AndAlgorithm.PROD;
            case BSUM -> AndAlgorithm.BDIF;
        };
    }
}
