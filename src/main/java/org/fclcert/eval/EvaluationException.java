package org.fclcert.eval;

import java.util.Objects;

/**
 * An evaluation that cannot produce a number: an unknown name, an input that is not a finite number,
 * a result that does not fit the output's data type. Carries a stable {@link EvaluationCode} ({@code FCL-Vnnn}).
 */
public final class EvaluationException extends Exception {
    private static final long serialVersionUID = 1L;

    private final EvaluationCode code;

    public EvaluationException(EvaluationCode code, String message) {
        super(message);
        this.code = Objects.requireNonNull(code, "code");
    }

    /** FCL-V006 for output {@code variable}, whose fired term keeps a positive degree beyond {@code at}. */
    static EvaluationException unbounded(String variable, double at) {
        return new EvaluationException(EvaluationCode.UNBOUNDED, "the set of output '" + variable + "' is unbounded: a"
                + " fired term is non-zero at its outer point " + at + " (its points come from variables) and the output"
                + " has no RANGE; declare a RANGE (5.2.3) or keep the variable points inside the term");
    }

    /** The catalogue entry of this failure. */
    public EvaluationCode diagnosticCode() {
        return code;
    }

    /** The stable code as text, {@code FCL-Vnnn}. */
    public String code() {
        return code.code();
    }

    /** An evaluation to run, which may end in an evaluation error. */
    @FunctionalInterface
    public interface Evaluation {
        void run() throws EvaluationException;
    }

    /**
     * Runs {@code evaluation}; the code of the evaluation error it ends in ({@code FCL-Vnnn}), or null when it ends
     * normally: how two evaluations that may both refuse a step are compared (a corpus step that must be refused).
     */
    public static String refusalOf(Evaluation evaluation) {
        try {
            evaluation.run();
            return null;
        } catch (EvaluationException e) {
            return e.code();
        }
    }

    /** {@code FCL-Vnnn: message}. */
    @Override
    public String toString() {
        return code.code() + ": " + getMessage();
    }
}
