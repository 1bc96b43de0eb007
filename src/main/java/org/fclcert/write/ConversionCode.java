package org.fclcert.write;

import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;

/**
 * The codes of the conversion of a dialect program to standard FCL ({@code FCL-Xnnn}), reported by
 * {@link StandardConversion.Finding#diagnostic(boolean)}. An exact conversion is a note and has no code.
 * docs/diagnostics.md lists the same table.
 */
public enum ConversionCode implements DiagnosticCode {
    NOT_EXPRESSIBLE("FCL-X001", Severity.ERROR, "Table 10",
            "a construct standard FCL cannot express (e.g. METHOD MoM); a warning with --allow-lossy"),
    APPROXIMATED("FCL-X002", Severity.WARNING, "Table 10",
            "a construct converted approximately; the message gives the largest membership error");

    private final String code;
    private final Severity severity;
    private final String clause;
    private final String meaning;

    ConversionCode(String code, Severity severity, String clause, String meaning) {
        this.code = code;
        this.severity = severity;
        this.clause = clause;
        this.meaning = meaning;
    }

    @Override
    public String code() {
        return code;
    }

    @Override
    public Severity severity() {
        return severity;
    }

    /** Both concern Open Level constructs (Table 10) of a library's dialect. */
    @Override
    public String clause() {
        return clause;
    }

    @Override
    public String meaning() {
        return meaning;
    }
}
