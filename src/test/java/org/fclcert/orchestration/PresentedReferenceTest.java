package org.fclcert.orchestration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.PresentedStatus;
import org.fclcert.harness.RunListener;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.fclcert.report.ReportFiles;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The semantic axis on fclcert's own reference evaluator: programs in fuzzylite's layout, read by fclcert's
 * fuzzylite reader, compute the standard's results, so every row realised on the language axis is realised on the
 * semantic axis too; and which layout {@code auto} picks for which implementation.
 */
class PresentedReferenceTest {

    @Test
    void autoPicksTheLibrarysLayoutForTheBuiltInAdaptersAndNoneOtherwise() {
        assertEquals(Optional.of(Dialect.FUZZYLITE), PresentAs.AUTO.resolve("fuzzylite"));
        assertEquals(Optional.of(Dialect.FUZZYLITE), PresentAs.AUTO.resolve("fuzzylite:/usr/bin/fuzzylite"));
        assertEquals(Optional.of(Dialect.FUZZYLITE), PresentAs.AUTO.resolve("jfuzzylite:lib/jfuzzylite.jar"));
        assertEquals(Optional.of(Dialect.JFUZZYLOGIC), PresentAs.AUTO.resolve("jfuzzylogic:jFuzzyLogic.jar"));
        assertEquals(Optional.empty(), PresentAs.AUTO.resolve("reference"));
        assertEquals(Optional.empty(), PresentAs.AUTO.resolve("java:com.example.Fcl"));
        assertEquals(Optional.empty(), PresentAs.AUTO.resolve("process:fuzzylite-wrapper"));
        assertEquals(Optional.empty(), PresentAs.NONE.resolve("fuzzylite"));
        assertEquals(Optional.of(Dialect.FFLL), PresentAs.of(Dialect.FFLL).resolve("reference"));
    }

    @Test
    void theReferenceInFuzzylitesLayoutIsRealisedOnBothAxes(@TempDir Path out) throws Exception {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        Certification.Request request = Certification.Request.builder("reference", corpus).corpusName("conformance")
                .selection(new CaseSelection(Set.of(), Set.of(), List.of("B-*", "E-*", "O-*"))).outDir(out)
                .presentAs(PresentAs.of(Dialect.FUZZYLITE)).build();
        Report report = Certification.run(request, RunListener.NONE).report();
        Report.SemanticAxis s = report.semantic();
        assertEquals("fuzzylite", s.presentAs());
        assertEquals(0, s.failed() + s.errored() + s.skipped(), s.toString());
        assertEquals(s.cases() - s.notPresentable(), s.passed());
        assertTrue(s.passed() > s.notPresentable(), "most positive cases are presentable: " + s);
        for (CaseResult c : report.cases()) {
            CaseResult.Presented p = c.presented();
            if (p.status() == PresentedStatus.NOT_PRESENTABLE) {
                assertTrue(p.message().startsWith("not presentable in fuzzylite's layout: "), p.message());
                assertNull(p.program());
            }
        }
        // B-COGS-001 needs nothing fuzzylite's FCL lacks: presented, and passed as the standard computes it
        CaseResult cogs = report.cases().stream().filter(c -> c.id().equals("B-COGS-001")).findFirst().orElseThrow();
        assertEquals(PresentedStatus.PASSED, cogs.presented().status(), cogs.presented().message());
        for (Report.FeatureRow f : report.features()) {
            if (f.semantic().total() > 0) {
                assertEquals(FeatureStatus.REALISED, f.semantic().status(), f.id());
            }
        }
        Report.FeatureRow row = report.features().stream().filter(f -> f.id().equals("B-COGS")).findFirst()
                .orElseThrow();
        assertEquals(FeatureStatus.REALISED, row.status());
        assertTrue(row.semantic().total() > 0);
        String md = Files.readString(out.resolve(ReportFiles.MARKDOWN));
        assertTrue(md.contains("Semantic verdict (fuzzylite layout)"), "the Markdown labels both axes");
        assertTrue(md.contains(Report.SEMANTIC_AXIS), md.substring(0, 600));
        String json = Files.readString(out.resolve(ReportFiles.JSON));
        assertTrue(json.contains("\"semantic\""), "report.json carries the semantic verdicts");
        String junit = Files.readString(out.resolve(ReportFiles.JUNIT));
        assertTrue(junit.contains("B-COGS-001 [semantic, fuzzylite layout]"), "junit.xml has the semantic testcases");
    }

    @Test
    void withoutAPresentationTheReportHasOneAxis(@TempDir Path out) throws Exception {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        Report report = Certification.run(Certification.Request.builder("reference", corpus)
                .selection(new CaseSelection(Set.of(), Set.of(), List.of("B-COGS-001"))).outDir(out).build(),
                RunListener.NONE).report();
        assertNull(report.semantic());
        assertNull(report.cases().get(0).presented());
        assertTrue(report.features().stream().allMatch(f -> f.semantic() == null));
        assertTrue(!Files.readString(out.resolve(ReportFiles.JSON)).contains("\"semantic\""));
    }
}
