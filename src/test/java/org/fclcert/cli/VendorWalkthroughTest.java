package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.fclcert.report.Tally;
import org.fclcert.report.VerdictInvariants;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The vendor walk-through of docs/iut-protocol.md run again (issue 29): the Python example of examples/iut/, a Basic
 * Level implementation that says plainly what it does not support, certified on the whole corpus through the process
 * adapter, then one case rerun with --case. The certificate must explain itself truly: its causes quote the
 * implementation's own messages, no verdict contradicts a row, the rerun is "not determined", and report.html,
 * junit.xml and the terminal count alike. (The Java SPI persona is the Maven integration test vendor-spi-only.)
 */
class VendorWalkthroughTest {
    private static final String IUT = "process:python3 " + Path.of("examples/iut/basic_iut.py").toAbsolutePath();

    @Test
    void thePythonVendorsCertificateExplainsItselfTruly(@TempDir Path dir) throws Exception {
        Cli run = Cli.run("certify", "--iut", IUT, "--no-probe", "--out", dir.resolve("all").toString());
        assertEquals(0, run.exitCode(), run.err());
        Report r = JsonReport.read(dir.resolve("all/report.json"));
        assertEquals(List.of(), VerdictInvariants.violations(r));
        // the Basic Level cases as certify counts them (Rejudge: a case with an interpretation flag is not one)
        long basic = org.fclcert.corpus.Corpus.load(Path.of("conformance")).cases().stream()
                .filter(c -> c.level() == org.fclcert.model.ConformanceLevel.BASIC && c.interpretation().isEmpty())
                .count();
        // examples/iut/basic_iut.py rejects RANGE with "'RANGE' is not supported at the Basic Level": that is the cause
        assertTrue(run.out().contains("Basic Level: conformant (all " + basic + " Basic Level cases passed)"),
                run.out());
        assertTrue(run.out().contains(" cases: rejected at load: 'RANGE' is not supported at the Basic Level\n"),
                run.out());
        assertTrue(r.causes().stream().filter(c -> c.kind().equals("rejected at load"))
                .allMatch(c -> r.cases().stream().filter(x -> x.id().equals(c.cases().get(0))).findFirst().orElseThrow()
                        .message().endsWith(c.cause())), "every rejection cause is its first case's own words");
        assertFalse(run.out().contains("`RANGE (a .. b)` without `:=`"), run.out());
        // E-RANGE-004 also tests B-DEFAULT-VALUE; rejected for its RANGE, it is not held against the Basic row
        Report.FeatureRow defaults = r.features().stream().filter(f -> f.id().equals("B-DEFAULT-VALUE")).findFirst()
                .orElseThrow();
        assertEquals("realised", defaults.status().label(), defaults.sentence());
        assertFalse(r.claims().notRealised().stream().anyMatch(s -> s.startsWith("B-")), r.claims().toString());
        // one count: report.html and junit.xml say what the tally says
        Tally t = Tally.of(r);
        String html = Cli.read(dir.resolve("all/report.html"));
        assertTrue(html.contains(t.sentence()), t.sentence());
        String junit = Cli.read(dir.resolve("all/junit.xml"));
        assertTrue(junit.contains("failures=\"" + t.failures() + "\" errors=\"" + t.errors() + "\" skipped=\""
                + (t.unclaimed() + t.notRun()) + "\""), junit.substring(0, 400));

        Cli rerun = Cli.run("certify", "--iut", IUT, "--case", "E-WITH-CONST-001", "--out", dir.resolve("one").toString());
        assertEquals(0, rerun.exitCode(), rerun.err());
        assertTrue(rerun.out().contains("Basic Level: not determined (0 of " + basic + " run)"), rerun.out());
        // the cases certify counts for the row (an interpretation flag takes a case out, as for Basic above)
        long withConst = org.fclcert.corpus.Corpus.load(Path.of("conformance")).cases().stream()
                .filter(c -> c.tests().contains(org.fclcert.model.Feature.E_WITH_CONST) && c.interpretation().isEmpty())
                .count();
        assertTrue(rerun.out().contains("Claimed, not determined: E-WITH-CONST (1 of " + withConst + " run)"),
                rerun.out());
        assertFalse(rerun.out().contains("not realised"), rerun.out());
        Report one = JsonReport.read(dir.resolve("one/report.json"));
        assertEquals(List.of(), VerdictInvariants.violations(one));
        assertTrue(Cli.read(dir.resolve("one/report.md")).contains("**Basic Level: not determined** (0 of " + basic + " run)."));
    }
}
