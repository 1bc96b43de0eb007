package org.fclcert.eval;

/**
 * What the numbers of a program and of its inputs mean to the exact judging path (docs/semantics.md, point 10).
 * The model holds every literal as the double nearest to what was written; the two readings recover either the
 * decimal that was written or keep that double's exact binary value.
 */
public enum NumberReading {
    /**
     * fclcert's reading, the one the exact path judges with: a literal and an input value mean the shortest
     * decimal that reads as their double (for every number written with at most 15 significant digits, exactly
     * the decimal written: {@code 0.1} is one tenth, an input of {@code 0.1} is one tenth).
     */
    DECIMAL,
    /** The exact binary value of the double nearest to the literal or input ({@code 0.1} is 0.1000000000000000055…). */
    BINARY;

    Rational read(double value) {
        return this == DECIMAL ? Rational.decimal(value) : Rational.exactly(value);
    }
}
