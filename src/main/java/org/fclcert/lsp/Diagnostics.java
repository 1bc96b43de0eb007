package org.fclcert.lsp;

import java.net.URLEncoder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.lsp4j.DiagnosticCodeDescription;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Range;
import org.fclcert.model.Severity;

/**
 * check's findings as the protocol's diagnostics: the same code, severity and message; the range is the token
 * at check's {@code line:col}; the clause the code cites is the code description, as a URN of IEC 61131-7
 * (RFC 5141) with the clause as its fragment, e.g. {@code urn:iec:std:iec:61131-7#5.2.4}.
 */
final class Diagnostics {
    static final String SOURCE = "fclcert";
    static final String STANDARD_URN = "urn:iec:std:iec:61131-7";

    private Diagnostics() {
    }

    static List<Diagnostic> of(Snapshot s) {
        List<Diagnostic> out = new ArrayList<>();
        for (org.fclcert.model.Diagnostic d : s.diagnostics()) {
            out.add(of(s, d));
        }
        return out;
    }

    static Diagnostic of(Snapshot s, org.fclcert.model.Diagnostic d) {
        Range range = range(s, d);
        Diagnostic out = new Diagnostic(range, d.message(),
                d.severity() == Severity.ERROR ? DiagnosticSeverity.Error : DiagnosticSeverity.Warning, SOURCE, d.code());
        out.setCodeDescription(new DiagnosticCodeDescription(clauseUri(d.diagnosticCode().clause())));
        return out;
    }

    static Range range(Snapshot s, org.fclcert.model.Diagnostic d) {
        return s.source().tokenRange(d.location().line(), d.location().column());
    }

    /** The URN of a clause or table of the standard, e.g. {@code urn:iec:std:iec:61131-7#Table%203}. */
    static String clauseUri(String clause) {
        return STANDARD_URN + "#" + URLEncoder.encode(clause, StandardCharsets.UTF_8).replace("+", "%20");
    }
}
