package org.fclcert.report;

import static org.fclcert.report.Results.header;
import static org.fclcert.report.Results.result;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RejectionPlace;
import org.fclcert.model.Feature;
import org.junit.jupiter.api.Test;

class ReportBuilderTest {
    static final List<CaseResult> RUN = List.of(
            result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")),
            result("B-COGS-002", "basic", CaseStatus.FAILED, List.of("B-COGS")),
            result("B-AND-MIN-001", "basic", CaseStatus.PASSED, List.of("B-AND-MIN")),
            result("E-NOT-001", "extension", CaseStatus.FAILED, List.of("E-NOT")),
            result("E-NOT-002", "extension", CaseStatus.ERRORED, List.of("E-NOT", "E-PARENS")),
            result("E-COG-001", "extension", CaseStatus.PASSED, List.of("E-COG")),
            result("E-COG-INT-001", "extension", CaseStatus.FAILED, List.of("E-COG"), "interpretation:3"));
    static final CaseResult NEVER_RAN = result("B-DEFAULT-NC-001", "basic", CaseStatus.PASSED, List.of("B-DEFAULT-NC"),
            "stateful");

    static Report report(List<String> claims) {
        List<CaseResult> planned = new ArrayList<>(RUN);
        planned.add(NEVER_RAN);
        return ReportBuilder.build(header(4, planned, claims), RUN, List.of(), List.of(), Instant.EPOCH);
    }

    static Report.FeatureRow row(Report r, String id) {
        return r.features().stream().filter(f -> f.id().equals(id)).findFirst().orElseThrow();
    }

    @Test
    void everyCatalogueFeatureHasARowWithItsTable() {
        Report r = report(List.of());
        assertEquals(Arrays.stream(Feature.values()).filter(f -> !f.dialectSyntax()).map(Feature::id).toList(),
                r.features().stream().map(Report.FeatureRow::id).toList());
        assertEquals(8, row(r, "B-COGS").table());
        assertEquals(9, row(r, "E-NOT").table());
        assertEquals(10, row(r, "O-MANY-POINTS").table());
    }

