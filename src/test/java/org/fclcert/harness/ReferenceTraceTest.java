package org.fclcert.harness;

import static org.fclcert.harness.TestCases.step;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.corpus.Vector;
import org.fclcert.model.ConformanceLevel;
import org.junit.jupiter.api.Test;

/** The reference's trace at a failing step: which rules fired with which degrees, and how each output got its value. */
class ReferenceTraceTest {
    /**
     * low rises from 0 at 0 to 1 at 2 and falls to 0 at 4; high rises from 6 to 1 at 8 and falls to 0 at 10. At
     * level 3 low is 0.5 and high 0; at level 5 both are 0; at level 7 low is 0 and high 0.5. Hand calculation:
     * level 3 → RULE 1 at 0.5, valve = 100 (CoGS of one singleton); level 5 → nothing fires, DEFAULT 50;
     * level 7 → RULE 2 at 0.5, activated 0.5 × WITH 0.5 = 0.25 on shut, valve = 0.
     */
    private static final String PROGRAM = """
            FUNCTION_BLOCK tank
            VAR_INPUT
                level : REAL;
            END_VAR
            VAR_OUTPUT
                valve : REAL;
            END_VAR
            FUZZIFY level
                TERM low := (0, 0) (2, 1) (4, 0);
                TERM high := (6, 0) (8, 1) (10, 0);
            END_FUZZIFY
            DEFUZZIFY valve
                TERM shut := 0;
                TERM open := 100;
                METHOD : CoGS;
                DEFAULT := 50;
            END_DEFUZZIFY
            RULEBLOCK r
                ACCU : MAX;
                RULE 1 : IF level IS low THEN valve IS open;
                RULE 2 : IF level IS high THEN valve IS shut WITH 0.5;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private static RunCase tank(List<Vector> vectors) {
        return new RunCase("B-DEFAULT-VALUE-001", "tank", ConformanceLevel.BASIC, List.of("B-DEFAULT-VALUE"),
                List.of("B-DEFAULT-VALUE"), List.of(), Optional.empty(), vectors, Optional.empty(), Tolerances.exact(),
                PROGRAM, "tank.fcl");
    }

    private static CaseResult run(RunCase c, ScriptedIut.Evaluation answers) throws IOException {
        List<CaseResult> results = new ArrayList<>();
        new Runner((text, x) -> new ExportCheck.Verdict(ExportStatus.PASSED, ""), RunListener.NONE)
                .run(ScriptedIut.loading(answers), null, List.of(c), new ResultSink() {
                    @Override
                    public void header(RunHeader header) {
                    }

                    @Override
                    public void accept(CaseResult result) {
                        results.add(result);
                    }
                });
        return results.get(0);
    }

    @Test
    void noRuleFiredSoDefaultApplies() throws IOException {
        RunCase c = tank(List.of(step(Map.of("level", 3.0), Map.of("valve", 100.0)),
                step(Map.of("level", 5.0), Map.of("valve", 50.0))));
        // right at step 1, wrong at step 2 (an implementation that keeps the last value instead of DEFAULT)
        CaseResult r = run(c, (call, in) -> Map.of("valve", 100.0));
        assertEquals(CaseStatus.FAILED, r.status());
        ReferenceTrace t = r.evidence().reference();
        assertEquals(2, t.step());
        assertEquals(List.of("no rule fired (2 rules, every degree 0)",
                "no rule fired → DEFAULT applies: valve = 50"), t.lines());
        assertEquals("default", t.output("VALVE").outcome());
    }

    @Test
    void whichRulesFiredWithWhichDegreesAndTheSingletonsTheyGave() throws IOException {
        RunCase c = tank(List.of(step(Map.of("level", 7.0), Map.of("valve", 0.0))));
        CaseResult r = run(c, (call, in) -> Map.of("valve", 12.0));
        ReferenceTrace t = r.evidence().reference();
        assertEquals(1, t.step());
        assertEquals(List.of("rules fired: RULE 2 at 0.5 → valve IS shut WITH 0.5",
                "not fired (degree 0): RULE 1",
                "valve = 0, defuzzified from the singletons 0 (degree 0.25)"), t.lines());
        ReferenceTrace.OutputValue valve = t.output("valve");
        assertEquals(List.of(List.of(0.0, 0.25), List.of(100.0, 0.0)), valve.set());
        assertEquals(true, valve.singletons());
    }

    @Test
    void theTraceTravelsThroughResultsJsonl() throws IOException {
        RunCase c = tank(List.of(step(Map.of("level", 3.0), Map.of("valve", 100.0))));
        CaseResult r = run(c, (call, in) -> Map.of("valve", 99.0));
        String line = Json.mapper().writeValueAsString(r);
        CaseResult back = Json.mapper().readValue(line, CaseResult.class);
        assertEquals(r.evidence().reference(), back.evidence().reference(), line);
        assertEquals(List.of("rules fired: RULE 1 at 0.5 → valve IS open", "not fired (degree 0): RULE 2",
                "valve = 100, defuzzified from the singletons 100 (degree 0.5)"), back.evidence().reference().lines());
    }

    @Test
    void aPassingCaseAndANegativeCaseCarryNoTrace() throws IOException {
        RunCase c = tank(List.of(step(Map.of("level", 3.0), Map.of("valve", 100.0))));
        assertNull(run(c, (call, in) -> Map.of("valve", 100.0)).evidence().reference());
        assertNull(ReferenceTraces.at(TestCases.negative("B-FB-901", "FCL-S001", 1), 1));
    }

    /**
     * docs/images/e-or-max-001-jfuzzylogic-set.svg is the picture report.html drew for jFuzzyLogic on E-OR-MAX-001
     * (it computed 9.09090909090909 at step 1, 'a OR b AND c' read left to right); it stays what the reference
     * evaluator and SetPicture draw for that step.
     */
    @Test
    void theReadmePictureOfAnAccumulatedSetIsWhatTheReportDraws() throws Exception {
        RunCase c = RunCases.from(org.fclcert.corpus.Corpus.load(java.nio.file.Path.of("conformance"))
                .byId("E-OR-MAX-001").orElseThrow());
        ReferenceTrace t = ReferenceTraces.at(c, 1);
        ReferenceTrace.OutputValue y = t.output("y");
        // by hand (the case's derivation): RULE 1 at 0.8 concludes hi (100), RULE 2 at 1 lo (0): CoGS 80/1.8
        assertEquals(List.of(List.of(0.0, 1.0), List.of(100.0, 0.8)), y.set());
        String svg = org.fclcert.plot.SetPicture.svg("E-OR-MAX-001, step 1: accumulated set of y", "y", y.singletons(),
                y.set(), c.vectors().get(0).out().get("y"), 9.09090909090909);
        assertEquals(java.nio.file.Files.readString(java.nio.file.Path.of("docs/images/e-or-max-001-jfuzzylogic-set.svg")),
                svg);
    }

    /**
     * B-FB-006 at step 1 (x = 1): lo 7/8 → down -20, hi 1/8 → up 80; CoGS = (-20·7/8 + 80·1/8) / 1 = -7.5, which the
     * INT output rounds half away from zero to -8. The trace says so, or -8 would not follow from the singletons.
     */
    @Test
    void anIntegerOutputShowsItsRounding() throws Exception {
        RunCase c = RunCases.from(org.fclcert.corpus.Corpus.load(java.nio.file.Path.of("conformance"))
                .byId("B-FB-006").orElseThrow());
        ReferenceTrace t = ReferenceTraces.at(c, 1);
        assertEquals("cmd = -8, defuzzified from the singletons -20 (degree 0.875), 80 (degree 0.125); that is -7.5,"
                + " rounded half away from zero to the output's integer type: cmd = -8", t.lines().get(t.lines().size() - 1));
        assertEquals(-7.5, t.output("cmd").computed());
        // a REAL output is not converted: no rounding clause, nothing recorded
        RunCase real = tank(List.of(step(Map.of("level", 7.0), Map.of("valve", 0.0))));
        assertNull(ReferenceTraces.at(real, 1).output("valve").computed());
    }

    @Test
    void numbersAreShortButExact() {
        assertEquals("85.7143", ReferenceTrace.number(600 / 7.0));
        assertEquals("0.125", ReferenceTrace.number(0.125));
        assertEquals("-3", ReferenceTrace.number(-3.0));
        assertEquals("1e-07", ReferenceTrace.number(1e-7));
    }
}
