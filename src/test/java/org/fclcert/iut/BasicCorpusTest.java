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
import org.junit.jupiter.api.Test;

/**
 * Both example Basic Level implementations — the reference and the Python example of the protocol
 * docs — run the Basic part of the corpus cleanly. A small, independent cross-check of the corpus,
 * the adapters and the example; the harness proper does much more (reverse order, export, reports).
 */
class BasicCorpusTest {

    @Test
    void theReferenceAndThePythonExamplePassEveryBasicCase() throws CorpusException, IutException {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        List<CorpusCase> basic = corpus.cases().stream()
                .filter(c -> c.path().toString().contains("basic")).toList();
        assertTrue(basic.size() >= 10, "only " + basic.size() + " basic cases");
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofSeconds(5));
        for (String spec : List.of("reference", BasicIutExampleTest.SPEC)) {
            try (ImplementationUnderTest iut = Iuts.open(spec, options)) {
                List<String> problems = new ArrayList<>();
                for (CorpusCase c : basic) {
                    run(iut, c, problems);
                }
                assertEquals(List.of(), problems, spec);
            }
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
            Map<String, Double> actual = iut.eval(c.block().orElse(null), v.in());
            for (Comparison cmp : c.tolerance().compareAll(v.out(), actual, OutputScales.none())) {
                if (!cmp.passed()) {
                    problems.add(c.id() + ": " + cmp);
                }
            }
        }
    }
}
