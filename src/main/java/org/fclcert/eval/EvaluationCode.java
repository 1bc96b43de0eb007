package org.fclcert.eval;

import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;

/**
 * The codes of the reference evaluator ({@code FCL-Vnnn}): why a checked program cannot be evaluated for
 * the values given. Carried by {@link EvaluationException}; docs/diagnostics.md lists the same table.
 */
public enum EvaluationCode implements DiagnosticCode {
    /** A name (variable or function block) that the program does not declare. */
    UNKNOWN_NAME("FCL-V001", "5.2.1", "a variable or function block name the program does not declare"),
    /** An input value that is NaN or infinite. */
    NOT_FINITE("FCL-V002", "5.2.1, IEC 61131-3 2.3.1", "an input value that is NaN or infinite"),
    /** {@code set} on a variable that is not a VAR_INPUT. */
    NOT_AN_INPUT("FCL-V003", "5.2.1", "a value given for a variable that is not a VAR_INPUT"),
    /** A value that does not fit the data type of its variable (e.g. 300 for a SINT output). */
    OUT_OF_RANGE("FCL-V004", "5.2.1, IEC 61131-3 2.3.1",
            "a value that does not fit its variable's data type (e.g. 200 for a SINT output)"),
    /** A defuzzification whose result is not a finite number (overflow in the arithmetic). */
    NO_RESULT("FCL-V005", "Table 1", "a defuzzification whose arithmetic overflowed (result not finite)"),
    /**
     * An output without RANGE whose set is unbounded at run time: a fired term, its variable points re-sorted,
     * is non-zero at its first or last point (the static case is FCL-C025; docs/semantics.md, point 5).
     */
    UNBOUNDED("FCL-V006", "5.2.2, 5.2.3",
            "an output without RANGE whose fired term, its points given by variables, is non-zero at an outer point"
                    + " (the set is unbounded)");

    private final Entry entry;

    /** Always an error: no number comes out. */
    EvaluationCode(String code, String clause, String meaning) {
        this.entry = new Entry(code, Severity.ERROR, clause, meaning);
    }

    @Override
    public Entry entry() {
        return entry;
    }

    /**
     * Whether a checked program and finite inputs alone cause this error (a value out of its type, an overflow, an
     * unbounded set), so that a corpus step may expect it; the others are misuse of the evaluator's interface.
     */
    public boolean causedByTheProgram() {
        return this == OUT_OF_RANGE || this == NO_RESULT || this == UNBOUNDED;
    }

    /** The code spelt exactly {@code FCL-Vnnn}, if it is one of these. */
    public static java.util.Optional<EvaluationCode> of(String code) {
        for (EvaluationCode c : values()) {
            if (c.entry.code().equals(code)) {
                return java.util.Optional.of(c);
            }
        }
        return java.util.Optional.empty();
    }
}
