package org.fclcert.orchestration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;
import org.fclcert.iut.IutOptions;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.probe.Prober;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CertificationTest {
    private static final Path MINI = Path.of("src/test/resources/corpus-mini");

    @Test
    void reportDirectoriesAreNamedAfterTheImplementation() {
        assertEquals("reference", Certification.defaultDirectoryName("reference", "fclcert reference evaluator"));
        assertEquals("fuzzylite-6.0", Certification.defaultDirectoryName("process:fl.sh", "fuzzylite 6.0"));
        assertEquals("my-iut", Certification.defaultDirectoryName("process:x", "../My IUT!/"));
        assertEquals("iut", Certification.defaultDirectoryName("process:x", "///"));
        String longName = "a".repeat(63) + " " + "b".repeat(236);   // 300 characters: above NAME_MAX
        assertEquals("a".repeat(63), Certification.defaultDirectoryName("process:x", longName),
                "cut to 64 characters, a trailing '-' dropped");
        assertEquals(Path.of("fclcert-reports", "reference"), Certification.DEFAULT_REPORTS_ROOT
                .resolve(Certification.defaultDirectoryName("process:x", "Reference")),
                "an implementation naming itself reference lands outside the committed reports/");
    }

    @Test
    void aRequestNeedsOnlyTheImplementationAndTheCorpus() throws Exception {
        Corpus corpus = Corpus.load(MINI);
        Certification.Request r = Certification.Request.builder("reference", corpus).build();
        assertEquals(IutOptions.defaults(), r.options());
        assertEquals("bundled", r.corpusName());
        assertEquals(CaseSelection.all(), r.selection());
        assertNull(r.outDir());
        assertEquals(Path.of("fclcert-reports"), r.reportsRoot(), "never the committed reports/");
        assertNull(r.probe(), "no Table 11 probes unless asked");
        assertThrows(NullPointerException.class, () -> Certification.Request.builder(null, corpus).build());
        assertThrows(IllegalArgumentException.class,
                () -> Certification.Request.builder("reference", corpus).reportsRoot(null).build());
    }

    @Test
    void aRunWritesResultsAndTheFourReportsAndRebuildsThemAlike(@TempDir Path dir) throws Exception {
        Certification.Request request = Certification.Request.builder("reference", Corpus.load(MINI))
                .corpusName(MINI.toString()).selection(new CaseSelection(Set.of(ConformanceLevel.BASIC), Set.of(),
                        List.of())).outDir(dir).filters(List.of("basic"), List.of(), List.of()).build();
        Certification.Outcome outcome = Certification.run(request, RunListener.NONE);
        assertEquals(dir, outcome.directory());
        Report report = outcome.report();
        assertTrue(report.summary().cases() > 0);
        assertEquals(report.summary().cases(), report.summary().passed(), "the reference passes every case");
        assertTrue(report.cases().stream().allMatch(c -> c.level().equals("basic")));
        assertEquals(List.of("basic"), report.run().selection().levels());
        for (String f : List.of("results.jsonl", "report.json", "report.md", "report.html", "junit.xml")) {
            assertTrue(Files.size(dir.resolve(f)) > 0, f);
        }
        Report again = Certification.rebuildReports(org.fclcert.harness.ResultsFile.read(dir.resolve("results.jsonl")),
                dir.resolve("again"));
        assertEquals(report.cases(), again.cases(), "results.jsonl holds every part of every case result");
        assertTrue(again.cases().stream().allMatch(c -> c.status() == CaseStatus.PASSED));
    }

    @Test
    void theFrontEndsDefaultsAreTheLibrarysOwn() {
        assertEquals(IutOptions.DEFAULT_TIMEOUT, Duration.ofSeconds(Defaults.TIMEOUT_SECONDS));
        assertEquals("5s", Defaults.TIMEOUT);
        assertEquals(IutOptions.DEFAULT_TIMEOUT.toMillis(), Long.parseLong(Defaults.TIMEOUT_MILLIS));
        assertEquals(Prober.DEFAULT_BUDGET, Duration.ofMinutes(Defaults.PROBE_BUDGET_MINUTES));
        assertEquals("3m", Defaults.PROBE_BUDGET);
        assertEquals(Prober.DEFAULT_BUDGET.toSeconds(), Long.parseLong(Defaults.PROBE_BUDGET_SECONDS));
        assertEquals(4096, Long.parseLong(Defaults.CERTIFY_PROBE_CAP_TEXT));
        assertEquals(Prober.DEFAULT_CAP, Long.parseLong(Defaults.PROBE_CAP_TEXT));
    }
}
