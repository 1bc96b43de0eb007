package org.fclcert.fuzz;

import java.util.Locale;

/** How an implementation departed from the reference on a valid program with fair inputs. */
public enum DeviationKind {
    /** An output outside its tolerance class. */
    WRONG_VALUE,
    /** An output that is NaN or infinite where the reference has a number. */
    NOT_A_NUMBER,
    /** An output the reference gives and the implementation does not. */
    MISSING_OUTPUT,
    /** The implementation refused the valid program. */
    REJECTED,
    /** The implementation answered an evaluation with an error. */
    EVAL_ERROR,
    /** The implementation died or threw. */
    CRASH,
    /** The implementation did not answer in time. */
    HANG,
    /** The implementation's reply was not a reply (not JSON, not the answer asked for). */
    GARBAGE;

    /** Lower-case word for file names and reports: {@code wrong-value}. */
    public String word() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** True for deviations after which the implementation is restarted. */
    public boolean fatal() {
        return this == CRASH || this == HANG || this == GARBAGE;
    }
}
