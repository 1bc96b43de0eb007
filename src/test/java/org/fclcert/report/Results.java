package org.fclcert.report;

import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.harness.PlannedCase;
import org.fclcert.harness.RunHeader;

/** Hand-made results and headers for report tests. */
final class Results {
    private Results() {
    }

    static CaseResult result(String id, String level, CaseStatus status, List<String> tests, String... flags) {
        boolean bad = status != CaseStatus.PASSED;
        return new CaseResult(new PlannedCase(id, "title of " + id, level, tests, List.of(flags)),
                new CaseResult.Verdict(status,
                        bad ? "step 1 of 1: y = 1.0 where 2.0 is expected" : "1 step(s) within tolerance", List.of(), null),
                new CaseResult.Evidence(bad ? new CaseResult.Step(1, Map.of("x", 0.5)) : null,
                        bad ? new CaseResult.Mismatch.Outputs(Map.of("y", 2.0), Map.of("y", 1.0)) : null,
                        status == CaseStatus.ERRORED ? "crashed\n--- stderr ---\nSegmentation fault" : null, 0.0),
                new CaseResult.Export(ExportStatus.UNSUPPORTED, null),
                new CaseResult.Setup(null, "exact", bad ? "FUNCTION_BLOCK fb\n  (* x < y & z *)\nEND_FUNCTION_BLOCK" : null, 3L));
    }

    static RunHeader header(int basicCasesInCorpus, List<CaseResult> planned, List<String> claims) {
        return new RunHeader(
                new RunHeader.Iut("Fake <FLC>", "0.1", "python3 fake.py", "process:python3 fake.py", null, claims,
                        Map.of()),
                new RunHeader.Toolkit("0.1.0-test"),
                new RunHeader.CorpusInfo("src/test/resources/corpus-mini", planned.size(), "00ff", basicCasesInCorpus),
                new RunHeader.Selection(List.of(), List.of(), List.of(),
                        planned.stream().map(c -> new PlannedCase(c.id(), c.title(), c.level(), c.tests(), c.flags()))
                                .toList()),
                "2026-11-22T04:00:00Z");
    }
}
