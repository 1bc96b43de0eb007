package org.fclcert.harness.fakes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.Certify;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;

/**
 * Each fake is wrong in one known way; certifying it on the small corpus must name exactly the feature rows
 * its defect touches and the cases that show it, and leave every other row realised. The cases' expected
 * numbers are hand-derived in their files (with the value the defect gives, where it differs).
 */
class FakesTest {
    static final Path CORPUS = Path.of("src/test/resources/corpus-mini");

    /** Rows the small corpus has evidence for (interpretation cases excluded), with their cases. */
    static final List<String> TESTED_ROWS = List.of("B-COGS", "B-ACCU-MAX", "B-DEFAULT-VALUE", "B-DEFAULT-NC",
            "B-SUBCONDITIONS", "E-ACCU-NSUM", "E-WITH-CONST", "E-OR-MAX", "E-RULEBLOCKS", "E-LM", "E-RM", "E-COG",
            "E-NOT");

    static Report certify(ImplementationUnderTest iut) throws Exception {
        return Certify.run(iut, CORPUS);
    }

    /** Row id → status for every row that is not realised. */
    static Map<String, FeatureStatus> notRealised(Report r) {
        return r.features().stream().filter(f -> f.status() != FeatureStatus.REALISED
                && f.status() != FeatureStatus.NOT_TESTED)
                .collect(Collectors.toMap(Report.FeatureRow::id, Report.FeatureRow::status, (a, b) -> a, TreeMap::new));
    }

    static Map<String, CaseStatus> notPassed(Report r) {
        return r.cases().stream().filter(c -> c.status() != CaseStatus.PASSED)
                .collect(Collectors.toMap(CaseResult::id, CaseResult::status, (a, b) -> a, TreeMap::new));
    }

    static CaseResult result(Report r, String id) {
        return r.cases().stream().filter(c -> c.id().equals(id)).findFirst().orElseThrow();
    }

    @Test
    void theCorrectImplementationPassesEveryCase() throws Exception {
        Report r = certify(new EvaluatorIut());
        assertEquals(Map.of(), notPassed(r), () -> r.cases().toString());
        assertTrue(r.basicLevel().conformant(), r.basicLevel().reason());
        assertEquals(4, r.basicLevel().required(), "four Basic cases, the interpretation one not counted");
        for (String id : TESTED_ROWS) {
            assertEquals(FeatureStatus.REALISED, r.features().stream().filter(f -> f.id().equals(id)).findFirst()
                    .orElseThrow().status(), id);
        }
        assertEquals(List.of("B-COGS-002"), r.interpretation().stream().map(Report.InterpretationEntry::id).toList());
    }

    @Test
    void alwaysZeroFailsEveryPositiveCase() throws Exception {
        Report r = certify(new Fakes.AlwaysZero());
        assertFalse(r.basicLevel().conformant());
        // B-SUBCONDITIONS is tested only by the negative case, which a zero-answering loader still rejects
        assertEquals(TESTED_ROWS.stream().filter(id -> !id.equals("B-SUBCONDITIONS"))
                .collect(Collectors.toMap(id -> id, id -> FeatureStatus.NOT_REALISED, (a, b) -> a, TreeMap::new)),
                notRealised(r));
        assertEquals("step 1 of 3: valve = 0.0 where 73.07692307692308 is expected (error 73.07692307692308, "
                + "allowed 7.307692307692308E-8)", result(r, "B-COGS-001").message());
        assertEquals("failed", r.interpretation().get(0).status(), "reported apart, but reported");
    }

    @Test
    void nsumAsBsumLosesOnlyTheNsumRow() throws Exception {
        Report r = certify(new Fakes.NsumAsBsum());
        assertEquals(Map.of("E-ACCU-NSUM", FeatureStatus.NOT_REALISED), notRealised(r));
        assertEquals(Map.of("E-ACCU-NSUM-001", CaseStatus.FAILED), notPassed(r));
        CaseResult c = result(r, "E-ACCU-NSUM-001");
        assertEquals(1, c.evidence().step().number());
        // BSUM: lo 1, hi 0.5: y = 50/1.5
        assertEquals(50 / 1.5, ((Map<?, ?>) c.mismatch().orElseThrow().actual()).get("y"));
        assertTrue(r.basicLevel().conformant());
    }

    @Test
    void weightBeforeActivationLosesTheWithRow() throws Exception {
        Report r = certify(new Fakes.WeightBeforeActivation());
        assertEquals(Map.of("E-WITH-CONST", FeatureStatus.NOT_REALISED), notRealised(r));
        CaseResult c = result(r, "E-WITH-CONST-001");
        // min(0.25, mu) for small: CoG = 1679.6875/29.6875 = 56.5789..., 1.75 off where 0.2 is allowed
        assertEquals(1679.6875 / 29.6875, (Double) ((Map<?, ?>) c.mismatch().orElseThrow().actual()).get("y"), 1e-3);
        assertEquals(1, c.evidence().step().number());
    }

