package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.corpus.CorpusException;
import org.fclcert.corpus.Vector;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * {@code convert --to} as a round trip over the conformance corpus: every positive case (Basic, Extension,
 * Open) written in each library's layout, read back with fclcert's reader of that dialect and evaluated against
 * the original on the case's own vectors and on a grid. A case the writer says it can express must come back
 * equal; every written text, expressible or not, must read back (the nearest program is still a program); the
 * rest is listed with the writer's reasons, and the counts are pinned so that a writer cannot silently lose ground.
 */
class CorpusRoundTripTest {
    private static final Path CORPUS = Path.of("conformance");
    private static List<CorpusCase> cases;
    private static final Map<Dialect, Tally> TALLIES = new LinkedHashMap<>();
    private static final List<String> FAILURES = new ArrayList<>();

    record Tally(List<String> equal, Map<String, List<String>> reasons) {
    }

    @BeforeAll
    static void roundTripEveryCase() throws CorpusException {
        cases = Corpus.load(CORPUS).cases().stream().filter(c -> !c.expectReject() && !c.inDialect()).toList();
        for (Dialect d : DialectWriters.libraries()) {
            Tally t = new Tally(new ArrayList<>(), new TreeMap<>());
            DialectWriter writer = DialectWriters.writer(d);
            for (CorpusCase c : cases) {
                Analysis a = Analysis.analyze(StrictReader.openLevel(), c.id(), c.programText());
                Program p = a.program().orElseThrow(() -> new AssertionError(c.id() + " does not read"));
                Written w = writer.write(p);
                List<Map<String, Double>> steps = c.vectors().stream().map(Vector::in).toList();
                RoundTrip rt = DialectWriters.readBackAndCompare(p, w, c.block().orElse(null), steps);
                if (rt.readBack().isEmpty()) {
                    FAILURES.add(c.id() + " as " + d.cliName() + " does not read back: " + rt.summary() + "\n"
                            + w.text());
                }
                if (w.exact()) {
                    if (!rt.equal()) {
                        FAILURES.add(c.id() + " as " + d.cliName() + " is said to be exact but " + rt.summary()
                                + "\n" + w.text());
                    }
                    t.equal().add(c.id());
                } else {
                    String codes = String.join(", ", w.notExpressible().stream().map(Diagnostic::code).distinct()
                            .sorted().toList());
                    t.reasons().computeIfAbsent(codes, k -> new ArrayList<>()).add(c.id() + " (" + w.notExpressible()
                            .get(0).message() + ")");
                }
            }
            TALLIES.put(d, t);
        }
        StringBuilder s = new StringBuilder();
        TALLIES.forEach((d, t) -> {
            s.append(d.cliName()).append(": ").append(t.equal().size()).append(" of ").append(cases.size())
                    .append(" round-trip equal\n");
            t.reasons().forEach((codes, ids) -> s.append("  ").append(ids.size()).append(" not expressible [")
                    .append(codes).append("]: ").append(String.join("; ", ids)).append('\n'));
        });
        System.out.println(s);
    }

    @Test
    void whatIsWrittenReadsBackAndWhatIsSaidToBeExactEvaluatesEqual() {
        assertEquals(0, FAILURES.size(), FAILURES.size() + " failures:\n" + String.join("\n\n",
                FAILURES.subList(0, Math.min(8, FAILURES.size()))));
    }

    @Test
    void everyCaseIsRoundTrippedOrListedWithItsReasons() {
        for (Tally t : TALLIES.values()) {
            int listed = t.reasons().values().stream().mapToInt(List::size).sum();
            assertEquals(cases.size(), t.equal().size() + listed);
        }
        // measured on the 125 positive cases of the corpus; a writer may gain, never lose ground
        // FFLL: 53 since its writer is held to the real library (issue 28): FFLL ignores the degrees written at
        // points, holds one output, one rule block and one conclusion per combination of input terms, and has no ACT
        // (the 88 before were exact only as fclcert read the text; FFLL crashed on or refused most of them)
        assertTrue(TALLIES.get(Dialect.FFLL).equal().size() >= 53, "ffll");
        assertTrue(TALLIES.get(Dialect.JFUZZYLOGIC).equal().size() >= 98, "jfuzzylogic");
        assertTrue(TALLIES.get(Dialect.FUZZYLITE).equal().size() >= 100, "fuzzylite");
        // FLL: 105 of 137 (2026-12-03); it cannot say data types, a second function block or an output without DEFUZZIFY
        assertTrue(TALLIES.get(Dialect.FLL).equal().size() >= 105, "fll");
    }
}
