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

    private final Entry entry;

    ConversionCode(String code, Severity severity, String clause, String meaning) {
        this.entry = new Entry(code, severity, clause, meaning);
    }

    @Override
    public Entry entry() {
        return entry;
    }
}
