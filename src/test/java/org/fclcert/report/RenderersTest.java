package org.fclcert.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.parsers.DocumentBuilderFactory;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.PlannedCase;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

class RenderersTest {
    private static final Report REPORT = ReportBuilderTest.report(List.of("E-NOT"));

    @Test
    void markdownIsAComplianceStatementWithReproCommands() {
        String md = MarkdownReport.render(REPORT);
        // the name is the implementation's: escaped, so it shows as "Fake <FLC>" and is no HTML tag
        assertTrue(md.startsWith("# FCL compliance statement: Fake \\<FLC\\> 0.1\n"), md);
        assertTrue(md.contains("**Basic Level: NOT conformant** (1 of 3 Basic Level cases run did not pass: "
                + "B-COGS-002; 3 of 4 run)."), md);
        assertTrue(md.contains("- Counted as in junit.xml and the Maven log: 8 cases: 3 passed; 2 failed, 1 errored"
                + " (counted); 1 failed or errored in features not claimed (skipped in junit.xml); 1 not run"), md);
        assertTrue(md.contains("## Table 8: Basic Level language elements (mandatory)"));
        assertTrue(md.contains("| defuzzification | B-COGS: METHOD CoGS, centre of gravity for singletons | **partial** "
                + "| 1/2 | B-COGS-002 |"), md);
        assertTrue(md.contains("Realised:\n\n- E-COG (METHOD CoG, centre of gravity)\n"), md);
        assertTrue(md.contains("- **Claimed but not realised**: E-NOT (not realised)"), md);
        assertTrue(md.contains("| E-COG-INT-001 | interpretation:3 | failed |"), md);
        assertTrue(md.contains("### E-NOT: NOT operator, 1 - argument (also IS NOT)\n"), md);
        assertTrue(md.contains("- **E-NOT-002** (title of E-NOT-002) errored: step 1 of 1: y = 1.0 where 2.0 is expected\n"
                + "  - step 1, inputs: x = 0.5\n"
                + "  - expected: y = 2.0; actual: y = 1.0\n  - also evidence for: E-PARENS\n"
                + "  - its last stderr line: `Segmentation fault`\n"
                + "  - reproduce: `./fclcert certify --iut 'process:python3 fake.py' --corpus "
                + "src/test/resources/corpus-mini --case E-NOT-002` (transcript: `requests/E-NOT-002.requests.jsonl`)\n"), md);
        assertTrue(md.contains("- **Incomplete run**"), md);
        assertFalse(md.contains("B-COGS-001**"), "passed cases are not listed as failures");
        assertFalse(md.contains("## Notes"), "no case has a note");
    }

    @Test
    void htmlIsOneSelfContainedBalancedPage() {
        String html = HtmlReport.render(REPORT);
        assertTrue(html.startsWith("<!DOCTYPE html>"));
        assertFalse(Pattern.compile("(src|href)=\"(https?:)?//").matcher(html).find(), "nothing is fetched");
        assertFalse(html.contains("<link"), "no external style sheet");
        assertTrue(html.contains("<style>") && html.contains("<script>"));
        assertBalanced(html);
        assertEquals(3, count(html, "<h2>Table "), "the three tables");
        assertEquals(REPORT.cases().size() - 1, count(html, "<details class=\"case\""));
        assertEquals(1, count(html, "<details open class=\"case\""), "the first failure only is open");
        assertTrue(html.indexOf("<details open class=\"case\" id=\"case-B-COGS-002\"") > 0, "B-COGS-002 fails first");
        assertTrue(html.indexOf("<h2>Failures by cause</h2>") < html.indexOf("<h2>Table 8"), "failures lead");
        assertTrue(html.contains("data-status=\"errored\" data-level=\"extension\""));
        assertTrue(html.contains("<span class=\"st partial\">partial</span>"));
        // program text is escaped and numbered
        assertTrue(html.contains("2    (* x &lt; y &amp; z *)") || html.contains("2  (* x &lt; y &amp; z *)"), html);
        assertTrue(html.contains("Fake &lt;FLC&gt;"));
        assertFalse(html.contains("Fake <FLC>"));
    }

