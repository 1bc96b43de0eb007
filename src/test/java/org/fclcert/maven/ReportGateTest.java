package org.fclcert.maven;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.PlannedCase;
import org.fclcert.harness.RunHeader;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;
import org.junit.jupiter.api.Test;

/** The decision of fclcert:verify on a reproduction: `mvn verify -Dfclcert.cases=ID` is judged by its cases. */
class ReportGateTest {
    private static Report run(List<String> casesSelected, CaseStatus status) {
        CaseResult r = new CaseResult(new PlannedCase("E-ACCU-NSUM-002", "t", "extension", List.of("E-ACCU-NSUM"),
                List.of()), new CaseResult.Verdict(status, "m", List.of(), null), null, null, null);
        RunHeader header = new RunHeader(new RunHeader.Iut("Vendor FCL", "1", "c", "java:V", null,
                List.of("E-ACCU-NSUM"), Map.of()), new RunHeader.Toolkit("t"),
                new RunHeader.CorpusInfo("bundled", 193, "00", 90),
                new RunHeader.Selection(List.of(), List.of(), casesSelected, List.of(r.plan())), "2026-01-01T00:00:00Z");
        return ReportBuilder.build(header, List.of(r), List.of(), List.of(), Instant.EPOCH);
    }

    @Test
    void aReproducedCaseThatNowPassesMeetsTheGateThoughNoLevelVerdictCanComeFromIt() {
        Report fixed = run(List.of("E-ACCU-NSUM-002"), CaseStatus.PASSED);
        assertTrue(!fixed.basicLevel().conformant(), "one case is no Basic Level verdict");
        for (ReportGate.FailOn failOn : ReportGate.FailOn.values()) {
            assertEquals(Optional.empty(), ReportGate.failure(fixed, failOn, List.of()), failOn.name());
        }
    }

    @Test
    void aReproducedCaseThatStillFailsFailsTheGateNamingIt() {
        Report still = run(List.of("E-ACCU-NSUM-002"), CaseStatus.FAILED);
        assertEquals(Optional.of("1 of the 1 case(s) selected by fclcert.cases did not pass: E-ACCU-NSUM-002 failed"),
                ReportGate.failure(still, ReportGate.FailOn.BASIC, List.of()));
        assertEquals(Optional.empty(), ReportGate.failure(still, ReportGate.FailOn.NONE, List.of()));
    }

    @Test
    void aWholeRunIsJudgedOnTheLevels() {
        Report whole = run(List.of(), CaseStatus.PASSED);
        // one case of the corpus's 90 Basic ones ran: the verdict is not determined, and the gate says so
        assertEquals(Optional.of("Basic Level not determined (0 of 90 run)"),
                ReportGate.failure(whole, ReportGate.FailOn.BASIC, List.of()));
    }
}
