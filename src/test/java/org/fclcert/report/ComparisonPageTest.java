package org.fclcert.report;

import static org.fclcert.report.Results.result;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.PlannedCase;
import org.fclcert.harness.RunHeader;
import org.junit.jupiter.api.Test;

/** The comparison page from two hand-made reports: one that passes everything, one with a wrong value and a crash. */
class ComparisonPageTest {
    private static final List<CaseResult> GOOD = List.of(
            result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")),
            result("B-COGS-002", "basic", CaseStatus.PASSED, List.of("B-COGS")),
            result("E-NOT-001", "extension", CaseStatus.PASSED, List.of("E-NOT")));
    private static final List<CaseResult> BAD = List.of(
            result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")),
            result("B-COGS-002", "basic", CaseStatus.FAILED, List.of("B-COGS")),      // y = 1 where 2 is expected
            result("E-NOT-001", "extension", CaseStatus.ERRORED, List.of("E-NOT")));

    static Report report(String name, List<CaseResult> results) {
        RunHeader header = new RunHeader(
                new RunHeader.Iut(name, "1.0", name, name, null, List.of(), Map.of()),
                new RunHeader.Toolkit("0.1.0-test"),
                new RunHeader.CorpusInfo("conformance", results.size(), "00ff", 2),
                new RunHeader.Selection(List.of(), List.of(), List.of(), results.stream()
                        .map(c -> new PlannedCase(c.id(), c.title(), c.level(), c.tests(), c.flags())).toList()),
                "2026-11-22T04:00:00Z");
        return ReportBuilder.build(header, results, List.of(), List.of(), Instant.EPOCH);
    }

    private static List<ComparisonPage.Entry> entries() {
        return List.of(new ComparisonPage.Entry(report("Good", GOOD), "good/report.md"),
                new ComparisonPage.Entry(report("Bad <lib>", BAD), "bad/report.md"));
    }

    @Test
    void theSummaryPutsTheImplementationsSideBySide() {
        String summary = ComparisonPage.summaryMarkdown(entries());
        assertTrue(summary.startsWith("|  | [Good 1.0](good/report.md) | [Bad <lib> 1.0](bad/report.md) |\n| --- | --- | --- |\n"),
                summary);
        assertTrue(summary.contains("| Cases (3) | 3 passed | 1 passed, 1 failed, 1 errored |\n"), summary);
        assertTrue(summary.contains("| Basic Level (Table 8) | conformant | **not conformant** (1 of 2 Basic cases passed) |"),
                summary);
        assertTrue(summary.contains("| Standard Extensions realised (Table 9) | 1 of 25 | 0 of 25 |"), summary);
    }

    @Test
    void everyFeatureRowDeviationsWithValuesAndCauses() {
        String md = ComparisonPage.markdown(entries());
        assertTrue(md.contains("| B-COGS: METHOD CoGS, centre of gravity for singletons | realised 2/2 | **partial** 1/2 |"), md);
        assertTrue(md.contains("| E-NOT: NOT operator, 1 - argument (also IS NOT) | realised 1/1 | **not realised** 0/1 |"), md);
        // the wrong value: y = 1.0 where the standard gives 2.0, at step 1
        assertTrue(md.contains("| B-COGS-002: title of B-COGS-002 | as the standard | **1** where the standard gives 2 (y, step 1) |"),
                md);
        assertTrue(md.contains("- 1 case: wrong value: B-COGS (METHOD CoGS, centre of gravity for singletons): wrong value"), md);
        assertTrue(md.contains("The semantic axis (the same cases in each library's own layout) was not run"), md);
        assertFalse(md.contains("semantic: "), "no semantic verdicts when the reports have none");
    }

    @Test
    void aSemanticVerdictIsShownBesideTheLanguageVerdict() {
        Report bad = report("Bad", BAD);
        List<Report.FeatureRow> rows = bad.features().stream().map(f -> !f.id().equals("B-COGS") ? f
                : new Report.FeatureRow(f.id(), f.table(), f.level(), f.element(), f.description(), f.status(), f.passed(),
                        f.failed(), f.errored(), f.skipped(), f.cases(), f.notPassed(),
                        new Report.Semantic(FeatureStatus.REALISED, 2, 2))).toList();
        Report withSemantic = new Report(bad.formatVersion(), bad.generatedAt(), bad.iut(), bad.toolkit(), bad.corpus(),
                bad.run(), bad.summary(), bad.rejections(), bad.basicLevel(), rows, bad.dataCheckList(),
                bad.interpretation(), bad.claims(), bad.causes(), bad.cases());
        String md = ComparisonPage.markdown(List.of(new ComparisonPage.Entry(withSemantic, "bad/report.md")));
        assertTrue(md.contains("| language: **partial** 1/2; semantic: realised 2/2 |"), md);
    }

    @Test
    void theHtmlEscapesNamesAndLinksTheHtmlReports() {
        String html = ComparisonPage.html(entries());
        assertTrue(html.contains("<a href=\"bad/report.html\">Bad &lt;lib&gt; 1.0</a>"), html);
        assertFalse(html.contains("<lib>"));
        assertTrue(html.contains("<b>not conformant</b>"));
    }

    @Test
    void numbersAreShortAndExact() {
        assertEquals("9.09091", ComparisonPage.number(100 * 0.1 / 1.1));
        assertEquals("25", ComparisonPage.number(25.0));
        assertEquals("NaN", ComparisonPage.number(Double.NaN));
        assertEquals("4.00004e-05", ComparisonPage.number(4.00004e-5));
    }
}
