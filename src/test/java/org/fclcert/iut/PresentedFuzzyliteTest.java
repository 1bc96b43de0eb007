package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.PresentedStatus;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;
import org.fclcert.orchestration.PresentAs;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The semantic axis on the real fuzzylite 6.0: the cases it rejects in the standard's layout are sent in its own
 * layout, and it computes otherwise than the standard. The expected deviations are worked out by hand (the
 * numbers are in each case's derivation): fuzzylite's CoGS sums per rule, not per term; its WITH folds the weight
 * into the degree before MIN activation.
 */
class PresentedFuzzyliteTest {
    private static final List<String> CASES = List.of("B-COGS-001", "E-WITH-CONST-001", "N-S002-001");

    @Test
    void fuzzyliteInItsOwnLayoutShowsItsSemanticDeviations(@TempDir Path out) throws Exception {
        Fuzzylite.assumeInstalled();
        Certification.Request request = Certification.Request.builder("fuzzylite", Corpus.load(Path.of("conformance")))
                .options(Fuzzylite.options()).corpusName("conformance")
                .selection(new CaseSelection(Set.of(), Set.of(), CASES)).outDir(out).build();
        assertEquals(PresentAs.AUTO, request.presentAs(), "auto is the default");
        Report report = Certification.run(request, RunListener.NONE).report();
        Map<String, CaseResult> byId = report.cases().stream()
                .collect(Collectors.toMap(CaseResult::id, Function.identity()));

        // language axis unchanged: the standard's text (sent disguised, so its lines move) is rejected at 'METHOD: CoGS;'
        CaseResult cogs = byId.get("B-COGS-001");
        assertEquals(CaseStatus.FAILED, cogs.status());
        assertTrue(cogs.message().startsWith("rejected a program the standard accepts at line ")
                && cogs.message().endsWith("in line: METHOD: CoGS"), cogs.message());

        // semantic axis: t=5, p=60 has R1 7/8, R2 1/8, R3 1/12, R4 1/12; per term (closed = max(1/8, 1/12))
        // (87.5 - 100/12) / (13/12) = 950/13 = 73.077; fuzzylite sums every rule's degree: (950/12) / (14/12) = 67.857
        CaseResult.Presented p = cogs.presented();
        assertNotNull(p, "a positive case is presented");
        assertEquals("fuzzylite", p.dialect());
        assertEquals(PresentedStatus.FAILED, p.status(), p.message());
        assertEquals(1, p.evidence().step().number());
        CaseResult.Mismatch.Outputs values = (CaseResult.Mismatch.Outputs) p.evidence().mismatch();
        assertEquals(950.0 / 13, values.expected().get("valve"), 1e-12);
        assertEquals(950.0 / 14, values.actual().get("valve"), 1e-9);
        assertNotNull(p.program(), "the written text of a failed presentation is kept");
        assertTrue(p.program().contains("COGS"), p.program());
        // the reference's trace at that step says why: closed takes max(1/8, 1/12), not their sum
        assertEquals(List.of("rules fired: RULE 1 at 0.875 → valve IS inlet; RULE 2 at 0.125 → valve IS closed;"
                + " RULE 3 at 0.0833333 → valve IS closed; RULE 4 at 0.0833333 → valve IS drainage",
                "valve = 73.0769, defuzzified from the singletons -100 (degree 0.0833333), 0 (degree 0.125),"
                + " 100 (degree 0.875)"), p.evidence().reference().lines());

        // WITH 0.5 then MIN: 0.5*ta (area 10 at 20) and tb clipped at 0.5 (area 15 at 80): CoG 1400/25 = 56;
        // fuzzylite clips ta at 0.5*1 (a trapezoid of area 15): (300 + 1200)/30 = 50 (its CoG samples the set)
        CaseResult.Presented w = byId.get("E-WITH-CONST-001").presented();
        assertEquals(PresentedStatus.FAILED, w.status(), w.message());
        CaseResult.Mismatch.Outputs wv = (CaseResult.Mismatch.Outputs) w.evidence().mismatch();
        assertEquals(56.0, wv.expected().get("y"), 1e-12);
        assertEquals(50.0, wv.actual().get("y"), 0.05);

        // negative cases stay on the language axis only
        assertEquals(null, byId.get("N-S002-001").presented());

        // a run of a few cases decides no row on either axis (issue 29): not determined, with what failed
        Report.FeatureRow cogsRow = row(report, "B-COGS");
        assertEquals(FeatureStatus.NOT_DETERMINED, cogsRow.status());
        assertEquals(List.of("B-COGS-001"), cogsRow.notPassed());
        assertEquals(FeatureStatus.NOT_DETERMINED, cogsRow.semantic().status());
        assertEquals(0, cogsRow.semantic().passed());
        assertEquals(1, cogsRow.semantic().total());
        assertEquals(FeatureStatus.NOT_DETERMINED, row(report, "E-WITH-CONST").semantic().status());
        assertEquals("fuzzylite", report.semantic().presentAs());
        assertEquals(2, report.semantic().cases());
        assertEquals(2, report.semantic().failed());

        // report --from rebuilds both axes from results.jsonl
        java.nio.file.Files.createDirectories(out.resolve("again"));
        Report again = Certification.rebuildReports(ResultsFile.read(out.resolve(Certification.RESULTS)),
                out.resolve("again"));
        assertEquals(report.semantic(), again.semantic());
        assertEquals(cogsRow.semantic(), row(again, "B-COGS").semantic());
        CaseResult.Presented back = again.cases().stream().filter(c -> c.id().equals("B-COGS-001")).findFirst()
                .orElseThrow().presented();
        assertEquals(values, back.evidence().mismatch());
        assertEquals(p.evidence().reference(), back.evidence().reference());
    }

    private static Report.FeatureRow row(Report r, String id) {
        return r.features().stream().filter(f -> f.id().equals(id)).findFirst().orElseThrow();
    }
}
