package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;
import org.fclcert.report.Report;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code certify --iut ffll} on the whole corpus: FFLL crashes on some programs, and every case is still run, none
 * skipped for a give-up; the crashes are counted per case and in the summary; {@code --present-as auto} presents the
 * positive cases in FFLL's layout.
 */
class FfllCertificationTest {
    @Test
    void everyCaseRunsThoughFfllCrashes(@TempDir Path dir) throws Exception {
        Ffll.assumeLibrary();
        Corpus corpus = Corpus.load(Path.of("conformance"));
        Report report = Certification.run(Certification.Request.builder("ffll", corpus).outDir(dir).build(),
                RunListener.NONE).report();
        assertEquals(corpus.cases().size(), report.summary().cases());
        // FFLL is sent no case written in a library's dialect; every other case is run, none skipped for a give-up
        long inDialect = corpus.cases().stream().filter(c -> c.dialect() != Dialect.STRICT).count();
        assertEquals(inDialect, report.summary().skipped());
        assertTrue(report.cases().stream().filter(c -> c.status() == CaseStatus.SKIPPED)
                .allMatch(c -> c.message().startsWith("not presentable: the case is written in ")));
        assertEquals("ffll", report.semantic().presentAs());
        int crashes = 0;
        for (CaseResult c : report.cases()) {
            assertTrue(c.presentedResult().map(p -> !p.message().contains("given up")).orElse(true), c.id());
            crashes += c.setup().crashes() == null ? 0 : c.setup().crashes();
            if (c.status() == CaseStatus.ERRORED) {
                assertTrue(c.setup().crashes() != null && c.setup().crashes() > 0, c.id() + ": " + c.message());
            }
        }
        assertEquals(crashes, report.summary().crashes());
        assertEquals(0, report.semantic().skipped(), report.semantic().toString());
    }
}
