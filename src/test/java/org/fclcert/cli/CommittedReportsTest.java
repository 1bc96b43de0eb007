package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.report.ComparisonPage;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;

/**
 * Keeps the committed comparison page and the README's side-by-side table equal to what {@code fclcert compare}
 * makes from the committed reports. When this fails, run {@code scripts/regenerate-reports} and paste the table it
 * prints into README.md.
 */
class CommittedReportsTest {
    static final List<String> DIRS = List.of("reference", "fuzzylite-6.0", "jfuzzylite-6.0.1", "jfuzzylogic-3.3", "ffll-2.2.1",
            "pyfuzzylite-8.0.6", "octave-flt-0.4.6");

    private static List<ComparisonPage.Entry> entries(String prefix) throws Exception {
        List<ComparisonPage.Entry> entries = new ArrayList<>();
        for (String dir : DIRS) {
            Report report = JsonReport.read(Path.of("reports", dir, "report.json"));
            entries.add(new ComparisonPage.Entry(report, prefix + dir + "/report.md"));
        }
        return entries;
    }

    @Test
    void theReadmeShowsTheSummaryOfTheCommittedReports() throws Exception {
        String readme = Files.readString(Path.of("README.md"), StandardCharsets.UTF_8);
        String table = ComparisonPage.summaryMarkdown(entries("reports/"));
        assertTrue(readme.contains(table), "README.md's side-by-side table is not what 'fclcert compare' makes of the"
                + " committed reports; run scripts/regenerate-reports and paste:\n" + table);
    }

    @Test
    void theCommittedComparisonPageIsUpToDate() throws Exception {
        List<ComparisonPage.Entry> entries = entries("");
        assertEquals(ComparisonPage.markdown(entries), Files.readString(Path.of("reports/index.md")),
                "reports/index.md is stale: run scripts/regenerate-reports");
        assertEquals(ComparisonPage.html(entries), Files.readString(Path.of("reports/index.html")),
                "reports/index.html is stale: run scripts/regenerate-reports");
    }

    @Test
    void theReferenceIsConformantAndEveryLibraryWasCertifiedOnTheSameCorpus() throws Exception {
        List<ComparisonPage.Entry> entries = entries("");
        Report reference = entries.get(0).report();
        assertTrue(reference.basicLevel().conformant());
        assertEquals(reference.summary().cases(), reference.summary().passed());
        for (ComparisonPage.Entry e : entries) {
            assertEquals(reference.corpus().sha256(), e.report().corpus().sha256(), e.link());
        }
    }
}
