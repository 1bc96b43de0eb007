package org.fclcert.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.HashSet;
import java.util.Set;
import javax.xml.parsers.DocumentBuilderFactory;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.Json;
import org.fclcert.harness.PlannedCase;
import org.fclcert.harness.ResultsFile;
import org.fclcert.report.HtmlReport;
import org.fclcert.report.JunitReport;
import org.fclcert.report.MarkdownReport;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;

/**
 * Coverage-guided fuzzing (Jazzer) of {@code fclcert report --from}: the bytes are a {@code results.jsonl} (written
 * by certify, then cut short, damaged or forged). Properties: it is read, or refused with a message that names the
 * file, never an exception; every warning names its line; the report holds each case once — the planned ones in
 * order, then any others — and renders in all four formats: report.json reads back to the same summary,
 * junit.xml is well-formed XML, report.md carries no unescaped {@code <} outside code spans (no raw HTML) and
 * report.html no script
 * but its own. docs/fuzzing-readers.md says how to fuzz for a budget.
 */
class ResultsFuzzTest {
    private static final int MAX_TEXT = 50_000;
    private static final String NAME = "results.jsonl";

    @FuzzTest(maxDuration = "10m")
    void reportFrom(byte[] bytes) throws Exception {
        String text = new String(bytes, StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        ResultsFile file;
        try {
            file = ResultsFile.parse(NAME, text.lines().toList());
        } catch (ResultsFile.InvalidResultsException e) {
            assertTrue(e.getMessage().startsWith(NAME + ":"), e.getMessage());
            return;
        }
        for (String problem : file.problems()) {
            assertTrue(problem.matches("(?s)" + NAME + ":[0-9]+: .+"), problem);
        }
        Report report = ReportBuilder.build(file, Instant.EPOCH);
        Set<String> ids = new HashSet<>();
        for (CaseResult c : report.cases()) {
            assertTrue(ids.add(c.id()), "case " + c.id() + " twice");
        }
        java.util.List<String> planned = file.header().selection().planned().stream().map(PlannedCase::id).distinct()
                .toList();
        assertEquals(planned, report.cases().stream().limit(planned.size()).map(CaseResult::id).toList(),
                "the planned cases first, in order");
        assertEquals(report.summary().cases(), report.cases().size());

        String json = Json.mapper().writeValueAsString(report);
        Report back = Json.mapper().readValue(json, Report.class);
        assertEquals(report.summary(), back.summary(), "report.json reads back");
        assertEquals(report.cases().size(), back.cases().size());

        String junit = JunitReport.render(report);
        DocumentBuilderFactory xml = DocumentBuilderFactory.newInstance();
        xml.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        xml.newDocumentBuilder().parse(new ByteArrayInputStream(junit.getBytes(StandardCharsets.UTF_8)));

        // inside a code span '<' is text, not HTML: look at what lies outside the spans
        String md = MarkdownReport.render(report).lines().map(l -> l.replaceAll("`[^`]*`", "``"))
                .collect(java.util.stream.Collectors.joining("\n"));
        for (int k = md.indexOf('<'); k >= 0; k = md.indexOf('<', k + 1)) {
            int at = k;
            assertTrue(k > 0 && md.charAt(k - 1) == '\\', () -> "raw '<' in report.md: "
                    + md.substring(Math.max(0, at - 40), Math.min(md.length(), at + 40)));
        }
        String html = HtmlReport.render(report);
        assertEquals(1, count(html.toLowerCase(java.util.Locale.ROOT), "<script"), "report.html: no script but its own");
        assertFalse(html.toLowerCase(java.util.Locale.ROOT).contains("href=\"javascript"), "no javascript: link");
    }

    private static int count(String text, String what) {
        int n = 0;
        for (int i = text.indexOf(what); i >= 0; i = text.indexOf(what, i + 1)) {
            n++;
        }
        return n;
    }
}
