package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The real corpus ({@code conformance/}) against the real toolkit: the build fails when a case and the
 * reader, checker, feature detector or reference evaluator disagree, or when coverage falls short.
 */
class ConformanceCorpusTest {
    private static final Path CORPUS = Path.of("conformance");
    private static LintReport report;

    @BeforeAll
    static void lint() {
        report = new CorpusLint().lint(CORPUS);
    }

    @Test
    void everyCaseAgreesWithTheToolkit() {
        assertEquals("", report.caseFindings().stream().map(CorpusProblem::toString)
                .collect(Collectors.joining("\n")));
    }

    @Test
    void theCorpusCoversTables8And9AndTheOpenLevelFeatures() {
        assertEquals(List.of(), report.coverageGaps());
    }

    @Test
    void theCorpusLoadsForRunners() throws CorpusException {
        Corpus corpus = Corpus.load(CORPUS);
        assertEquals(report.cases(), corpus.cases().size());
        assertTrue(report.negative() >= CoverageRules.NEGATIVE_CASES, "negative cases: " + report.negative());
        // every Basic case carries a hand derivation (also a lint rule; stated here as the corpus' promise)
        assertTrue(corpus.cases().stream().filter(c -> c.id().startsWith("B-")).allMatch(c -> c.derivation().isPresent()));
    }
}
