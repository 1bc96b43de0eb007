package org.fclcert.model;

/** Algorithms for the AND operator (Table 3), each paired with its De Morgan OR algorithm. */
public enum AndAlgorithm {
    MIN,
    PROD,
    BDIF;

    /** The OR algorithm that makes a De Morgan pair with this one (Table 3). */
    public OrAlgorithm pair() {
        return switch (this) {
            case MIN -> OrAlgorithm.MAX;
            case PROD -> OrAlgorithm.ASUM;
            case BDIF -> OrAlgorithm.BSUM;
        };
    }
}
