package org.fclcert.probe;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.model.Diagnostic;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/** Every generated program is valid standard FCL, and the reference's answers on them agree with hand calculation. */
class FamiliesTest {
    private static void assertValid(String what, ProbeProgram p) {
        Analysis a = Analysis.analyze(new StrictReader(), what, p.fcl());
        List<Diagnostic> errors = a.diagnostics().stream().filter(Diagnostic::isError).toList();
        assertTrue(errors.isEmpty(), what + ": " + errors + "\n" + p.fcl());
        assertTrue(a.program().isPresent(), what);
    }

    private static List<ProbeProgram> all(int n) {
        List<ProbeProgram> list = new ArrayList<>(List.of(Families.inputs(n), Families.termsPerInput(n),
                Families.termsAllInputs(n, 3), Families.outputs(n), Families.termsPerOutput(n),
                Families.termsAllOutputs(n, 2, n).orElseThrow(), Families.pointsPerOutputTerm(n),
                Families.pointsAllOutputTerms(n, 3, 2, n).orElseThrow(),
                Families.pointsAllOutputTerms(n, 1, 4, n).orElseThrow(), Families.ruleBlocks(n).orElseThrow(),
                Families.rules(n, n, 1).orElseThrow(), Families.rules(n, 3, n).orElseThrow(),
                Families.subconditions(n, 4), Families.subconclusions(n, 3), Families.nesting(n),
                Families.longNames(n), Families.distinctNames(n)));
        if (n >= 2) {
            list.add(Families.pointsPerInputTerm(n));
            list.add(Families.pointsAllInputTerms(n, 3, 2, n).orElseThrow());
        }
        return list;
    }

    @Test
    void everyFamilyIsValidStandardFclAtSeveralSizes() {
        for (int n : new int[] {1, 2, 3, 5, 16, 100}) {
            List<ProbeProgram> programs = all(n);
            for (int i = 0; i < programs.size(); i++) {
                assertValid("family " + i + " at " + n, programs.get(i));
            }
        }
        for (String type : Prober.DATA_TYPES) {
            assertValid(type, Families.dataType(type));
        }
        assertValid("mixed case", Families.mixedCase());
        assertValid("workload", new ProbeProgram(Families.workload(), List.of()));
    }

    @Test
    void samplesAreTheFirstTwoBetweenAndTheLast() {
        assertArrayEquals(new int[] {0}, Families.sample(1));
        assertArrayEquals(new int[] {0, 1}, Families.sample(2));
        assertArrayEquals(new int[] {0, 33, 66, 99}, Families.sample(100));
    }

    @Test
    void termSizesSplitEvenlyWithinTheLimit() {
        assertEquals(List.of(3, 3, 2, 2), Families.termSizes(10, 3, 2));
        assertEquals(List.of(7), Families.termSizes(7, 100, 2));
        assertEquals(List.of(3, 2, 2), Families.termSizes(7, 3, 2));
    }

    private static List<Map<String, Double>> reference(ProbeProgram p) {
        return ReferenceJudge.expected(p).outputs().orElseThrow();
    }

    @Test
    void theDegreeMeterShowsTheDegree() {
        // y = d / (d + 0.5): d = 0.5 gives 1/2, d = 1 gives 2/3, d = 0 gives lo alone, 0
        List<Map<String, Double>> out = reference(new ProbeProgram(Families.meterProgram("REAL", "REAL"),
                Families.meterVectors(0.5, 1, 0)));
        assertEquals(0.5, out.get(1).get("y"), 1e-12);
        assertEquals(2.0 / 3, out.get(2).get("y"), 1e-12);
        assertEquals(0.0, out.get(3).get("y"), 1e-12);
    }

    @Test
    void theDataTypeProgramRisesFrom20To100() {
        // x = 25: lo 0.75 at 20, hi 0.25 at 100: (15 + 25) / 1 = 40; x = 50: (10 + 50) / 1 = 60
        List<Map<String, Double>> out = reference(Families.dataType("INT"));
        assertEquals(List.of(20.0, 40.0, 60.0, 100.0), out.stream().map(m -> m.get("y")).toList());
    }

    @Test
    void anOutputTermOfTwoPointsIsATriangleWithItsCentreAtTwoThirds() {
        // (0, 0) (1, 1) over RANGE (0 .. 1): centre of gravity of the triangle = 2/3; clipped at 0.5 the
        // set is min(u, 0.5): area 0.375, moment 1/24 + 0.1875 = 11/48, centre 11/18
        List<Map<String, Double>> out = reference(Families.pointsPerOutputTerm(2));
        assertEquals(2.0 / 3, out.get(0).get("y1"), 1e-12);
        assertEquals(11.0 / 18, out.get(1).get("y1"), 1e-12);
        assertEquals(0.0, out.get(2).get("y1"), 1e-12);
    }

    @Test
    void theRulesFamilyMovesYWhenASampledRuleFires() {
        // x = 0.5 fires the filler rules: base (0) at 0.5 -> y = 0; then s_k = 1 adds t_k = 10k at 1:
        // y = 10k / 1.5
        List<Map<String, Double>> out = reference(Families.rules(100, 100, 1).orElseThrow());
        assertEquals(0.0, out.get(0).get("y"), 1e-12);
        for (int k = 1; k <= 4; k++) {
            assertEquals(10.0 * k / 1.5, out.get(k).get("y"), 1e-9);
        }
    }

    @Test
    void theSubconditionsFamilyReadsTheLoweredInput() {
        // all inputs 1: d = 1 -> 2/3; then one input at 0.2k: d = 0.2k -> 0.2k / (0.2k + 0.5)
        List<Map<String, Double>> out = reference(Families.subconditions(10, 10));
        assertEquals(2.0 / 3, out.get(0).get("y"), 1e-12);
        for (int k = 1; k <= 4; k++) {
            double d = 0.2 * k;
            assertEquals(d / (d + 0.5), out.get(k).get("y"), 1e-12);
        }
    }
}
