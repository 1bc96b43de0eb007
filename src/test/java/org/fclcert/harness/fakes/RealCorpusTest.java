package org.fclcert.harness.fakes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.Certify;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.model.Feature;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The fakes against the real corpus ({@code conformance/}): each must lose the feature rows of its defect,
 * and every case it does not pass must use a feature its defect touches, so the report blames the right rows
 * and nothing else. (The small corpus of {@link FakesTest} pins exact numbers; this one follows the corpus as
 * it grows.)
 */
class RealCorpusTest {
    static final Path CORPUS = Path.of("conformance");
    static Certify.Prepared corpus;
    static Map<String, CorpusCase> cases;

    @BeforeAll
    static void load() throws Exception {
        Certify.Prepared all = Certify.Prepared.load(CORPUS);
        // the fakes speak standard FCL only: a case written in a dialect is not sent to them (DialectCasesTest)
        corpus = new Certify.Prepared(all.dir(), all.sha256(),
                all.cases().stream().filter(c -> !c.inDialect()).toList());
        cases = Corpus.load(CORPUS).cases().stream().collect(Collectors.toMap(CorpusCase::id, c -> c));
    }

    static Report certify(ImplementationUnderTest iut) throws Exception {
        return Certify.run(iut, corpus);
    }

    static Map<String, String> notPassed(Report r) {
        return r.cases().stream().filter(c -> c.status() != CaseStatus.PASSED)
                .collect(Collectors.toMap(CaseResult::id, c -> c.status().word() + ": " + c.message(), (a, b) -> a,
                        TreeMap::new));
    }

    static FeatureStatus row(Report r, String id) {
        return r.features().stream().filter(f -> f.id().equals(id)).findFirst().orElseThrow().status();
    }

    /** Every case that did not pass uses one of the features the defect is about. */
    static void failuresExplainedBy(Report r, Set<Feature> defect) {
        for (CaseResult c : r.cases()) {
            if (c.status() != CaseStatus.PASSED) {
                assertTrue(cases.get(c.id()).features().stream().anyMatch(defect::contains),
                        c.id() + " did not pass (" + c.message() + ") but uses none of " + defect);
            }
        }
    }

    static boolean corpusTests(Feature f) {
        return cases.values().stream().anyMatch(c -> c.tests().contains(f));
    }

    @Test
    void theCorrectEvaluatorPassesEveryCase() throws Exception {
        Report r = certify(new EvaluatorIut());
        assertEquals(Map.of(), notPassed(r));
        assertTrue(r.basicLevel().conformant(), r.basicLevel().reason());
        r.features().stream().filter(f -> f.table() != 10)
                .forEach(f -> assertNotEquals(FeatureStatus.PARTIAL, f.status(), f.id()));
    }

    @Test
    void alwaysZeroIsNotBasicConformant() throws Exception {
        Report r = certify(new Fakes.AlwaysZero());
        assertFalse(r.basicLevel().conformant());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "B-COGS"));
        assertTrue(r.summary().failed() > r.summary().passed(), r.summary().toString());
    }

    @Test
    void nsumAsBsum() throws Exception {
        Report r = certify(new Fakes.NsumAsBsum());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "E-ACCU-NSUM"));
        failuresExplainedBy(r, Set.of(Feature.E_ACCU_NSUM));
        assertTrue(r.basicLevel().conformant());
    }

    @Test
    void equalPrecedenceOfAndAndOr() throws Exception {
        Report r = certify(new Fakes.EqualPrecedence());
        assertNotEquals(FeatureStatus.REALISED, row(r, "E-OR-MAX"));
        failuresExplainedBy(r, Set.of(Feature.E_OR_MAX, Feature.E_OR_ASUM, Feature.E_OR_BSUM));
        assertTrue(r.basicLevel().conformant());
    }

    @Test
    void coupledAndOr() throws Exception {
        Report r = certify(new Fakes.CoupledAndOr());
        assertNotEquals(FeatureStatus.REALISED, row(r, "E-RULEBLOCKS"));
        failuresExplainedBy(r, Set.of(Feature.E_RULEBLOCKS));
    }

    @Test
    void sampledDefuzzification() throws Exception {
        Report r = certify(new Fakes.SampledDefuzzification());
        for (String id : new String[] {"E-COG", "E-COA", "E-LM", "E-RM"}) {
            assertNotEquals(FeatureStatus.REALISED, row(r, id), id);
        }
        // a sampled MoM is a sampled position too (O-MOM-001, -003: off by up to one step)
        failuresExplainedBy(r, Set.of(Feature.E_COG, Feature.E_COA, Feature.E_LM, Feature.E_RM, Feature.O_MOM));
        assertTrue(r.basicLevel().conformant());
    }

    @Test
    void weightBeforeActivation() throws Exception {
        Report r = certify(new Fakes.WeightBeforeActivation());
        failuresExplainedBy(r, Set.of(Feature.E_WITH_CONST, Feature.E_WITH_VAR));
        assertTrue(r.basicLevel().conformant());
    }

    @Test
    void perRuleCogs() throws Exception {
        Report r = certify(new Fakes.PerRuleCogs());
        assertFalse(r.basicLevel().conformant());
        // B-DEFAULT-VALUE-004 (nothing fires: the DEFAULT) passes whatever the accumulation, so the row is partial
        assertNotEquals(FeatureStatus.REALISED, row(r, "B-ACCU-MAX"));
        assertNotEquals(FeatureStatus.REALISED, row(r, "B-COGS"));
        failuresExplainedBy(r, Set.of(Feature.B_COGS));
    }

    @Test
    void ignoresDefault() throws Exception {
        Report r = certify(new Fakes.IgnoresDefault());
        assertFalse(r.basicLevel().conformant());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "B-DEFAULT-VALUE"));
        failuresExplainedBy(r, Set.of(Feature.B_DEFAULT_VALUE));
    }

    @Test
    void ncAsZero() throws Exception {
        Report r = certify(new Fakes.NcAsZero());
        assertFalse(r.basicLevel().conformant());
        assertEquals(FeatureStatus.NOT_REALISED, row(r, "B-DEFAULT-NC"));
        failuresExplainedBy(r, Set.of(Feature.B_DEFAULT_NC));
    }

    @Test
    void acceptsAnything() throws Exception {
        Report r = certify(new Fakes.AcceptsAnything());
        for (CaseResult c : r.cases()) {
            boolean negative = cases.get(c.id()).expectReject();
            assertEquals(negative ? CaseStatus.FAILED : CaseStatus.PASSED, c.status(), c.id());
        }
    }

    @Test
    void rejectsNot() throws Exception {
        Report r = certify(new Fakes.RejectsNot());
        assertEquals(corpusTests(Feature.E_NOT) ? FeatureStatus.NOT_REALISED : FeatureStatus.NOT_TESTED,
                row(r, "E-NOT"));
        failuresExplainedBy(r, Set.of(Feature.E_NOT));
        assertTrue(r.basicLevel().conformant());
    }
}