    @Test
    void rowsAreRealisedPartialNotRealisedOrNotTested() {
        Report r = report(List.of());
        assertEquals(FeatureStatus.PARTIAL, row(r, "B-COGS").status());
        assertEquals(List.of("B-COGS-001", "B-COGS-002"), row(r, "B-COGS").cases());
        assertEquals(List.of("B-COGS-002"), row(r, "B-COGS").notPassed());
        assertEquals(FeatureStatus.REALISED, row(r, "B-AND-MIN").status());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "E-NOT").status());
        assertEquals(1, row(r, "E-NOT").failed());
        assertEquals(1, row(r, "E-NOT").errored());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "E-PARENS").status());
        assertEquals(FeatureStatus.NOT_TESTED, row(r, "E-ACCU-NSUM").status());
        // the failing interpretation case is not held against E-COG
        assertEquals(FeatureStatus.REALISED, row(r, "E-COG").status());
        assertEquals(List.of("E-COG-001"), row(r, "E-COG").cases());
        // the planned case that never ran is a skip, which never counts as passed
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "B-DEFAULT-NC").status());
        assertEquals(1, row(r, "B-DEFAULT-NC").skipped());
    }

    @Test
    void summaryCountsEveryCaseAndTheUnrunOneAsSkipped() {
        Report r = report(List.of());
        assertEquals(new Report.Summary(8, 3, 3, 1, 1), r.summary());
        assertFalse(r.run().complete());
        CaseResult last = r.cases().get(7);
        assertEquals("B-DEFAULT-NC-001", last.id());
        assertEquals(CaseStatus.SKIPPED, last.status());
    }

    @Test
    void interpretationCasesAreListedApart() {
        Report r = report(List.of());
        assertEquals(List.of(new Report.InterpretationEntry("E-COG-INT-001", "title of E-COG-INT-001",
                "interpretation:3", "failed", "step 1 of 1: y = 1.0 where 2.0 is expected", null)), r.interpretation());
    }

    @Test
    void basicLevelNeedsEveryBasicCaseOfTheCorpusToPass() {
        Report r = report(List.of());
        assertFalse(r.basicLevel().conformant());
        assertEquals("2 of 4 Basic Level cases did not pass: B-COGS-002, B-DEFAULT-NC-001", r.basicLevel().reason());

        List<CaseResult> allPass = List.of(result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")),
                result("B-AND-MIN-001", "basic", CaseStatus.PASSED, List.of("B-AND-MIN")));
        Report partialRun = ReportBuilder.build(header(3, allPass, List.of()), allPass, List.of(), List.of(),
                Instant.EPOCH);
        assertFalse(partialRun.basicLevel().conformant(), "2 of the corpus's 3 Basic cases is not enough");
        assertEquals("only 2 of the corpus's 3 Basic Level cases were run", partialRun.basicLevel().reason());

        Report whole = ReportBuilder.build(header(2, allPass, List.of()), allPass, List.of(), List.of(), Instant.EPOCH);
        assertTrue(whole.basicLevel().conformant());
        assertEquals("all 2 Basic Level cases passed", whole.basicLevel().reason());
    }

    @Test
    void claimsAreComparedWithTheMeasurements() {
        Report.Claims c = report(List.of("E-NOT", "e-cog", "X-HEDGES", "E-ACCU-NSUM")).claims();
        assertEquals(List.of("E-COG"), c.confirmed());
        assertEquals(List.of("E-NOT (not realised)"), c.notRealised());
        assertEquals(List.of("E-ACCU-NSUM"), c.untested(), "no case of it ran: not held against the claim");
        assertEquals(List.of("X-HEDGES"), c.unknown());
        assertEquals(List.of(), c.unclaimed());
        assertEquals(List.of("E-COG"), report(List.of()).claims().unclaimed());
    }

    @Test
    void failOnConditions() {
        Report r = report(List.of("E-COG"));
        assertTrue(FailOn.NONE.holds(r));
        assertFalse(FailOn.BASIC.holds(r));
        assertFalse(FailOn.CLAIMED.holds(r));
        assertFalse(FailOn.ANY.holds(r));
        List<CaseResult> allPass = List.of(result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")),
                result("E-NOT-001", "extension", CaseStatus.FAILED, List.of("E-NOT")));
        Report basicOnly = ReportBuilder.build(header(1, allPass, List.of("E-NOT")), allPass, List.of(), List.of(),
                Instant.EPOCH);
        assertTrue(FailOn.BASIC.holds(basicOnly));
        Report untestedClaim = ReportBuilder.build(header(1, allPass.subList(0, 1), List.of("E-NOT")),
                allPass.subList(0, 1), List.of(), List.of(), Instant.EPOCH);
        assertTrue(FailOn.CLAIMED.holds(untestedClaim), "a claim without a case in the run is not refuted");
        assertFalse(FailOn.CLAIMED.holds(basicOnly));
        assertEquals("claimed but not realised: E-NOT (not realised)", FailOn.CLAIMED.explain(basicOnly));
    }

    @Test
    void negativeCasesAreCountedByWhereTheRejectionWasPlaced() {
        List<CaseResult> run = List.of(rejected("N-C002-001", RejectionPlace.AT_ERROR_LINE),
                rejected("N-C002-002", RejectionPlace.OTHER_LINE), rejected("N-S002-001", RejectionPlace.UNLOCATED),
                rejected("N-S003-001", RejectionPlace.UNLOCATED), result("B-COGS-001", "basic", CaseStatus.PASSED,
                        List.of("B-COGS")));
        Report r = ReportBuilder.build(header(5, run, List.of()), run, List.of(), List.of(), Instant.EPOCH);
        assertEquals(new Report.Rejections(4, 1, 1, 2), r.rejections());
        assertEquals("4 negative case(s) rejected: 1 at the error's line, 1 at another line, 2 without a line",
                r.rejections().sentence());
        assertTrue(r.rejections().doubtful());
        assertTrue(MarkdownReport.render(r).contains("- Negative cases: 4 negative case(s) rejected: 1 at the error's"
                + " line, 1 at another line, 2 without a line (a rejection at another line"));
        assertFalse(report(List.of()).rejections().doubtful(), "no negative case: nothing to doubt");
    }

    private static CaseResult rejected(String id, RejectionPlace place) {
        CaseResult r = result(id, "basic", CaseStatus.PASSED, List.of());
        return new CaseResult(r.plan(), new CaseResult.Verdict(r.status(), "rejected", List.of(), place),
                new CaseResult.Evidence(null, new CaseResult.Mismatch.Sentences("reject", "rejected"), null, null),
                r.export(), new CaseResult.Setup(null, "exact", null, 1L));
    }
}
