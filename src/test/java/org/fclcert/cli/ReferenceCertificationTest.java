package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.fclcert.report.ReportVerifier;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The proof that matters most: fclcert's own evaluator certifies on the real corpus at 100 %. */
class ReferenceCertificationTest {
    @TempDir
    Path dir;

    @Test
    void theReferenceCertifiesTheWholeCorpus() throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int exit = Main.run(new PrintWriter(out), new PrintWriter(err), "certify", "--out", dir.toString(),
                "--fail-on", "any", "--probe-cap", "16");
        assertEquals(0, exit, err::toString);
        Report r = JsonReport.read(dir.resolve("report.json"));
        assertEquals(r.corpus().cases(), r.summary().cases(), "every case of the corpus ran");
        assertEquals(r.summary().cases(), r.summary().passed(), err::toString);
        assertTrue(r.basicLevel().conformant(), r.basicLevel().reason());
        assertTrue(r.run().complete());
        for (Report.FeatureRow f : r.features()) {
            assertNotEquals(FeatureStatus.PARTIAL, f.status(), f.id());
            assertNotEquals(FeatureStatus.NOT_REALISED, f.status(), f.id());
            if (f.table() == 8) {
                assertEquals(FeatureStatus.REALISED, f.status(), "every Table 8 row has evidence: " + f.id());
            }
        }
        // the reference exports with the canonical writer: every positive case reads back and evaluates alike
        r.cases().forEach(c -> assertNotEquals(ExportStatus.FAILED, c.export().status(), c.id() + ": " + c.export().message()));
        assertTrue(r.cases().stream().anyMatch(c -> c.export().status() == ExportStatus.PASSED));
        assertTrue(r.cases().stream().allMatch(c -> c.status() == CaseStatus.PASSED));
        assertTrue(out.toString().startsWith("fclcert reference evaluator "), out::toString);
        assertTrue(Files.readString(dir.resolve("report.md")).contains("**Basic Level: conformant**"));
        // judged again from its evidence, the run says the same (the dialect cases too: the reference reads them all)
        assertEquals(List.of(), ReportVerifier.verify(dir, Path.of("conformance")));
    }

    @Test
    void onceTheCorpusCoversTable9EveryRowIsRealised() throws Exception {
        Main.run(new PrintWriter(new StringWriter()), new PrintWriter(new StringWriter()), "certify", "--out",
                dir.toString(), "--level", "extension", "--no-probe");
        Report r = JsonReport.read(dir.resolve("report.json"));
        Assumptions.assumeTrue(r.features().stream().filter(f -> f.table() == 9)
                .noneMatch(f -> f.status() == FeatureStatus.NOT_TESTED), "the corpus does not cover Table 9 yet");
        r.features().stream().filter(f -> f.table() == 9)
                .forEach(f -> assertEquals(FeatureStatus.REALISED, f.status(), f.id()));
    }
}