    @Test
    void equalPrecedenceLosesTheRowOfTheMixedCondition() throws Exception {
        Report r = certify(new Fakes.EqualPrecedence());
        assertEquals(Map.of("E-OR-MAX", FeatureStatus.NOT_REALISED), notRealised(r));
        // (0.8 OR 0.3) AND 0.1 = 0.1: y = 10/0.3
        assertEquals(10 / 0.3, (Double) ((Map<?, ?>) result(r, "E-OR-MAX-001").mismatch().orElseThrow().actual()).get("y"), 1e-9);
    }

    @Test
    void coupledAndOrLosesTheSeveralRuleBlocksRow() throws Exception {
        Report r = certify(new Fakes.CoupledAndOr());
        assertEquals(Map.of("E-RULEBLOCKS", FeatureStatus.NOT_REALISED), notRealised(r));
        // block one evaluated with PROD: 0.2 / (0.2 + 0.4)
        assertEquals(100 * 0.2 / 0.6, (Double) ((Map<?, ?>) result(r, "E-RULEBLOCKS-001").mismatch().orElseThrow().actual()).get("y1"), 1e-9);
    }

    @Test
    void sampledDefuzzificationLosesCogLmAndRm() throws Exception {
        Report r = certify(new Fakes.SampledDefuzzification());
        assertEquals(Map.of("E-COG", FeatureStatus.NOT_REALISED, "E-LM", FeatureStatus.NOT_REALISED,
                "E-RM", FeatureStatus.NOT_REALISED), notRealised(r));
        assertEquals(Map.of("y", 30.5), result(r, "E-LM-001").mismatch().orElseThrow().actual(), "first midpoint on the plateau");
        assertEquals(Map.of("y", 49.5), result(r, "E-RM-001").mismatch().orElseThrow().actual(), "last midpoint on the plateau");
        assertEquals(Map.of("y", 0.0), result(r, "E-COG-001").mismatch().orElseThrow().actual(), "no sample hits the narrow term: DEFAULT");
        // step 2: the clipped set reaches 0.5 at 20.1; the first sample at or above it is 20.5
        assertEquals(0.4, result(r, "E-LM-001").evidence().maxError(), 1e-9);
    }

    @Test
    void perRuleCogsLosesTheBasicLevel() throws Exception {
        Report r = certify(new Fakes.PerRuleCogs());
        // on singletons per-rule summing equals NSUM (the normalisation cancels in CoGS), so that row holds
        assertEquals(Map.of("B-ACCU-MAX", FeatureStatus.NOT_REALISED, "B-COGS", FeatureStatus.NOT_REALISED),
                notRealised(r));
        assertFalse(r.basicLevel().conformant());
        // (950/12) / (14/12): both rules concluding 'closed' counted
        assertEquals(950.0 / 14, (Double) ((Map<?, ?>) result(r, "B-COGS-001").mismatch().orElseThrow().actual()).get("valve"), 1e-9);
    }

    @Test
    void ignoringDefaultLosesTheDefaultValueRow() throws Exception {
        Report r = certify(new Fakes.IgnoresDefault());
        assertEquals(Map.of("B-DEFAULT-VALUE", FeatureStatus.NOT_REALISED), notRealised(r));
        assertEquals(2, result(r, "B-DEFAULT-VALUE-001").evidence().step().number());
        assertFalse(r.basicLevel().conformant());
    }

    @Test
    void ncAsZeroLosesTheNcRow() throws Exception {
        Report r = certify(new Fakes.NcAsZero());
        assertEquals(Map.of("B-DEFAULT-NC", FeatureStatus.NOT_REALISED), notRealised(r));
        CaseResult c = result(r, "B-DEFAULT-NC-001");
        assertEquals(2, c.evidence().step().number());
        assertEquals(List.of("2 of 4 steps gave a wrong result"), c.verdict().notes());
    }

    @Test
    void acceptingAnythingFailsTheNegativeCase() throws Exception {
        Report r = certify(new Fakes.AcceptsAnything());
        assertEquals(Map.of("B-SUBCONDITIONS", FeatureStatus.NOT_REALISED), notRealised(r));
        assertEquals("accepted a program the standard rejects: FCL-C002 at line 25",
                result(r, "B-SUBCONDITIONS-901").message());
        assertFalse(r.basicLevel().conformant());
    }

    @Test
    void rejectingNotLosesOnlyTheNotRow() throws Exception {
        Report r = certify(new Fakes.RejectsNot());
        assertEquals(Map.of("E-NOT", FeatureStatus.NOT_REALISED), notRealised(r));
        assertEquals("rejected a program the standard accepts at line 32: NOT is not supported",
                result(r, "E-NOT-001").message());
        assertTrue(r.basicLevel().conformant());
    }
}
