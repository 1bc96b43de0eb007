package org.fclcert.check;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;
import org.fclcert.model.Toolkit;

/**
 * Diagnostics as a SARIF 2.1.0 log (OASIS Static Analysis Results Interchange Format), what GitHub code
 * scanning, GitLab and CI dashboards read from linters: one run of the tool {@code fclcert}, whose rules are the
 * catalogue entries of the codes found (code, severity, clause, meaning as help), and one result per
 * diagnostic with its file and region (line and column, 1-based, columns in UTF-16 code units as Java counts
 * them). Used by {@code check --format sarif} and the Maven {@code check} goal; docs/diagnostics.md, "SARIF".
 */
public final class SarifLog {
    /** The schema a SARIF 2.1.0 log names. */
    public static final String SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json";

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private SarifLog() {
    }

    /** The log of these diagnostics, as JSON text ending in a newline. */
    public static String render(List<Diagnostic> diagnostics) {
        ObjectNode log = JSON.createObjectNode();
        log.put("$schema", SCHEMA);
        log.put("version", "2.1.0");
        ObjectNode run = log.putArray("runs").addObject();
        ObjectNode driver = run.putObject("tool").putObject("driver");
        driver.put("name", "fclcert");
        driver.put("version", Toolkit.version());
        Map<String, Integer> ruleIndex = new LinkedHashMap<>();
        ArrayNode rules = driver.putArray("rules");
        List<DiagnosticCode> codes = new ArrayList<>();
        for (Diagnostic d : diagnostics) {
            if (ruleIndex.putIfAbsent(d.code(), codes.size()) == null) {
                codes.add(d.diagnosticCode());
            }
        }
        for (DiagnosticCode code : codes) {
            ObjectNode rule = rules.addObject();
            rule.put("id", code.code());
            rule.putObject("shortDescription").put("text", code.meaning());
            String cites = code.clause().equals("—") ? "" : " (IEC 61131-7 " + code.clause() + ")";
            rule.putObject("fullDescription").put("text", code.meaning() + cites);
            rule.putObject("help").put("text", code.code() + ": " + code.meaning() + cites
                    + ". docs/diagnostics.md lists every code with what it asserts.");
            rule.putObject("defaultConfiguration").put("level", level(code.severity()));
            rule.putObject("properties").put("clause", code.clause());
        }
        run.put("columnKind", "utf16CodeUnits");
        ArrayNode results = run.putArray("results");
        for (Diagnostic d : diagnostics) {
            ObjectNode result = results.addObject();
            result.put("ruleId", d.code());
            result.put("ruleIndex", ruleIndex.get(d.code()));
            result.put("level", level(d.severity()));
            result.putObject("message").put("text", d.message());
            ObjectNode physical = result.putArray("locations").addObject().putObject("physicalLocation");
            physical.putObject("artifactLocation").put("uri", uri(d.location().file()));
            if (d.location().line() >= 1) {
                ObjectNode region = physical.putObject("region");
                region.put("startLine", d.location().line());
                if (d.location().column() >= 1) {
                    region.put("startColumn", d.location().column());
                }
            }
        }
        try {
            return JSON.writeValueAsString(log) + "\n";
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String level(Severity severity) {
        return severity == Severity.ERROR ? "error" : "warning";
    }

    /**
     * A file name as a URI reference: unreserved characters and '/' kept, everything else percent-encoded as
     * UTF-8 (so {@code <stdin>} is {@code %3Cstdin%3E}, and a Windows path's '\' becomes '/').
     */
    static String uri(String file) {
        StringBuilder out = new StringBuilder();
        for (byte b : file.replace('\\', '/').getBytes(StandardCharsets.UTF_8)) {
            int c = b & 0xff;
            if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || "-._~/".indexOf(c) >= 0) {
                out.append((char) c);
            } else {
                out.append('%').append(Character.toUpperCase(Character.forDigit(c >> 4, 16)))
                        .append(Character.toUpperCase(Character.forDigit(c & 15, 16)));
            }
        }
        return out.toString();
    }
}
