package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
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
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A certification of the real fuzzylite over a handful of corpus cases, through the same {@link Certification}
 * API the command line uses. The statuses were checked by hand against fuzzylite's output on the case files.
 */
class FuzzyliteCertificationTest {
    private static final List<String> CASES = List.of(
            "B-ACCU-MAX-001", "B-COGS-001", "B-ONE-RULEBLOCK-002", "N-C016-001", "N-S002-001", "N-S012-001");

    @Test
    void standardProgramsAreRejectedForFuzzylitesDialectAndNegativeCasesPassOnlyAsRejections(@TempDir Path out)
            throws Exception {
        Fuzzylite.assumeInstalled();
        Certification.Request request = Certification.Request.builder("fuzzylite", Corpus.load(Path.of("conformance")))
                .options(Fuzzylite.options()).corpusName("conformance")
                .selection(new CaseSelection(Set.of(), Set.of(), CASES)).outDir(out)
                // the library's own reaction to the corpus text as written (its lines, its messages): no disguise
                .freshEvidence(false).build();
        Report report = Certification.run(request, RunListener.NONE).report();
        Map<String, CaseResult> byId = report.cases().stream()
                .collect(Collectors.toMap(CaseResult::id, Function.identity()));
        assertEquals(Set.copyOf(CASES), byId.keySet());
        assertEquals("fuzzylite", report.iut().name());
        assertEquals("6.0", report.iut().version());

        // METHOD : CoGS, written as Table 1 spells it, is no defuzzifier fuzzylite knows (it wants COGS); no line
        CaseResult accuMax = byId.get("B-ACCU-MAX-001");
        assertEquals(CaseStatus.FAILED, accuMax.status());
        assertEquals("rejected a program the standard accepts: fuzzylite: [factory error] constructor of "
                + "Defuzzifier <CoGS> not registered", accuMax.message());

        // 'METHOD: CoGS;' without a blank before the colon stops the reader at line 54, which it quotes
        CaseResult cogs = byId.get("B-COGS-001");
        assertEquals(CaseStatus.FAILED, cogs.status());
        assertTrue(cogs.message().startsWith("rejected a program the standard accepts at line 54: fuzzylite: "
                + "[syntax error] unexpected token <METHOD:>"), cogs.message());

        // a (* *) comment is "unknown block definition"; fuzzylite numbers that line itself (25)
        CaseResult comments = byId.get("B-ONE-RULEBLOCK-002");
        assertEquals(CaseStatus.FAILED, comments.status());
        assertTrue(comments.message().startsWith("rejected a program the standard accepts at line 25: fuzzylite: "
                + "[syntax error] unknown block definition <(*>"), comments.message());

        // a DEFUZZIFY without METHOD (error at line 26) is rejected, but for ACCU inside the rule block (line 34)
        CaseResult noMethod = byId.get("N-C016-001");
        assertEquals(CaseStatus.PASSED, noMethod.status());
        assertEquals(List.of("the implementation reports line 34; the error (FCL-C016) is at line 26"), noMethod.verdict().notes());
        assertEquals(org.fclcert.harness.RejectionPlace.OTHER_LINE, noMethod.verdict().rejection());

        // an unclosed comment (line 42): "passes", but fuzzylite never got there - it refused CoGS, naming no line
        CaseResult unclosed = byId.get("N-S002-001");
        assertEquals(CaseStatus.PASSED, unclosed.status());
        assertEquals("rejected: fuzzylite: [factory error] constructor of Defuzzifier <CoGS> not registered",
                unclosed.message());
        assertEquals(List.of("the implementation gave no line for its rejection; the error is at line 42"),
                unclosed.verdict().notes());
        assertEquals(org.fclcert.harness.RejectionPlace.UNLOCATED, unclosed.verdict().rejection());

        // FUZZIFY temp never closed: rejected where the next FUZZIFY starts (line 21), the case's line
        CaseResult unclosedBlock = byId.get("N-S012-001");
        assertEquals(CaseStatus.PASSED, unclosedBlock.status());
        assertTrue(unclosedBlock.message().startsWith("rejected at line 21: fuzzylite: [syntax error] expected "
                + "<END_FUZZIFY> before <FUZZIFY>"), unclosedBlock.message());
        assertEquals(List.of(), unclosedBlock.verdict().notes());

        assertFalse(report.basicLevel().conformant());
        assertTrue(report.features().stream().filter(r -> r.table() == 9).noneMatch(r -> r.passed() > 0));
        assertTrue(Files.isRegularFile(out.resolve("report.md")));
        assertTrue(Files.readString(out.resolve("report.md")).startsWith("# FCL compliance statement: fuzzylite 6.0"));
    }
}
