package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.corpus.Vector;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.Test;

/**
 * {@code convert --to fis} over the conformance corpus: every positive case written as FIS, read back by fclcert's
 * FIS reader and evaluated by the reference against the original on the case's vectors and on a grid of every input
 * (equal within {@link RoundTrip#TOLERANCE}, relative). A case the writer calls exact must come back equal, every
 * text must read back, and the count of exact cases may grow, never shrink.
 */
class FisWriterCorpusTest {
    @Test
    void everyCaseIsWrittenReadBackAndTheExactOnesEvaluateEqual() throws Exception {
        List<CorpusCase> cases = Corpus.load(Path.of("conformance")).cases().stream().filter(c -> !c.expectReject() && !c.inDialect())
                .toList();
        DialectWriter writer = DialectWriters.writer(Dialect.FIS);
        List<String> failures = new ArrayList<>();
        List<String> equal = new ArrayList<>();
        Map<String, List<String>> reasons = new TreeMap<>();
        int comparisons = 0;
        for (CorpusCase c : cases) {
            Program p = Analysis.analyze(StrictReader.openLevel(), c.id(), c.programText()).program().orElseThrow();
            Written w = writer.write(p);
            List<Map<String, Double>> steps = c.vectors().stream().map(Vector::in).toList();
            RoundTrip rt = DialectWriters.readBackAndCompare(p, w, c.block().orElse(null), steps);
            if (rt.readBack().isEmpty()) {
                failures.add(c.id() + " does not read back: " + rt.summary() + "\n" + w.text());
            } else if (w.exact() && !rt.equal()) {
                failures.add(c.id() + " is said to be exact but " + rt.summary() + "\n" + w.text());
            } else if (w.exact()) {
                equal.add(c.id());
                comparisons += rt.comparisons();
            } else {
                reasons.computeIfAbsent(String.join(", ", w.notExpressible().stream().map(Diagnostic::code).distinct()
                        .sorted().toList()), k -> new ArrayList<>()).add(c.id());
            }
        }
        StringBuilder s = new StringBuilder("fis: " + equal.size() + " of " + cases.size() + " round-trip equal on "
                + comparisons + " comparisons\n");
        reasons.forEach((codes, ids) -> s.append("  ").append(ids.size()).append(" [").append(codes).append("]: ")
                .append(String.join(" ", ids)).append('\n'));
        System.out.println(s);
        failures.forEach(f -> System.out.println("FAILURE " + f.lines().findFirst().orElse("")));
        assertEquals(List.of(), failures.subList(0, Math.min(5, failures.size())), failures.size() + " failures");
        assertEquals(cases.size(), equal.size() + reasons.values().stream().mapToInt(List::size).sum());
        // measured on the 137 positive cases (2026-12-03): most are lost to FIS having no DEFAULT (FCL-X111) where
        // the rules leave a gap, and to its Sugeno average counting every rule (ACCU SUM, FCL-X108)
        assertTrue(equal.size() >= 13, "fis: " + equal.size());
    }
}
