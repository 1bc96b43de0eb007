package org.fclcert.check;

import java.util.Objects;
import java.util.regex.Pattern;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;

/**
 * The code a check rule owns: {@code FCL-Cnnn} for an error, {@code FCL-W0nn} for a warning. Each rule
 * declares its own ({@code static final CheckCode CODE = CheckCode.error(...)}) next to what it checks; the
 * catalogue collects them from the registered rules ({@link Checker#standardRules()}), so a new rule needs no
 * entry anywhere else.
 *
 * @param code     e.g. {@code FCL-C002}
 * @param severity error for {@code FCL-C}, warning for {@code FCL-W}
 * @param clause   the clause or table the rule enforces, e.g. {@code 5.2.4}; {@code —} for a warning the
 *                 standard does not ask for
 * @param meaning  one line saying what the rule asserts of a valid program
 */
public record CheckCode(String code, Severity severity, String clause, String meaning) implements DiagnosticCode {
    private static final Pattern ERROR = Pattern.compile("FCL-C\\d{3}");
    private static final Pattern WARNING = Pattern.compile("FCL-W0\\d{2}");

    public CheckCode {
        Objects.requireNonNull(severity, "severity");
        Pattern form = severity == Severity.ERROR ? ERROR : WARNING;
        if (code == null || !form.matcher(code).matches()) {
            throw new IllegalArgumentException("a check " + severity.word() + " code has the form "
                    + (severity == Severity.ERROR ? "FCL-Cnnn" : "FCL-W0nn") + ", not " + code);
        }
        if (clause == null || clause.isBlank() || meaning == null || meaning.isBlank()) {
            throw new IllegalArgumentException(code + " needs a clause and a meaning");
        }
    }

    /** The code of a rule whose violation makes the program non-conforming. */
    public static CheckCode error(String code, String clause, String meaning) {
        return new CheckCode(code, Severity.ERROR, clause, meaning);
    }

    /** The code of a rule that flags a legal program that is probably not what was meant. */
    public static CheckCode warning(String code, String clause, String meaning) {
        return new CheckCode(code, Severity.WARNING, clause, meaning);
    }

    @Override
    public Entry entry() {
        return new Entry(code, severity, clause, meaning);
    }
}
