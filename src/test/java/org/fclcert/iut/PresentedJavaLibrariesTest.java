package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.PresentedStatus;
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The semantic axis on the real Java libraries, each in its own layout ({@code --present-as auto}): jfuzzylite
 * (test class path) shares fuzzylite's deviations; jFuzzyLogic (the unmodified build of ../shared) computes NSUM
 * as BSUM. Expected values by hand, from the cases' derivations.
 */
class PresentedJavaLibrariesTest {

    private static Map<String, CaseResult> certify(String spec, Path out, List<String> cases) throws Exception {
        Certification.Request request = Certification.Request.builder(spec, Corpus.load(Path.of("conformance")))
                .options(IutOptions.defaults().withTimeout(Duration.ofSeconds(20))).corpusName("conformance")
                .selection(new CaseSelection(Set.of(), Set.of(), cases)).outDir(out).build();
        Report report = Certification.run(request, RunListener.NONE).report();
        return report.cases().stream().collect(Collectors.toMap(CaseResult::id, Function.identity()));
    }

    private static double actual(CaseResult c, String output) {
        return ((CaseResult.Mismatch.Outputs) c.presented().evidence().mismatch()).actual().get(output);
    }

    @Test
    void jfuzzyliteSumsCogsPerRuleAndFoldsTheWeightBeforeMin(@TempDir Path out) throws Exception {
        Map<String, CaseResult> byId = certify("jfuzzylite", out, List.of("B-COGS-001", "E-WITH-CONST-001"));
        CaseResult cogs = byId.get("B-COGS-001");
        assertEquals("fuzzylite", cogs.presented().dialect());
        assertEquals(PresentedStatus.FAILED, cogs.presented().status(), cogs.presented().message());
        // t=5, p=60: the rules' degrees 7/8 + 1/8 + 1/12 + 1/12 = 14/12 in the denominator, not 13/12 per term
        assertEquals(950.0 / 14, actual(cogs, "valve"), 1e-9);
        CaseResult with = byId.get("E-WITH-CONST-001");
        assertEquals(PresentedStatus.FAILED, with.presented().status());
        // min(0.5 * 1, ta): a trapezoid of area 15 at 20 beside tb's 15 at 80 -> 50 (sampled), not 56
        assertEquals(50.0, actual(with, "y"), 0.05);
    }

    @Test
    void jfuzzylogicComputesNsumAsBsumInItsOwnLayout(@TempDir Path out) throws Exception {
        Map<String, CaseResult> byId = certify(JFuzzyLogic.spec(), out, List.of("E-ACCU-NSUM-001", "B-COGS-001"));
        CaseResult nsum = byId.get("E-ACCU-NSUM-001");
        assertEquals("jfuzzylogic", nsum.presented().dialect());
        assertEquals(PresentedStatus.FAILED, nsum.presented().status(), nsum.presented().message());
        // a=0.8 b=0.7 c=0.5: bounded sums zero = 1, full = 0.5 -> 50/1.5 = 33.333 (NSUM: 1 and 1/3 -> 25)
        assertEquals(100.0 / 3, actual(nsum, "y"), 1e-9);
        // B-COGS-001 it computes as the standard does in its own layout
        assertEquals(PresentedStatus.PASSED, byId.get("B-COGS-001").presented().status(),
                byId.get("B-COGS-001").presented().message());
    }
}
