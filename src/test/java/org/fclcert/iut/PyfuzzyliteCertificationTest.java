package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code certify --iut pyfuzzylite --case ...} on four cases: the standard text is refused by pyfuzzylite's FLL importer
 * (a negative case fails: its accepted twin, the defect repaired, is refused as well), and on the semantic axis ({@code --present-as auto}, FLL) B-COGS-001
 * passes while E-ACCU-NSUM-002 fails with pyfuzzylite's pairwise NormalizedSum: 49.719 where the case's hand-derived
 * value is 49.130, and E-COG-002 with its sampled CoG missing a term 0.001 wide (the DEFAULT 7 for 40.0004).
 */
class PyfuzzyliteCertificationTest {
    @Test
    void aFewCasesPassAndFailWithPyfuzzylitesOwnValues(@TempDir Path dir) throws Exception {
        Pyfuzzylite.assumeInstalled();
        List<String> ids = List.of("B-COGS-001", "E-ACCU-NSUM-002", "E-COG-002", "N-C001-001");
        Report report = Certification.run(Certification.Request.builder("pyfuzzylite", Corpus.load(Path.of("conformance")))
                .selection(new CaseSelection(Set.of(), Set.of(), ids)).outDir(dir).build(), RunListener.NONE).report();
        Map<String, CaseResult> byId = report.cases().stream().collect(Collectors.toMap(CaseResult::id,
                Function.identity()));
        assertEquals(Set.copyOf(ids), byId.keySet());
        assertEquals("fll", report.semantic().presentAs());
        CaseResult cogs = byId.get("B-COGS-001");
        assertEquals(CaseStatus.FAILED, cogs.status(), "standard FCL is refused: " + cogs.message());
        assertTrue(cogs.message().contains("FllImporter"), cogs.message());
        assertEquals(PresentedStatus.PASSED, cogs.presentedResult().orElseThrow().status());
        CaseResult.Presented nsum = byId.get("E-ACCU-NSUM-002").presentedResult().orElseThrow();
        assertEquals(PresentedStatus.FAILED, nsum.status());
        assertTrue(nsum.message().contains("y = 49.7191") && nsum.message().contains("49.1304"), nsum.message());
        CaseResult.Presented cog = byId.get("E-COG-002").presentedResult().orElseThrow();
        assertEquals(PresentedStatus.FAILED, cog.status());
        assertTrue(cog.message().contains("y = 7.0 where 40.0004"), cog.message());
        // its refusal is of FCL itself, not of the planted error: the case's accepted twin is refused as well
        CaseResult negative = byId.get("N-C001-001");
        assertEquals(CaseStatus.FAILED, negative.status(), negative.message());
        assertTrue(negative.message().contains("rejected the case's accepted twin"), negative.message());
    }
}
