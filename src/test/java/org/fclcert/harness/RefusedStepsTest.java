package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.Vector;
import org.fclcert.iut.ForwardingIut;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Steps a case expects refused ({@code error: FCL-V004}): B-FB-151, whose steps 3-5 put a SINT output beyond its type
 * (128, -129, 200) and whose other steps are in range (step 2 at both ends, 127 and -128).
 */
class RefusedStepsTest {
    private static RunCase sintEnds;

    @BeforeAll
    static void load() throws Exception {
        sintEnds = RunCases.from(Corpus.load(Path.of("conformance")).cases()).stream()
                .filter(c -> c.id().equals("B-FB-151")).findFirst().orElseThrow();
        assertTrue(sintEnds.vectors().get(2).refused() && !sintEnds.vectors().get(1).refused());
    }

    /** The reference, with its answer to the steps the case expects refused replaced by {@code answer}. */
    private interface Answer {
        Map<String, Double> at(Map<String, Double> in, IutException refusal) throws IutException;
    }

    private static CaseResult run(Answer answer) throws Exception {
        return run(answer, sintEnds);
    }

    private static CaseResult run(Answer answer, RunCase c) throws Exception {
        try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
            ImplementationUnderTest iut = new ForwardingIut(reference) {
                @Override
                public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
                    try {
                        return delegate().eval(block, inputs);
                    } catch (IutException e) {
                        return answer.at(inputs, e);
                    }
                }
            };
            return new CaseRunner(new ReferenceExportCheck()).run(iut, c).result();
        }
    }

    /** y and z (in this order) as B-FB-151 computes them, saturated at SINT's ends instead of refused. */
    private static Map<String, Double> saturating(Map<String, Double> in) {
        Map<String, Double> out = new java.util.LinkedHashMap<>();
        out.put("y", Math.min(127.0, 100 + 10 * in.get("x")));
        out.put("z", Math.max(-128.0, -100 - 10 * in.get("w")));
        return out;
    }

    @Test
    void theReferenceRefusesThemWithTheCode() throws Exception {
        CaseResult r = run((in, e) -> {
            throw e;
        });
        assertEquals(CaseStatus.PASSED, r.status(), r.message());
        assertEquals("3 step(s) within tolerance, 3 refused as required", r.message());
    }

    @Test
    void aRefusalThatNamesNoCodeIsARefusal() throws Exception {
        CaseResult r = run((in, e) -> {
            throw new IutException(IutException.Kind.EVAL_ERROR, "value out of range");
        });
        assertEquals(CaseStatus.PASSED, r.status(), r.message());
    }

    @Test
    void aValueWhereTheStepMustBeRefusedFails() throws Exception {
        // an implementation that saturates at the type's end instead of refusing
        CaseResult r = run((in, e) -> saturating(in));
        assertEquals(CaseStatus.FAILED, r.status());
        assertEquals("step 3 of 6: gives {y=127.0, z=-100.0} where the evaluation must be refused with FCL-V004 (a value"
                + " that does not fit its variable's data type (e.g. 200 for a SINT output))", r.message().lines().findFirst()
                .orElseThrow());
    }

    @Test
    void aRefusalWithAnotherCodeFails() throws Exception {
        CaseResult r = run((in, e) -> {
            throw new IutException(IutException.Kind.EVAL_ERROR, "FCL-V006: something else");
        });
        assertEquals(CaseStatus.FAILED, r.status());
        assertTrue(r.message().startsWith("step 3 of 6: refuses the evaluation with FCL-V006 where FCL-V004 is expected"),
                r.message());
    }

    @Test
    void aBreakdownAtARefusedStepIsNoRefusal() throws Exception {
        CaseResult r = run((in, e) -> {
            throw new IutException(IutException.Kind.CRASH, "the process died");
        });
        assertEquals(CaseStatus.ERRORED, r.status(), r.message());
    }

    @Test
    void freshStepsAreRefusedToo() throws Exception {
        RunCase fresh = FreshVectors.withFresh(sintEnds, 20261205L);
        List<Vector> drawn = fresh.vectors().subList(sintEnds.vectors().size(), fresh.vectors().size());
        assertTrue(drawn.stream().anyMatch(Vector::refused), "fresh refused steps: " + drawn);
        assertTrue(drawn.stream().filter(Vector::refused).allMatch(v -> v.error().get().equals("FCL-V004")), "" + drawn);
        assertEquals(CaseStatus.PASSED, run((in, e) -> {
            throw e;
        }, fresh).status());
        // an implementation that refuses the corpus's own refused inputs (remembered) and saturates elsewhere
        java.util.Set<Map<String, Double>> remembered = new java.util.HashSet<>();
        sintEnds.vectors().stream().filter(Vector::refused).forEach(v -> remembered.add(v.in()));
        Answer lookup = (in, e) -> {
            if (remembered.contains(in)) {
                throw e;
            }
            return saturating(in);
        };
        assertEquals(CaseStatus.PASSED, run(lookup).status(), "the corpus's own steps alone do not tell");
        CaseResult r = run(lookup, fresh);
        assertEquals(CaseStatus.FAILED, r.status());
        assertTrue(r.message().contains("where the evaluation must be refused with FCL-V004"), r.message());
    }

    @Test
    void anExportThatNoLongerRefusesFailsTheExportCheck() throws Exception {
        try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
            // exports its program with the SINT outputs made REAL: step 3 then evaluates to 128
            ImplementationUnderTest iut = new ForwardingIut(reference) {
                @Override
                public java.util.Optional<String> export() throws IutException {
                    return delegate().export().map(text -> text.replaceAll("(?i)\\bSINT\\b", "REAL"));
                }
            };
            CaseResult r = new CaseRunner(new ReferenceExportCheck()).run(iut, sintEnds).result();
            assertEquals(CaseStatus.PASSED, r.status(), r.message());
            assertEquals(ExportStatus.FAILED, r.export().status());
            assertTrue(r.export().message().startsWith("the exported FCL evaluates step 3 to {y=128.0, z=-100.0}, where"
                    + " the original refuses it with FCL-V004"), r.export().message());
        }
    }
}
