package org.fclcert.eval;

/**
 * An evaluation that cannot produce a number: an unknown name, an input that is not a finite number,
 * a result that does not fit the output's data type. Carries a stable {@code FCL-Vnnn} code.
 */
public final class EvaluationException extends Exception {
    private static final long serialVersionUID = 1L;

    /** A name (variable or function block) that the program does not declare. */
    public static final String UNKNOWN_NAME = "FCL-V001";
    /** An input value that is NaN or infinite. */
    public static final String NOT_FINITE = "FCL-V002";
    /** {@code set} on a variable that is not a VAR_INPUT. */
    public static final String NOT_AN_INPUT = "FCL-V003";
    /** A value that does not fit the data type of its variable (e.g. 300 for a SINT output). */
    public static final String OUT_OF_RANGE = "FCL-V004";
    /** A defuzzification whose result is not a finite number (overflow in the arithmetic). */
    public static final String NO_RESULT = "FCL-V005";
    /**
     * An output without RANGE whose set is unbounded at run time: a fired term, its variable points re-sorted,
     * is non-zero at its first or last point (the static case is FCL-C025).
     */
    public static final String UNBOUNDED = "FCL-V006";

    /** FCL-V006 for output {@code variable}, whose fired term keeps a positive degree beyond {@code at}. */
    static EvaluationException unbounded(String variable, double at) {
        return new EvaluationException(UNBOUNDED, "the set of output '" + variable + "' is unbounded: a fired term"
                + " is non-zero at its outer point " + at + " (its points come from variables) and the output has no"
                + " RANGE; declare a RANGE (5.2.3) or keep the variable points inside the term");
    }

    private final String code;

    public EvaluationException(String code, String message) {
        super(message);
        this.code = code;
    }

    /** The stable diagnostic code, {@code FCL-Vnnn}. */
    public String code() {
        return code;
    }

    /** {@code FCL-Vnnn: message}. */
    @Override
    public String toString() {
        return code + ": " + getMessage();
    }
}