    @Test
    void junitHasOneTestcasePerCaseAndSurvivesControlCharacters() throws Exception {
        CaseResult garbage = new CaseResult(new PlannedCase("B-FB-009", "garbage", "basic", List.of("B-FB"), List.of()),
                new CaseResult.Verdict(CaseStatus.ERRORED, "broke the protocol: reply 'x\u0001\u0007y'", List.of(), null),
                new CaseResult.Evidence(null, null, "\u0000\u001b[31mboom", null), null,
                new CaseResult.Setup(null, "exact", null, 1L));
        List<CaseResult> cases = new java.util.ArrayList<>(REPORT.cases());
        cases.add(garbage);
        Report r = new Report(1, REPORT.generatedAt(), REPORT.iut(), REPORT.toolkit(), REPORT.corpus(), REPORT.run(),
                new Report.Summary(9, 3, 3, 2, 1), REPORT.rejections(), REPORT.basicLevel(), REPORT.features(), List.of(),
                REPORT.interpretation(), REPORT.claims(), REPORT.causes(), cases);
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(JunitReport.render(r).getBytes(StandardCharsets.UTF_8)));
        Element suite = doc.getDocumentElement();
        assertEquals("testsuite", suite.getTagName());
        assertEquals("9", suite.getAttribute("tests"));
        assertEquals("2", suite.getAttribute("errors"));
        NodeList testcases = suite.getElementsByTagName("testcase");
        assertEquals(9, testcases.getLength());
        Element first = (Element) testcases.item(0);
        assertEquals("fclcert.B-COGS", first.getAttribute("classname"));
        assertEquals(0, first.getChildNodes().getLength(), "a passed case has no child element");
        // B-COGS-002 and E-NOT-001 (E-NOT is claimed) fail; E-COG-INT-001 failed too, but E-COG is not claimed
        assertEquals(2, suite.getElementsByTagName("failure").getLength());
        assertEquals("2", suite.getAttribute("failures"));
        assertEquals(2, suite.getElementsByTagName("error").getLength());
        assertEquals("2", suite.getAttribute("skipped"));
        assertEquals(new JunitReport.Counts(9, 2, 2, 2), JunitReport.counts(r));
        assertEquals("Tests run: 9, Failures: 2, Errors: 2, Skipped: 2", JunitReport.counts(r).surefireLine());
        Element unclaimed = (Element) suite.getElementsByTagName("skipped").item(0);
        assertEquals("fclcert.E-COG", ((Element) unclaimed.getParentNode()).getAttribute("classname"));
        assertTrue(unclaimed.getAttribute("message").startsWith("not claimed: Fake <FLC> does not claim E-COG (failed: "),
                unclaimed.getAttribute("message"));
        Element skipped = (Element) suite.getElementsByTagName("skipped").item(1);
        assertEquals("not run: the run ended before this case", skipped.getAttribute("message"));
        Element last = (Element) testcases.item(8);
        assertTrue(last.getElementsByTagName("error").item(0).getTextContent().contains("\uFFFD[31mboom"));
    }

    @Test
    void allFourFilesAreWrittenAndTheJsonReadsBack(@TempDir Path dir) throws Exception {
        List<Path> files = ReportFiles.writeAll(REPORT, dir.resolve("reports/fake"));
        assertEquals(Set.of("report.json", "report.md", "report.html", "junit.xml"),
                Set.copyOf(files.stream().map(p -> p.getFileName().toString()).toList()));
        Report back = JsonReport.read(files.get(0));
        assertEquals(REPORT.features(), back.features());
        assertEquals(REPORT.basicLevel(), back.basicLevel());
        assertEquals(REPORT.summary(), back.summary());
        String json = Files.readString(files.get(0));
        assertTrue(json.contains("\"dataCheckList\" : [ ]"), "present and empty until the probes fill it");
    }

    @Test
    void anAcceptedInvalidProgramShowsTheLineWhereItsErrorIs() {
        CaseResult accepted = MadeResults.made("B-FB-901", "basic", List.of(), List.of(), CaseStatus.FAILED,
                "accepted a program the standard rejects: FCL-S001 at line 3", "reject: FCL-S001 at line 3", "accepted",
                org.fclcert.harness.ExportStatus.NOT_RUN, "FUNCTION_BLOCK fb\nVAR_INPUT\n    x : REAL; `END_VAR\n");
        Report r = ReportBuilder.build(Results.header(1, List.of(accepted), List.of()), List.of(accepted), List.of(),
                List.of(), java.time.Instant.EPOCH);
        assertTrue(MarkdownReport.render(r).contains("  - line 3, where the error is: `x : REAL; 'END_VAR`\n"),
                MarkdownReport.render(r));
        assertTrue(HtmlReport.render(r).contains("<p>Line 3, where the error is: <code>x : REAL; `END_VAR</code></p>"));
    }

    @Test
    void aRunFromMavenIsReproducedWithMaven(@TempDir Path dir) throws Exception {
        CaseResult failed = Results.result("B-COGS-002", "basic", CaseStatus.FAILED, List.of("B-COGS"));
        org.fclcert.harness.RunHeader cli = Results.header(1, List.of(failed), List.of());
        org.fclcert.harness.RunHeader maven = new org.fclcert.harness.RunHeader(cli.iut(),
                new org.fclcert.harness.RunHeader.Toolkit("0.1.0-test", "mvn verify -Dfclcert.cases={case}"),
                cli.corpus(), cli.selection(), cli.startedAt());
        Report r = ReportBuilder.build(maven, List.of(failed), List.of(), List.of(), java.time.Instant.EPOCH);
        assertTrue(MarkdownReport.render(r).contains("  - reproduce: `mvn verify -Dfclcert.cases=B-COGS-002`"));
        assertTrue(HtmlReport.render(r).contains("<code class=\"cmd\">mvn verify -Dfclcert.cases=B-COGS-002</code>"));
        Report back = JsonReport.read(ReportFiles.writeAll(r, dir).get(0));
        assertEquals("mvn verify -Dfclcert.cases={case}", back.toolkit().rerun());
        // the command line's own runs keep theirs, and their JSON has no rerun
        Report plain = ReportBuilder.build(cli, List.of(failed), List.of(), List.of(), java.time.Instant.EPOCH);
        assertTrue(MarkdownReport.render(plain).contains("reproduce: `./fclcert certify --iut 'process:python3 fake.py'"));
        assertFalse(Files.readString(ReportFiles.writeAll(plain, dir.resolve("cli")).get(0)).contains("rerun"));
    }

    @Test
    void aCaseShowsItsSemanticAxisWithTheReferencesTraceAndPicture() {
        org.fclcert.harness.ReferenceTrace trace = new org.fclcert.harness.ReferenceTrace(1,
                List.of(new org.fclcert.harness.ReferenceTrace.RuleDegree("r", "1", 0.5, List.of("y IS hi"))),
                List.of(new org.fclcert.harness.ReferenceTrace.OutputValue("y", 100, "defuzzified", true,
                        List.of(List.of(0.0, 0.0), List.of(100.0, 0.5)))));
        CaseResult rejected = MadeResults.made("B-COGS-001", "basic", List.of("B-COGS"), List.of(), CaseStatus.FAILED,
                "rejected a program the standard accepts", "load and evaluate", "rejected",
                org.fclcert.harness.ExportStatus.NOT_RUN, "FUNCTION_BLOCK fb\nEND_FUNCTION_BLOCK\n")
                .withPresented(new CaseResult.Presented("fuzzylite", org.fclcert.harness.PresentedStatus.FAILED,
                        "step 1 of 1: y = 60.0 where 100.0 is expected", List.of(), new CaseResult.Evidence(
                        new CaseResult.Step(1, java.util.Map.of("x", 0.5)), new CaseResult.Mismatch.Outputs(
                        java.util.Map.of("y", 100.0), java.util.Map.of("y", 60.0)), null, 40.0, trace), "text"));
        Report r = ReportBuilder.build(Results.header(1, List.of(rejected), List.of()).presentedAs("fuzzylite"),
                List.of(rejected), List.of(), List.of(), java.time.Instant.EPOCH);
        String html = HtmlReport.render(r);
        assertTrue(html.contains("<p><b>Semantic axis</b> (written in fuzzylite's layout): <span class=\"st failed\">"
                + "failed</span> step 1 of 1: y = 60.0 where 100.0 is expected</p>"), html);
        assertTrue(html.contains("<li>rules fired: RULE 1 at 0.5 → y IS hi</li>"));
        assertTrue(html.contains("<title>B-COGS-001 (fuzzylite layout), step 1: accumulated set of y</title>"), html);
        assertTrue(MarkdownReport.render(r).contains("    - y = 100, defuzzified from the singletons 100 (degree 0.5)"),
                MarkdownReport.render(r));
    }

    private static int count(String text, String what) {
        int n = 0;
        for (int i = text.indexOf(what); i >= 0; i = text.indexOf(what, i + 1)) {
            n++;
        }
        return n;
    }

    /** Every non-void element is closed in order (the page is hand-written HTML, so this is worth checking). */
    private static void assertBalanced(String html) {
        Set<String> voids = Set.of("meta", "input", "br", "hr", "img", "link");
        Matcher m = Pattern.compile("<(/?)([a-zA-Z0-9]+)[^>]*>").matcher(html.replaceAll("(?s)<script>.*?</script>", "")
                .replaceAll("(?s)<style>.*?</style>", ""));
        Deque<String> open = new ArrayDeque<>();
        while (m.find()) {
            String tag = m.group(2).toLowerCase();
            if (voids.contains(tag)) {
                continue;
            }
            if (m.group(1).isEmpty()) {
                open.push(tag);
            } else {
                assertEquals(open.isEmpty() ? "(none)" : open.peek(), tag, "closing tag at " + m.start());
                open.pop();
            }
        }
        assertTrue(open.isEmpty(), "unclosed: " + open);
    }
}
