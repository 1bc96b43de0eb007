package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code fclcert compare} over report directories written by {@code certify}. */
class CompareCommandTest {

    @Test
    void writesIndexMdAndHtmlFromReportDirectoriesAndPrintsTheSummary(@TempDir Path tmp) throws Exception {
        Path ref = tmp.resolve("reports/reference");
        Cli certify = Cli.run("certify", "--corpus", "src/test/resources/corpus-mini", "--out", ref.toString(), "--no-probe");
        assertEquals(0, certify.exitCode(), certify.err());
        Path out = tmp.resolve("reports");
        Cli r = Cli.run("compare", "--out", out.toString(), ref.toString(), ref.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().startsWith("|  | [fclcert reference evaluator "), r.out());
        assertTrue(r.out().contains("](" + ref.resolve("report.md") + ") |"), r.out());
        assertTrue(r.out().contains("| Cases (13) | 13 passed | 13 passed |"), r.out());
        assertTrue(r.out().strip().endsWith("Wrote " + out.resolve("index.md") + " and index.html"), r.out());
        String md = Files.readString(out.resolve("index.md"));
        assertTrue(md.startsWith("# FCL implementations side by side"), md);
        assertTrue(md.contains("No implementation computed a wrong value"), md);
        assertTrue(Files.readString(out.resolve("index.html")).contains("<a href=\"reference/report.html\">"));
        // the same reports give the same page (no clock in it)
        Cli again = Cli.run("compare", "--out", out.toString(), ref.toString(), ref.toString());
        assertEquals(0, again.exitCode());
        assertEquals(md, Files.readString(out.resolve("index.md")));
    }

    @Test
    void aDirectoryWithoutAReportCannotBeCompared(@TempDir Path tmp) {
        Cli r = Cli.run("compare", "--out", tmp.toString(), tmp.resolve("nothing").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("report.json: no such file"), r.err());
    }
}
