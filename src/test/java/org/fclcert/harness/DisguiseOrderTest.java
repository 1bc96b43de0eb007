package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.Vector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The order and layout of the disguise (issue 26): declarations, blocks, terms and rules reordered where 5.2
 * leaves the order free, lines broken and indented, the meaning kept (the exact reference on every vector of
 * every positive case), and a negative case's error at the place its token moved to.
 */
class DisguiseOrderTest {
    private static List<RunCase> cases;

    @BeforeAll
    static void corpus() throws Exception {
        List<RunCase> all = RunCases.from(Corpus.load(Path.of("conformance")).cases());
        // the disguise rewrites standard FCL; a case written in a dialect is exempt (the last test here)
        cases = all.stream().filter(c -> !c.inDialect()).toList();
        dialectCases = all.stream().filter(RunCase::inDialect).toList();
    }

    private static List<RunCase> dialectCases;

    /**
     * A case written in a library's dialect is sent undisguised, with the reason in its result's notes: every step of
     * the disguise rewrites standard FCL's tokens and checks the result with the standard's reader, which a dialect's
     * text is not (fuzzylite's rules end with their line; its shapes and hedges are words the renaming would take for
     * names). Its fresh vectors still come from the reference on the case's own reading.
     */
    @Test
    void everyDialectCaseIsExemptWithItsReasonAndSentAsTheCorpusWritesIt() throws Exception {
        assertTrue(dialectCases.size() >= 20, "dialect cases: " + dialectCases.size());
        for (RunCase c : dialectCases) {
            FreshEvidence.Prepared p = FreshEvidence.prepare(c, 2027);
            assertTrue(Disguise.exemption(c).isPresent(), c.id());
            assertEquals(c.program(), p.disguise().text(), c.id());
            assertEquals(c.program(), p.sent().program(), c.id());
            assertEquals(0, p.disguise().renamed(), c.id());
            assertEquals(0, p.disguise().lineShift(), c.id());
            assertFalse(p.disguise().reordered(), c.id());
            CaseResult noted = p.noted(CaseResult.skipped(c.plan(), "probe"), 2027);
            assertTrue(noted.verdict().notes().stream().anyMatch(n -> n.contains("sent undisguised (written in ")),
                    c.id() + ": " + noted.verdict().notes());
        }
        // and a standard case is never exempt
        assertTrue(cases.stream().noneMatch(c -> Disguise.exemption(c).isPresent()));
    }

    private static Program read(String id, String text) {
        Analysis a = Analysis.analyze(StrictReader.openLevel(), id, text);   // the disguise's cases are standard FCL
        assertFalse(a.hasErrors(), id + ": " + a.diagnostics());
        return a.program().orElseThrow();
    }

    @Test
    void everyPositiveCaseEvaluatesExactlyAsTheCorpusTextOnEveryVectorAndMostAreReordered() throws Exception {
        int reordered = 0;
        int positive = 0;
        int ruleOrderChanged = 0;
        for (RunCase c : cases) {
            if (c.expectReject()) {
                continue;
            }
            positive++;
            FreshEvidence.Prepared p = FreshEvidence.prepare(c, 2027);
            Disguise d = p.disguise();
            Program original = read(c.id(), c.program());
            Program sent = read(c.id(), d.text());
            if (d.reordered()) {
                reordered++;
            }
            if (rulesMoved(d.text())) {
                ruleOrderChanged++;
            }
            // the exact reference on both texts, every vector (the case's own and the fresh ones)
            ExactInstance a = Evaluator.load(original).newExactInstance(c.block().orElse(null), NumberReading.DECIMAL);
            ExactInstance b = Evaluator.load(sent).newExactInstance(d.sent(c.block().orElse(null)), NumberReading.DECIMAL);
            for (Vector v : p.plain().vectors()) {
                for (Map.Entry<String, Double> in : v.in().entrySet()) {
                    a.set(in.getKey(), in.getValue());
                    b.set(d.sent(in.getKey()), in.getValue());
                }
                if (v.refused()) {
                    // a step the case expects refused: refused by both texts, with the case's code
                    assertEquals(v.error().get(), assertThrows(EvaluationException.class, a::evaluate).code(), c.id());
                    assertEquals(v.error().get(), assertThrows(EvaluationException.class, b::evaluate).code(), c.id());
                    continue;
                }
                a.evaluate();
                b.evaluate();
                for (String out : v.out().keySet()) {
                    assertEquals(a.get(out), b.get(d.sent(out)), c.id() + " " + v.in() + " " + out);
                }
            }
        }
        assertTrue(reordered >= positive * 9 / 10, "reordered: " + reordered + " of " + positive);
        assertTrue(ruleOrderChanged >= positive / 2, "rule order changed in " + ruleOrderChanged + " of " + positive);
    }

    /** Whether the rule numbers of the text (renumbered in ascending order before the rules moved) are out of order. */
    private static boolean rulesMoved(String text) {
        List<Integer> numbers = new ArrayList<>();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?i)RULE\\s+(\\d+)\\s*:").matcher(text);
        while (m.find()) {
            numbers.add(Integer.parseInt(m.group(1)));
        }
        return !numbers.equals(numbers.stream().sorted().toList());
    }

    @Test
    void everyNegativeCasesErrorIsWhereTheReferenceFindsItAfterTheTokensMoved() {
        int reordered = 0;
        int negative = 0;
        int columnsAgree = 0;
        for (RunCase c : cases) {
            if (!c.expectReject()) {
                continue;
            }
            negative++;
            Disguise d = FreshEvidence.prepare(c, 2027).disguise();
            RunCase sent = d.apply(c);
            String code = sent.expectedError().orElseThrow().code();
            int line = sent.expectedError().orElseThrow().line();
            List<Diagnostic> errors = Analysis.analyze(StrictReader.openLevel(), c.id(), d.text()).diagnostics().stream()
                    .filter(Diagnostic::isError).toList();
            assertTrue(errors.stream().anyMatch(e -> e.code().equals(code) && e.location().line() == line),
                    c.id() + ": no " + code + " at line " + line + " of the text sent: " + errors + "\n" + d.text());
            if (d.reordered()) {
                reordered++;
            }
            Optional<DisguiseText.Place> place = d.errorPlace();
            if (place.isPresent()) {
                assertEquals(line, place.get().line(), c.id());
                if (errors.stream().anyMatch(e -> e.code().equals(code) && e.location().line() == line
                        && e.location().column() == place.get().column())) {
                    columnsAgree++;
                }
            }
        }
        assertTrue(reordered >= negative * 3 / 4, "reordered: " + reordered + " of " + negative);
        assertTrue(columnsAgree >= negative * 3 / 4, "error at the mapped column: " + columnsAgree + " of " + negative);
    }

    @Test
    void twinsLoadOnTheReferenceAndDifferFromTheCase() {
        int twins = 0;
        int negative = 0;
        for (RunCase c : cases) {
            if (!c.expectReject()) {
                continue;
            }
            negative++;
            Disguise d = FreshEvidence.prepare(c, 2027).disguise();
            if (d.twin().isEmpty()) {
                continue;
            }
            twins++;
            String twin = d.twin().get().text();
            assertFalse(twin.equals(d.text()), c.id());
            Analysis a = Analysis.analyze(StrictReader.openLevel(), c.id(), twin);
            assertFalse(a.hasErrors(), c.id() + ": " + a.diagnostics() + "\n" + twin);
        }
        // measured on the corpus of 72 negative cases: 52 repaired by one small edit (RepairedTwin)
        assertTrue(twins >= 48, "twins: " + twins + " of " + negative);
    }
}
