package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.Vector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Names;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** Fresh vectors and the disguise (issue 26): drawn from the seed, meaning kept, text never the corpus's. */
class FreshEvidenceTest {
    private static List<RunCase> cases;

    @BeforeAll
    static void corpus() throws Exception {
        // a case written in a dialect is sent undisguised (DisguiseOrderTest says so for each)
        cases = RunCases.from(Corpus.load(Path.of("conformance")).cases()).stream().filter(c -> !c.inDialect()).toList();
    }

    private static RunCase byId(String id) {
        return cases.stream().filter(c -> c.id().equals(id)).findFirst().orElseThrow();
    }

    @Test
    void theSameSeedReplaysTheSameTextAndVectorsAndAnotherSeedDoesNot() {
        RunCase c = byId("B-ACCU-MAX-001");
        FreshEvidence.Prepared a = FreshEvidence.prepare(c, 42);
        FreshEvidence.Prepared b = FreshEvidence.prepare(c, 42);
        FreshEvidence.Prepared other = FreshEvidence.prepare(c, 43);
        assertEquals(a.disguise().text(), b.disguise().text());
        assertEquals(a.plain().vectors(), b.plain().vectors());
        assertNotEquals(a.disguise().text(), other.disguise().text());
        assertNotEquals(a.plain().vectors(), other.plain().vectors());
        assertEquals(FreshVectors.COUNT, a.fresh(), "B-ACCU-MAX-001 is stateless: every drawn vector should be kept");
        assertEquals(c.vectors(), a.plain().vectors().subList(0, c.vectors().size()), "the corpus vectors come first");
    }

    private static final Pattern WORD = Pattern.compile("\\(\\*.*?\\*\\)|[A-Za-z_][A-Za-z0-9_]*", Pattern.DOTALL);

    @Test
    void noTextSentIsTheCorpusTextAndNoDeclaredNameOfAPositiveCaseIsLeftInIt() {
        int renamedCases = 0;
        for (RunCase c : cases) {
            Disguise d = FreshEvidence.prepare(c, 7).disguise();
            assertNotEquals(c.program(), d.text(), c.id());
            if (c.expectReject()) {
                continue;
            }
            assertTrue(d.renamed() > 0, c.id() + " keeps its names");
            renamedCases++;
            List<String> declared = declared(c);
            Matcher m = WORD.matcher(d.text());
            while (m.find()) {
                String w = m.group();
                assertFalse(!w.startsWith("(*") && declared.stream().anyMatch(n -> Names.same(n, w)),
                        c.id() + ": the corpus name '" + w + "' is in the text sent");
            }
        }
        assertEquals(cases.stream().filter(c -> !c.expectReject()).count(), renamedCases, "every positive case is renamed");
    }

    private static List<String> declared(RunCase c) {
        var p = Analysis.analyze(StrictReader.openLevel(), c.id(), c.program()).program().orElseThrow();
        List<String> out = new ArrayList<>();
        p.functionBlocks().forEach(fb -> {
            fb.variables().forEach(v -> out.add(v.name()));
            out.add(fb.name());
        });
        return out;
    }

    @Test
    void aNegativeCasesErrorIsWhereTheReferenceFindsItInTheTextSent() {
        int moved = 0;
        for (RunCase c : cases) {
            if (!c.expectReject()) {
                continue;
            }
            RunCase sent = FreshEvidence.prepare(c, 11).sent();
            String code = sent.expectedError().orElseThrow().code();
            int line = sent.expectedError().orElseThrow().line();
            var errors = Analysis.analyze(StrictReader.openLevel(), c.id(), sent.program()).diagnostics().stream()
                    .filter(Diagnostic::isError).toList();
            assertTrue(errors.stream().anyMatch(e -> e.code().equals(code) && e.location().line() == line),
                    c.id() + ": no " + code + " at line " + line + " of the text sent: " + errors);
            if (line != c.expectedError().orElseThrow().line()) {
                moved++;
            }
        }
        // the lines put in front move every error; a reordering may now and then bring one back to its corpus line
        assertTrue(moved >= 65, "the error's line moves with the text: " + moved + " of 72 moved");
    }

    @Test
    void freshExpectedValuesAgreeWithTheDoubleArithmeticOfTheFastPath() throws Exception {
        // the expected values come from the exact path; the fast path (doubles, compiled) is a second arithmetic
        int checked = 0;
        for (RunCase c : cases.subList(0, 60)) {
            if (c.expectReject()) {
                continue;
            }
            FreshEvidence.Prepared p = FreshEvidence.prepare(c, 5);
            var program = Analysis.analyze(StrictReader.openLevel(), c.id(), c.program()).program().orElseThrow();
            FunctionBlockInstance fb = c.block().isPresent() ? Evaluator.load(program).newInstance(c.block().get())
                    : Evaluator.load(program).newInstance();
            for (Vector v : p.plain().vectors()) {
                v.in().forEach((k, x) -> {
                    try {
                        fb.set(k, x);
                    } catch (Exception e) {
                        throw new AssertionError(e);
                    }
                });
                if (v.refused()) {
                    assertEquals(v.error().get(), assertThrows(EvaluationException.class, fb::evaluate).code(), c.id());
                    continue;
                }
                fb.evaluate();
                for (Map.Entry<String, Double> out : v.out().entrySet()) {
                    assertTrue(c.tolerance().accepts(out.getKey(), out.getValue(), fb.get(out.getKey())),
                            c.id() + " " + v + ": fast path gives " + fb.get(out.getKey()));
                }
            }
            checked += p.fresh();
        }
        assertTrue(checked > 200, "fresh vectors checked: " + checked);
    }

    @Test
    void theReferenceBehindTheDisguisePassesAndNoCorpusNameIsSent() throws Exception {
        CaseRunner runner = new CaseRunner(new ReferenceExportCheck());
        for (String id : List.of("B-ACCU-MAX-001", "E-RULEBLOCKS-001", "N-C002-001")) {
            RunCase c = byId(id);
            try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
                CaseResult live = FreshEvidence.run(runner, reference, c, 99).result();
                assertEquals(CaseStatus.PASSED, live.status(), id + ": " + live.message());
                assertFalse(live.replies().isEmpty());
                assertTrue(live.replies().stream().allMatch(x -> x.in() == null || x.in().keySet().stream()
                        .noneMatch(k -> c.vectors().get(0).in().containsKey(k))), id + ": a corpus name was sent");
            }
        }
    }
}
