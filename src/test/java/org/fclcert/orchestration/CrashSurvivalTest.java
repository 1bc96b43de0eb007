package org.fclcert.orchestration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.RunListener;
import org.fclcert.iut.IutOptions;
import org.fclcert.report.Report;
import org.fclcert.report.ReportVerifier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A crash costs only the request that caused it: an implementation that kills itself (SIGSEGV) on every third
 * request of each of its processes still has every case of the corpus run, none skipped, and the report counts its
 * crashes and restarts, per case and in all.
 */
class CrashSurvivalTest {
    private static final Path CRASH_EVERY = Path.of("src/test/resources/iut/crash_every.py").toAbsolutePath();

    @Test
    void anImplementationCrashingOnEveryThirdRequestHasEveryCaseRun(@TempDir Path dir) throws Exception {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        Certification.Request request = Certification.Request.builder("process:python3 '" + CRASH_EVERY + "' 3", corpus)
                .options(IutOptions.defaults().withTimeout(Duration.ofSeconds(5))).outDir(dir).build();
        Report report = Certification.run(request, RunListener.NONE).report();

        assertEquals(corpus.cases().size(), report.summary().cases());
        // a process is sent no case written in a library's dialect; every other case runs, none skipped for a give-up
        long dialectCases = corpus.cases().stream().filter(c -> c.dialect() != org.fclcert.syntax.dialect.Dialect.STRICT).count();
        assertTrue(dialectCases > 0, "the corpus has dialect cases");
        assertEquals(dialectCases, report.summary().skipped(), "only the dialect cases are skipped");
        int crashes = 0;
        int restarts = 0;
        int crashedCases = 0;
        int withStderr = 0;
        for (CaseResult c : report.cases()) {
            if (c.status() == CaseStatus.SKIPPED) {
                assertTrue(c.message().startsWith("not presentable: the case is written in "), c.id() + ": " + c.message());
                continue;
            }
            assertTrue(c.status() == CaseStatus.FAILED || c.status() == CaseStatus.ERRORED, c.id() + ": " + c.message());
            int own = c.setup().crashes() == null ? 0 : c.setup().crashes();
            crashes += own;
            restarts += c.setup().restarts() == null ? 0 : c.setup().restarts();
            crashedCases += own > 0 ? 1 : 0;
            if (c.status() == CaseStatus.ERRORED) {
                assertTrue(own > 0, c.id() + " errored without a crash counted: " + c.message());
                assertTrue(c.message().contains("killed by signal 11 (SIGSEGV"), c.message());
                // the end of its stderr, when it arrived before fclcert stopped waiting for it (500 ms)
                withStderr += c.evidence().error().contains("about to crash on request 3") ? 1 : 0;
            }
        }
        // the fake answers no case right (it computes sums), and each process dies on its third request: at least
        // one crash in every three requests, and every case sends at least two (load, export)
        assertTrue(crashes * 3 >= report.summary().cases() * 2 / 3, "crashes: " + crashes);
        assertTrue(crashedCases > report.summary().cases() / 3, "cases with a crash: " + crashedCases);
        assertTrue(withStderr > 0, "no errored case shows the crash's stderr");
        assertEquals(crashes, report.summary().crashes());
        assertEquals(restarts, report.summary().restarts());
        // each crash is followed by one restart, made by the next request (none after the last request of the run)
        assertTrue(restarts == crashes || restarts == crashes - 1, crashes + " crashes, " + restarts + " restarts");

        Report again = Certification.rebuildReports(ResultsFile.read(dir.resolve("results.jsonl")), dir.resolve("again"));
        assertEquals(report.summary(), again.summary(), "results.jsonl keeps every case's crashes and restarts");
        // judged again from its evidence, a line with crashes is consistent (they are the run's statistics)
        assertEquals(List.of(), ReportVerifier.verify(dir, Path.of("conformance")));
    }
}
