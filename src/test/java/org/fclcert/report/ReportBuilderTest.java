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
import org.fclcert.harness.RunHeader;
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
        // the planned case that never ran is a skip: it never counts as passed, and the row is not decided without it
        assertEquals(FeatureStatus.NOT_TESTED, row(r, "B-DEFAULT-NC").status());
        assertEquals(1, row(r, "B-DEFAULT-NC").skipped());
        assertEquals("not tested (0 of 1 run)", row(r, "B-DEFAULT-NC").sentence());
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
        // B-DEFAULT-NC-001 never ran: only the Basic case that ran and failed decides, and the reason says what ran
        assertEquals("1 of 3 Basic Level cases run did not pass: B-COGS-002; 3 of 4 run", r.basicLevel().reason());
        assertEquals(Report.BasicLevel.NOT_CONFORMANT, r.basicLevel().verdict());

        List<CaseResult> allPass = List.of(result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")),
                result("B-AND-MIN-001", "basic", CaseStatus.PASSED, List.of("B-AND-MIN")));
        Report partialRun = ReportBuilder.build(header(3, allPass, List.of()), allPass, List.of(), List.of(),
                Instant.EPOCH);
        assertFalse(partialRun.basicLevel().conformant(), "2 of the corpus's 3 Basic cases is not enough");
        assertEquals("not determined (2 of 3 run)", partialRun.basicLevel().sentence());

        Report whole = ReportBuilder.build(header(2, allPass, List.of()), allPass, List.of(), List.of(), Instant.EPOCH);
        assertTrue(whole.basicLevel().conformant());
        assertEquals("conformant (all 2 Basic Level cases passed)", whole.basicLevel().sentence());
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

    /**
     * The vendor's report of issue 29: every Basic case passed, and an Extension case that also tests B-DEFAULT-VALUE
     * was rejected for its RANGE. The Basic row is not held to it, so "conformant" never sits beside a partial Table 8
     * row or a "claimed but not realised" Basic feature; the row names the case it did not count and why.
     */
    @Test
    void anExtensionCaseNeverCountsAgainstABasicRow() {
        List<CaseResult> run = List.of(result("B-DEFAULT-VALUE-001", "basic", CaseStatus.PASSED, List.of("B-DEFAULT-VALUE")),
                result("E-RANGE-004", "extension", CaseStatus.FAILED, List.of("E-RANGE", "B-DEFAULT-VALUE")));
        Report r = ReportBuilder.build(header(1, run, List.of("B-DEFAULT-VALUE", "E-RANGE")), run, List.of(), List.of(),
                Instant.EPOCH);
        assertTrue(r.basicLevel().conformant());
        Report.FeatureRow row = row(r, "B-DEFAULT-VALUE");
        assertEquals(FeatureStatus.REALISED, row.status());
        assertEquals(List.of(), row.notPassed());
        assertEquals("realised (1 of 1 passed; not counted: E-RANGE-004 (a case of the extension level: it needs more"
                + " than basic level features to run))", row.sentence());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "E-RANGE").status());
        assertEquals(List.of("B-DEFAULT-VALUE"), r.claims().confirmed());
        assertEquals(List.of("E-RANGE (not realised)"), r.claims().notRealised());
    }

    /** A wrong value where the reference evaluator took the DEFAULT isolates B-DEFAULT-VALUE among the rows tested. */
    @Test
    void aWrongDefaultCountsAgainstTheDefaultRowAlone() {
        CaseResult made = result("B-COGS-003", "basic", CaseStatus.FAILED, List.of("B-COGS", "B-DEFAULT-VALUE"));
        org.fclcert.harness.ReferenceTrace trace = new org.fclcert.harness.ReferenceTrace(1, List.of(), List.of(
                new org.fclcert.harness.ReferenceTrace.OutputValue("y", 2.0, "default", true, List.of())));
        CaseResult failed = new CaseResult(made.plan(), made.verdict(), new CaseResult.Evidence(made.evidence().step(),
                made.evidence().mismatch(), null, 1.0, trace), made.export(), made.setup());
        List<CaseResult> run = List.of(result("B-COGS-001", "basic", CaseStatus.PASSED, List.of("B-COGS")), failed);
        Report r = ReportBuilder.build(header(2, run, List.of()), run, List.of(), List.of(), Instant.EPOCH);
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "B-DEFAULT-VALUE").status());
        assertEquals(FeatureStatus.REALISED, row(r, "B-COGS").status());
        assertEquals(List.of("B-COGS-003 (its failing step isolates B-DEFAULT-VALUE)"), row(r, "B-COGS").notCounted());
        assertEquals(Report.BasicLevel.NOT_CONFORMANT, r.basicLevel().verdict());
        assertEquals("wrong value: B-DEFAULT-VALUE (DEFAULT with a constant value when no rule fired): wrong value",
                r.causes().get(0).kind() + ": " + r.causes().get(0).cause());
    }

    /**
     * A one-case rerun: the corpus has four cases for E-COG (corpus.rowCases) and one ran and failed. The row, the
     * claim and the Basic verdict say "not determined" with how many ran — never "not realised" or "not conformant".
     */
    @Test
    void aOneCaseRerunDeterminesNothingItDidNotRun() {
        List<CaseResult> run = List.of(result("E-COG-002", "extension", CaseStatus.FAILED, List.of("E-COG")));
        RunHeader h = header(92, run, List.of("E-COG"));
        RunHeader narrowed = new RunHeader(h.iut(), h.toolkit(), new RunHeader.CorpusInfo(h.corpus().dir(), 200,
                h.corpus().sha256(), 92, java.util.Map.of("E-COG", 4, "B-COGS", 4)),
                new RunHeader.Selection(List.of(), List.of(), List.of("E-COG-002"), h.selection().planned()),
                h.startedAt());
        Report r = ReportBuilder.build(narrowed, run, List.of(), List.of(), Instant.EPOCH);
        assertEquals("not determined (0 of 92 run)", r.basicLevel().sentence());
        assertEquals(FeatureStatus.NOT_DETERMINED, row(r, "E-COG").status());
        assertEquals("not determined (1 of 4 run; not passed: E-COG-002)", row(r, "E-COG").sentence());
        assertEquals(List.of("E-COG (1 of 4 run)"), r.claims().notDetermined());
        assertEquals(List.of(), r.claims().notRealised());
        assertEquals(FeatureStatus.NOT_TESTED, row(r, "B-COGS").status());
        String md = MarkdownReport.render(r);
        assertTrue(md.contains("**Basic Level: not determined** (0 of 92 run)."), md);
        assertTrue(md.contains("| not determined (1 of 4 run) | 0/1 | E-COG-002 |"), md);
        assertTrue(md.contains("- Claimed, not determined: E-COG (1 of 4 run)"), md);
        assertTrue(HtmlReport.render(r).contains("Basic Level: not determined"));
    }
}
