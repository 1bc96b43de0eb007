package org.fclcert.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.stream.Collectors;
import org.fclcert.model.Diagnostic;

/** Diagnostics in the two output formats, and the one-line summary of a run. */
final class DiagnosticPrinter {
    private static final ObjectMapper JSON = new ObjectMapper();

    /** One diagnostic in the JSON output of {@code check}. */
    record JsonDiagnostic(String file, int line, int column, String severity, String code, String message) {
        static JsonDiagnostic of(Diagnostic d) {
            return new JsonDiagnostic(d.location().file(), d.location().line(), d.location().column(),
                    d.severity().word(), d.code(), d.message());
        }
    }

    private DiagnosticPrinter() {
    }

    /**
     * {@code path:line:col: severity CODE: message}, one per line; a message quoting the source's control
     * characters (a block name taken verbatim) shows them visibly, so the file cannot act on the terminal.
     */
    static void text(PrintWriter out, List<Diagnostic> diagnostics) {
        diagnostics.forEach(d -> out.println(TerminalText.visible(d.toString())));
    }

    static void json(PrintWriter out, List<Diagnostic> diagnostics) {
        out.println(jsonLines(diagnostics.stream().map(JsonDiagnostic::of).toList()));
    }

    /** A JSON array with one compact element per line: easy to read, diff and grep. */
    static String jsonLines(List<?> elements) {
        if (elements.isEmpty()) {
            return "[]";
        }
        return elements.stream().map(e -> "  " + toJson(e)).collect(Collectors.joining(",\n", "[\n", "\n]"));
    }

    static String toJson(Object value) {
        try {
            return JSON.writeValueAsString(value);
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** E.g. {@code 2 files checked: 1 error, 3 warnings}. */
    static String summary(int files, List<Diagnostic> diagnostics) {
        long errors = diagnostics.stream().filter(Diagnostic::isError).count();
        long warnings = diagnostics.size() - errors;
        return count(files, "file") + " checked: " + count(errors, "error") + ", " + count(warnings, "warning");
    }

    static String count(long n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
