package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;
import org.fclcert.report.Causes;
import org.fclcert.report.Report;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Certifications of the real jfuzzylite 6.0.1 (the whole corpus, about 3 s) and jFuzzyLogic (a handful of cases
 * in its child JVM) through the {@link Certification} API the command line uses. Expected values come from the
 * cases' own hand derivations, which name what a left-to-right AND/OR or a BSUM in place of NSUM would give.
 */
class LibraryCertificationTest {

    private static Report certify(String spec, List<String> cases, Path out) throws Exception {
        Certification.Request request = Certification.Request.builder(spec, Corpus.load(Path.of("conformance")))
                .options(IutOptions.defaults().withTimeout(Duration.ofSeconds(20))).corpusName("conformance")
                .selection(new CaseSelection(Set.of(), Set.of(), cases)).outDir(out)
                // the library's own reaction to the corpus text as written (its lines, its messages): no disguise
                .freshEvidence(false).build();
        return Certification.run(request, RunListener.NONE).report();
    }

    private static Map<String, CaseResult> byId(Report report) {
        return report.cases().stream().collect(Collectors.toMap(CaseResult::id, Function.identity()));
    }

    private static Causes.Cause cause(Report report, String text) {
        return report.causes().stream().filter(c -> c.cause().equals(text)).findFirst()
                .orElseThrow(() -> new AssertionError("no cause '" + text + "' in " + report.causes()));
    }

    @Test
    void jfuzzyliteRejectsEveryPositiveCaseAtLoadForReasonsOfItsDialect(@TempDir Path out) throws Exception {
        Report report = certify("jfuzzylite", List.of(), out);
        assertEquals("jfuzzylite", report.iut().name());
        assertEquals("6.0.1", report.iut().version());
        Map<String, CaseResult> cases = byId(report);
        Corpus corpus = Corpus.load(Path.of("conformance"));
        Set<String> inDialect = corpus.cases().stream().filter(c -> c.dialect() != Dialect.STRICT)
                .map(CorpusCase::id).collect(Collectors.toSet());
        assertFalse(inDialect.isEmpty());
        List<CaseResult> positive = report.cases().stream()
                .filter(c -> !c.id().startsWith("N-") && !inDialect.contains(c.id())).toList();
        assertEquals(corpus.cases().stream().filter(c -> !c.expectReject() && c.dialect() == Dialect.STRICT).count(),
                positive.size());
        // the cases written in fuzzylite's FCL are sent as written, and jfuzzylite loads them: every one of them is
        // run (none rejected for its syntax); those in another library's dialect are not sent
        Set<String> inFuzzylite = corpus.cases().stream().filter(c -> c.dialect() == Dialect.FUZZYLITE)
                .map(CorpusCase::id).collect(Collectors.toSet());
        assertFalse(inFuzzylite.isEmpty());
        assertTrue(inFuzzylite.stream().map(cases::get).noneMatch(c -> c.status() == CaseStatus.SKIPPED
                || c.message().startsWith("rejected a program") && c.message().contains("syntax error")),
                inFuzzylite.stream().map(cases::get).map(c -> c.id() + ": " + c.message()).toList().toString());
        // as measured by hand with jfuzzylite on the case files: not one positive case in standard FCL loads
        assertTrue(positive.stream().allMatch(c -> c.status() == CaseStatus.FAILED
                && c.message().startsWith("rejected a program the standard accepts")),
                () -> positive.stream().filter(c -> c.status() != CaseStatus.FAILED).map(CaseResult::id).toList().toString());
        assertEquals(0, report.summary().errored());
        assertFalse(report.basicLevel().conformant());

        // the causes are what jfuzzylite said. B-ACCU-MAX-001 writes Table 1's 'METHOD : CoGS;', which jfuzzylite has
        // not registered (it wants COGS)
        assertTrue(cause(report, "jfuzzylite: [construction error] constructor <CoGS> not registered in"
                + " DefuzzifierFactory").cases().contains("B-ACCU-MAX-001"));
        // E-VAR-LOCAL-001 declares 'VAR_OUTPUT y : REAL; END_VAR' on one line; the group quotes its first case
        Causes.Cause oneLine = report.causes().get(0);
        assertTrue(oneLine.cause().startsWith("jfuzzylite: [syntax error] expected <END_VAR> before <VAR_OUTPUT> in line:"),
                "the largest group comes first: " + oneLine);
        assertTrue(oneLine.cases().contains("E-VAR-LOCAL-001"), oneLine.toString());
        assertTrue(cases.get("E-VAR-LOCAL-001").message().contains("expected <END_VAR> before <VAR_OUTPUT>"));
        assertTrue(Files.readString(out.resolve("report.md")).contains("## Failures by cause"));
    }

    @Test
    void jFuzzyLogicComputesAndOrLeftToRightNsumAsBsumAndCrashesOnABareVariable(@TempDir Path out) throws Exception {
        String spec = JFuzzyLogic.spec();
        List<String> ids = List.of("B-ACCU-MAX-001", "E-OR-MAX-001", "E-ACCU-NSUM-001", "E-COND-VARIABLE-001",
                "N-C016-001", "N-S012-001");
        Report report = certify(spec, ids, out);
        Map<String, CaseResult> cases = byId(report);
        assertEquals("jFuzzyLogic", report.iut().name());

        assertEquals(CaseStatus.PASSED, cases.get("B-ACCU-MAX-001").status());
        // 'a OR b AND c' at a=0.8 b=0.3 c=0.1 k=1: the standard's a OR (b AND c) = 0.8 gives 80/1.8; left to right
        // (a OR b) AND c = 0.1 gives 10/1.1 = 9.0909 (the case's own derivation)
        CaseResult orMax = cases.get("E-OR-MAX-001");
        assertEquals(CaseStatus.FAILED, orMax.status());
        assertEquals(100 * 0.1 / 1.1, ((Map<?, ?>) orMax.mismatch().orElseThrow().actual()).get("y"));
        // NSUM at a=0.8 b=0.7 c=0.5: the standard 25; BSUM clips zero's 1.5 to 1: 50/1.5 = 33.33 (the derivation)
        CaseResult nsum = cases.get("E-ACCU-NSUM-001");
        assertEquals(CaseStatus.FAILED, nsum.status());
        assertEquals(100.0 / 3, (Double) ((Map<?, ?>) nsum.mismatch().orElseThrow().actual()).get("y"), 1e-9);
        // a bare variable as a condition: a NullPointerException in its tree walker, errored, not a rejection
        CaseResult bare = cases.get("E-COND-VARIABLE-001");
        assertEquals(CaseStatus.ERRORED, bare.status());
        assertTrue(bare.message().contains("NullPointerException"), bare.message());
        // a DEFUZZIFY without METHOD is accepted (it defaults to CoG)
        assertEquals(CaseStatus.FAILED, cases.get("N-C016-001").status());
        // an unclosed FUZZIFY: the parse error it prints (and recovers from) is the rejection, at the case's line
        CaseResult unclosed = cases.get("N-S012-001");
        assertEquals(CaseStatus.PASSED, unclosed.status());
        assertTrue(unclosed.message().startsWith("rejected at line 21: jFuzzyLogic printed a parse error"), unclosed.message());

        assertEquals(List.of("E-COND-VARIABLE-001"), cause(report,
                "crashed: NullPointerException in net.sourceforge.jFuzzyLogic.rule.RuleBlock.fclTreeRuleBlockRuleIf:263").cases());
        assertEquals(List.of("E-ACCU-NSUM-001"), cause(report, "E-ACCU-NSUM (ACCU with the NSUM algorithm): wrong value").cases());
    }
}
