package org.fclcert.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.harness.PlannedCase;
import org.fclcert.harness.ReferenceTrace;
import org.fclcert.harness.RunHeader;
import org.fclcert.plot.Chromium;
import org.fclcert.plot.SetPicture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * report.html as a person opens it, in headless Chromium: a partial run of one failing continuous case leads with
 * its cause, folds the rows it did not test, and shows the case open with the reference's trace and its accumulated
 * set, the standard's value and the implementation's marked.
 */
class HtmlReportChromiumTest {
    @TempDir
    Path dir;

    /** E-COG-001 at step 1: the trapezoid clipped at 0.6 over [20, 80], CoG 50 by symmetry; the implementation said 62.5. */
    static Report failingContinuousCase() {
        ReferenceTrace trace = new ReferenceTrace(1,
                List.of(new ReferenceTrace.RuleDegree("No1", "1", 0.6, List.of("y IS mid"))),
                List.of(new ReferenceTrace.OutputValue("y", 50, "defuzzified", false, List.of(List.of(0.0, 0.0),
                        List.of(20.0, 0.0), List.of(40.0, 0.6), List.of(60.0, 0.6), List.of(80.0, 0.0),
                        List.of(100.0, 0.0)))));
        CaseResult failed = new CaseResult(new PlannedCase("E-COG-001", "CoG of a clipped trapezoid", "extension",
                List.of("E-COG"), List.of()),
                new CaseResult.Verdict(CaseStatus.FAILED, "step 1 of 1: y = 62.5 where 50.0 is expected", List.of(), null),
                new CaseResult.Evidence(new CaseResult.Step(1, Map.of("x", 0.4)),
                        new CaseResult.Mismatch.Outputs(Map.of("y", 50.0), Map.of("y", 62.5)), null, 12.5, trace),
                new CaseResult.Export(ExportStatus.UNSUPPORTED, null),
                new CaseResult.Setup(null, "continuous", "FUNCTION_BLOCK fb\nEND_FUNCTION_BLOCK", 3L));
        RunHeader header = new RunHeader(
                new RunHeader.Iut("Vendor FCL", "2.0", "python3 v.py", "process:python3 v.py", null, List.of(), Map.of()),
                new RunHeader.Toolkit("0.1.0-test"),
                new RunHeader.CorpusInfo("conformance", 193, "00ff", 90),
                new RunHeader.Selection(List.of(), List.of(), List.of("E-COG-001"),
                        List.of(failed.plan())), "2026-11-22T04:00:00Z");
        return ReportBuilder.build(header, List.of(failed), List.of(), List.of(), Instant.EPOCH);
    }

    /**
     * Every committed report, its details unfolded, fits a 1024-pixel window: no horizontal scrollbar. Table 11's
     * notes of a library that refuses every text are sentences of several hundred characters; set as a badge that
     * never wraps, they made the page 3 500 to 5 600 pixels wide. Table 8's nine columns with badges that never
     * wrapped made the library reports about 1 190 pixels wide.
     */
    @Test
    void everyCommittedReportFitsTheWindowsWidth() throws Exception {
        List<Path> reports;
        try (var dirs = java.nio.file.Files.list(Path.of("reports"))) {
            reports = dirs.map(d -> d.resolve("report.html")).filter(java.nio.file.Files::isRegularFile).sorted()
                    .toList();
        }
        assertTrue(reports.size() >= 7, "the committed reports: " + reports);
        for (Path r : reports) {
            // rendered from the report's model, so that a change of HtmlReport shows before the reports are regenerated
            Report report = JsonReport.read(r.resolveSibling("report.json"));
            List<String> over = Chromium.overflow(dir, r.getParent().getFileName().toString(), HtmlReport.render(report),
                    1024);
            assertEquals(1, over.size(), r + " is wider than the window: " + String.join("\n", over));
            assertTrue(over.get(0).matches("width (\\d+) of \\1"), r + ": " + over);
        }
    }

    @Test
    void theFailingCaseIsOpenWithItsTraceAndItsAccumulatedSet() throws Exception {
        String html = HtmlReport.render(failingContinuousCase());
        assertTrue(html.contains("<li>rules fired: RULE 1 at 0.6 → y IS mid</li>"), html);
        // the rows this partial run did not test are folded: all of Tables 8 and 10, all but E-COG of Table 9
        assertTrue(html.contains("<summary>11 of 11 rows not tested in this run (partial selection)</summary>"), html);
        assertTrue(html.contains("<summary>24 of 25 rows not tested in this run (partial selection)</summary>"), html);
        assertTrue(html.contains("<summary>4 of 4 rows not tested in this run (partial selection)</summary>"), html);
        assertEquals(1, html.split("<svg", -1).length - 1, "one picture");
        BufferedImage page = Chromium.render(dir, "report.html", html, 1200, 2200, "report");
        // the picture is drawn in the open case: its fill, the standard's green line and the implementation's red
        // dashes, each a run of pixels no other part of the page has in these colours
        assertTrue(count(page, SetPicture.SET_FILL) > 5_000, "the set's fill: " + count(page, SetPicture.SET_FILL));
        assertTrue(count(page, SetPicture.EXPECTED) > 300, "the standard's line: " + count(page, SetPicture.EXPECTED));
        assertTrue(count(page, SetPicture.ACTUAL) > 150, "the implementation's line: " + count(page, SetPicture.ACTUAL));
        // and the page leads with what is wrong: the failure's red badge within the first screen
        assertTrue(count(page.getSubimage(0, 0, 1200, 700), "#fadddd") > 200, "a red 'failed' badge near the top");
    }

    @Test
    void reportMdOfAPartialRunListsTheRowsItTestedAndNamesTheOthersInOneLine() {
        String md = MarkdownReport.render(failingContinuousCase());
        assertTrue(md.contains("Not tested in this run (partial selection): B-FB, B-IN-TERM, B-OUT-SINGLETON, B-AND-MIN,"),
                md);
        // one case of a narrowed run whose header does not say how many E-COG has: failed, yet no verdict on the row
        assertTrue(md.contains("| defuzzification method | E-COG: METHOD CoG, centre of gravity | not determined (1 run)"
                + " | 0/1 | E-COG-001 |"), md);
        assertTrue(!md.contains("| not tested |"), "no untested row is tabled");
        assertTrue(md.contains("    - rules fired: RULE 1 at 0.6 → y IS mid\n"), md);
    }

    private static int count(BufferedImage image, String rgb) {
        int want = Integer.parseInt(rgb.substring(1), 16);
        int n = 0;
        for (int x = 0; x < image.getWidth(); x++) {
            for (int y = 0; y < image.getHeight(); y++) {
                if (Chromium.close(image.getRGB(x, y), want, 6)) {
                    n++;
                }
            }
        }
        return n;
    }
}
