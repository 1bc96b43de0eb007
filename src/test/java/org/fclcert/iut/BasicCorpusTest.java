package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.corpus.Comparison;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.corpus.CorpusException;
import org.fclcert.corpus.OutputScales;
import org.fclcert.corpus.Vector;
import org.fclcert.model.ConformanceLevel;
import org.junit.jupiter.api.Test;

/**
 * The Python example of docs/iut-protocol.md, an independent Basic Level implementation, runs the
 * Basic Level cases of the corpus (positive and negative) cleanly through the process adapter: a cross-check of the corpus, the
 * adapter and the example (the reference is held to the whole corpus by the corpus tests). The
 * harness proper does much more (reverse order, export, reports).
 */
class BasicCorpusTest {

    @Test
    void thePythonExamplePassesEveryBasicCase() throws CorpusException, IutException {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        List<CorpusCase> basic = corpus.cases().stream()
                .filter(c -> c.level() == ConformanceLevel.BASIC).toList();
        assertTrue(basic.stream().anyMatch(CorpusCase::expectReject) && basic.size() >= 20, "only " + basic.size() + " basic cases");
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofSeconds(5));
        try (ImplementationUnderTest iut = Iuts.open(BasicIutExampleTest.SPEC, options)) {
            List<String> problems = new ArrayList<>();
            for (CorpusCase c : basic) {
                run(iut, c, problems);
            }
            assertEquals(List.of(), problems,
                    "examples/iut/basic_iut.py and the Basic corpus disagree: fix the example, or the case");
        }
    }

    private static void run(ImplementationUnderTest iut, CorpusCase c, List<String> problems) throws IutException {
        LoadOutcome outcome = iut.load(c.programText());
        if (c.expectReject()) {
            if (!(outcome instanceof LoadOutcome.Rejected r) || r.line().orElse(-1) != c.expectedError().get().line()) {
                problems.add(c.id() + ": expected a rejection at line " + c.expectedError().get().line() + ", got " + outcome);
            }
            return;
        }
        if (outcome instanceof LoadOutcome.Rejected r) {
            problems.add(c.id() + ": rejected: " + r);
            return;
        }
        for (Vector v : c.vectors()) {
            if (v.refused()) {
                try {
                    problems.add(c.id() + ": gives " + iut.eval(c.block().orElse(null), v.in()) + " where "
                            + v.error().get() + " is expected");
                } catch (IutException e) {
                    if (e.kind() != IutException.Kind.EVAL_ERROR) {
                        throw e;
                    }
                }
                continue;
            }
            Map<String, Double> actual = iut.eval(c.block().orElse(null), v.in());
            for (Comparison cmp : c.tolerance().compareAll(v.out(), actual, OutputScales.none())) {
                if (!cmp.passed()) {
                    problems.add(c.id() + ": " + cmp);
                }
            }
        }
    }
}
