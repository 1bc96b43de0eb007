package org.fclcert.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.model.Diagnostic;
import org.junit.jupiter.api.Test;

/** The standard's own example programs, typed in from the figures. */
class StandardExamplesTest {
    /** The findings but FCL-W005 (the crane's rules leave regions uncovered; CoverageGapsTest judges those). */
    private static List<String> summary(Analysis analysis) {
        return analysis.diagnostics().stream().filter(d -> !d.code().equals("FCL-W005"))
                .map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList();
    }

    @Test
    void valveExampleOf53IsValidWithoutAnyDiagnostic() {
        Analysis analysis = Programs.analyzeResource("standard/valve_5_3.fcl");
        assertEquals(List.of(), analysis.diagnostics());
        assertTrue(analysis.program().isPresent());
    }

    @Test
    void craneOfAnnexCAsPrintedIsRejectedAtRule2BecausePosBigIsNotATermOfPower() {
        Analysis analysis = Programs.analyzeResource("standard/crane_annex_c.fcl");
        assertTrue(analysis.program().isEmpty());
        List<Diagnostic> errors = analysis.diagnostics().stream().filter(Diagnostic::isError).toList();
        assertEquals(1, errors.size(), errors::toString);
        Diagnostic error = errors.get(0);
        assertEquals("FCL-C002", error.code());
        // line 42: "    RULE 2: IF distance IS far AND angle IS neg_small THEN power IS pos_big;", 'power' at column 60
        assertEquals(42, error.location().line());
        assertEquals(60, error.location().column());
        assertEquals("power IS pos_big: 'pos_big' is not a term of output 'power' (its terms: neg_high, neg_medium,"
                + " zero, pos_medium, pos_high); 'pos_big' is a term of input 'angle', and a conclusion sets only"
                + " outputs", error.message());
        assertEquals("standard/crane_annex_c.fcl:42:60: error FCL-C002: " + error.message(), error.toString());
    }

    @Test
    void craneOfAnnexCAsPrintedAlsoWarnsAboutItsUnusedTerms() {
        // Annex C itself says some terms are unused: distance too_far, angle pos_big; and with rule 2 pointing
        // at pos_big, the outputs neg_high (never concluded) and pos_high are unused too.
        Analysis analysis = Programs.analyzeResource("standard/crane_annex_c.fcl");
        assertEquals(List.of("FCL-W001@13:5", "FCL-W001@25:5", "FCL-W001@29:5", "FCL-C002@42:60", "FCL-W001@33:5")
                .stream().sorted(StandardExamplesTest::byPosition).toList(), summary(analysis));
    }

    @Test
    void craneOfAnnexCWithPosBigCorrectedToPosHighIsValid() {
        Analysis analysis = Programs.analyzeResource("standard/crane_annex_c_corrected.fcl");
        assertTrue(analysis.program().isPresent());
        assertEquals(List.of("FCL-W001@13:5", "FCL-W001@25:5", "FCL-W001@29:5"), summary(analysis));
    }

    @Test
    void ovenOfAnnexDAsPrintedIsRejectedByTheReaderAtColorEqualsBrownAndAtAndBetweenSubconclusions() {
        Analysis analysis = Programs.analyzeResource("standard/oven_annex_d.fcl");
        assertTrue(analysis.program().isEmpty());
        List<String> found = summary(analysis);
        // line 45: "    RULE1: IF humidity IS middle AND color = brown THEN dT1 IS zero", '=' at column 44;
        // line 46: "        AND dT2 IS zero;", the AND at column 9
        assertTrue(found.contains("FCL-S025@45:44"), found::toString);
        assertTrue(found.contains("FCL-S028@46:9"), found::toString);
    }

    @Test
    void ovenOfAnnexDWrittenInFclIsValidAndReadsTheColourClassesAsBareInputVariables() {
        Analysis analysis = Programs.analyzeResource("standard/oven_annex_d_corrected.fcl");
        // by hand: low is 0 from 50 up, high 0 up to 70, and rules 1, 4 and 5 need a colour above 0 (clamped)
        assertEquals(List.of("standard/oven_annex_d_corrected.fcl:36:1: warning FCL-W005: humidity in [50, 70] and"
                + " brown in (-inf, 0] and light in (-inf, 0] and dark in (-inf, 0]: no rule of block 'inference'"
                + " fires; dT1 takes DEFAULT 0, dT2 takes DEFAULT 0"),
                analysis.diagnostics().stream().map(Diagnostic::toString).toList());
        FeatureReport report = new FeatureDetector().detect(analysis.program().orElseThrow());
        List<String> conditionVariables = report.uses().stream()
                .filter(u -> u.feature().id().equals("E-COND-VARIABLE")).map(u -> "line " + u.location().line()).toList();
        assertEquals(List.of("line 39", "line 42", "line 43"), conditionVariables);
    }

    private static int byPosition(String a, String b) {
        return Integer.compare(line(a), line(b));
    }

    private static int line(String s) {
        return Integer.parseInt(s.substring(s.indexOf('@') + 1, s.indexOf(':')));
    }
}
