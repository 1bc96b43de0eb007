package org.fclcert.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Program;
import org.junit.jupiter.api.Test;

/**
 * Exact feature uses ({@code id@line}, sorted) of whole programs; the expectations are read off the
 * program texts by hand, following the detection table in docs/conformance-features.md.
 */
class FeatureDetectorTest {
    private final FeatureDetector detector = new FeatureDetector();

    private static Program valid(String name, String text) {
        Analysis analysis = Programs.analyze(name, text);
        // a minimal program may leave inputs where no rule fires (FCL-W005): not what feature detection is about
        assertEquals(List.of(), analysis.diagnostics().stream().filter(d -> !d.code().equals("FCL-W005")).toList(),
                name + " must be a clean program");
        return analysis.program().orElseThrow();
    }

    private static List<String> uses(FeatureReport report) {
        return report.uses().stream().map(u -> u.feature().id() + "@" + u.location().line()).sorted().toList();
    }

    private static List<String> sorted(String... expected) {
        List<String> list = new ArrayList<>(List.of(expected));
        list.sort(null);
        return list;
    }

    private static final String[] VALVE_BASIC = {
        "B-FB@1",
        "B-IN-TERM@10", "B-IN-TERM@11", "B-IN-TERM@14", "B-IN-TERM@15",
        "B-OUT-SINGLETON@18", "B-OUT-SINGLETON@19", "B-OUT-SINGLETON@20",
        "B-COGS@21", "B-DEFAULT-VALUE@22",
        "B-ONE-RULEBLOCK@24", "B-AND-MIN@25", "B-ACCU-MAX@26",
        "B-SUBCONDITIONS@27", "B-SUBCONDITIONS@27", "B-ONE-SUBCONCLUSION@27",
        "B-SUBCONDITIONS@28", "B-SUBCONDITIONS@28", "B-ONE-SUBCONCLUSION@28",
        "B-SUBCONDITIONS@29", "B-SUBCONDITIONS@29", "B-ONE-SUBCONCLUSION@29",
        "B-SUBCONDITIONS@30", "B-SUBCONDITIONS@30", "B-ONE-SUBCONCLUSION@30",
    };

    @Test
    void valveOf53WithoutItsWeightingFactorUsesExactlyTheBasicSet() {
        String text = Programs.text("standard/valve_5_3.fcl").replace(" WITH 0.8;", ";");
        FeatureReport report = detector.detect(valid("valve.fcl", text));
        assertEquals(sorted(VALVE_BASIC), uses(report));
        assertEquals(ConformanceLevel.BASIC, report.level());
    }

    @Test
    void valveOf53AsPrintedNeedsTheExtensionForItsConstantWeightingFactor() {
        // Table 8 has no weighting factor row; WITH with a constant is Table 9's (rule 2, line 28)
        FeatureReport report = detector.detect(valid("valve.fcl", Programs.text("standard/valve_5_3.fcl")));
        List<String> expected = new ArrayList<>(List.of(VALVE_BASIC));
        expected.add("E-WITH-CONST@28");
        expected.sort(null);
        assertEquals(expected, uses(report));
        assertEquals(ConformanceLevel.EXTENSION, report.level());
    }

    @Test
    void extensionProgramUsesEachExtensionFeatureWhereWritten() {
        FeatureReport report = detector.detect(valid("extension.fcl", Programs.text("features/extension.fcl")));
        assertEquals(sorted(
                "B-FB@1",
                "E-VAR-LOCAL@12",
                "E-IN-TERM-4@15",            // cold: four constant points
                "E-TERM-VARIABLE-POINT@16",  // ok: (setpoint, 1); three points but not constant, so not B-IN-TERM
                "B-IN-TERM@17",
                "E-RANGE@20", "E-OUT-TERM-4@21", "E-OUT-TERM-4@22", "E-COG@23", "B-DEFAULT-NC@24",
                "E-AND-PROD@27", "E-ACT-MIN@28", "E-ACCU-BSUM@29",
                // rule 1: OR implied by AND: PROD is ASUM; parentheses; NOT; second subconclusion is a bare local
                "B-SUBCONDITIONS@30", "B-SUBCONDITIONS@30", "B-SUBCONDITIONS@30", "E-OR-ASUM@30", "E-PARENS@30",
                "E-NOT@30", "E-SUBCONCLUSIONS@30",
                // rule 2: IS NOT, one subconclusion, constant weight
                "B-SUBCONDITIONS@31", "E-NOT@31", "B-ONE-SUBCONCLUSION@31", "E-WITH-CONST@31",
                // second rule block: only OR: ASUM declared, so its AND is PROD; no ACT on point terms: MIN
                "E-RULEBLOCKS@33", "E-ACT-MIN@33", "E-OR-ASUM@34", "E-ACCU-BSUM@35",
                "E-COND-VARIABLE@36", "B-SUBCONDITIONS@36", "E-AND-PROD@36",
                "E-SUBCONCLUSIONS@36", "E-WITH-VAR@36"), uses(report));
        assertEquals(ConformanceLevel.EXTENSION, report.level());
    }

    @Test
    void openProgramUsesManyPointsIntermediateDegreesAndVariableDegrees() {
        FeatureReport report = detector.detect(valid("open.fcl", Programs.text("features/open.fcl")));
        assertEquals(sorted(
                "B-FB@1",
                "O-MANY-POINTS@10", "O-DEGREES-0-1@10", "O-DEGREES-0-1@10", "O-DEGREES-0-1@10",
                "O-VAR-DEGREE@11",
                "B-OUT-SINGLETON@14", "B-OUT-SINGLETON@15", "B-COGS@16", "B-DEFAULT-VALUE@17",
                "B-ONE-RULEBLOCK@19", "B-AND-MIN@20", "B-ACCU-MAX@21",
                "B-SUBCONDITIONS@22", "B-ONE-SUBCONCLUSION@22", "B-SUBCONDITIONS@23", "B-ONE-SUBCONCLUSION@23"),
                uses(report));
        assertEquals(ConformanceLevel.OPEN, report.level());
    }

    @Test
    void methodsAndImpliedOperatorPairsInTwoFunctionBlocks() {
        FeatureReport report = detector.detect(valid("methods.fcl", Programs.text("features/methods.fcl")));
        assertEquals(sorted(
                "B-FB@1", "B-IN-TERM@11", "B-IN-TERM@12",
                "E-OUT-TERM-4@15", "E-COA@16", "B-DEFAULT-VALUE@17",
                "E-OUT-TERM-4@20", "E-LM@21", "B-DEFAULT-VALUE@22",
                "E-OUT-TERM-4@25", "E-RM@26", "B-DEFAULT-VALUE@27",
                "B-ONE-RULEBLOCK@29", "E-OR-BSUM@30", "E-ACT-PROD@31", "E-ACCU-NSUM@32",
                // only OR: BSUM declared: the AND of rule 1 is its Table 3 pair BDIF
                "B-SUBCONDITIONS@33", "B-SUBCONDITIONS@33", "E-AND-BDIF@33", "B-ONE-SUBCONCLUSION@33",
                "B-SUBCONDITIONS@34", "B-SUBCONDITIONS@34", "E-SUBCONCLUSIONS@34",
                "B-FB@37", "B-IN-TERM@45", "B-IN-TERM@46", "B-OUT-SINGLETON@49", "B-COGS@50", "B-DEFAULT-NC@51",
                "B-ONE-RULEBLOCK@53", "B-AND-MIN@54", "B-ACCU-MAX@55",
                // only AND: MIN declared: the OR is its pair MAX, in no table (README errata)
                "B-SUBCONDITIONS@56", "B-SUBCONDITIONS@56", "E-OR-MAX@56", "B-ONE-SUBCONCLUSION@56"), uses(report));
        assertEquals(ConformanceLevel.EXTENSION, report.level());
    }

    @Test
    void variablePointsInFourPointTermsVariableSingletonsManyPointOutputsAndDeclaredPairs() {
        FeatureReport report = detector.detect(valid("corners.fcl", Programs.text("features/corners.fcl")));
        assertEquals(sorted(
                "B-FB@1",
                "E-IN-TERM-4@12", "E-TERM-VARIABLE-POINT@12",   // four points, one of them (bp, 1)
                "B-IN-TERM@13",
                "E-TERM-VARIABLE-POINT@16", "B-OUT-SINGLETON@17", "B-COGS@18", "B-DEFAULT-VALUE@19",
                // five output points, two degrees of 0.5: not E-OUT-TERM-4
                "E-RANGE@22", "O-MANY-POINTS@23", "O-DEGREES-0-1@23", "O-DEGREES-0-1@23", "E-COG@24",
                "B-DEFAULT-VALUE@25",
                "E-AND-BDIF@28", "E-OR-BSUM@29", "B-ACCU-MAX@30",
                "B-SUBCONDITIONS@31", "B-SUBCONDITIONS@31", "B-ONE-SUBCONCLUSION@31",
                "B-SUBCONDITIONS@32", "B-SUBCONDITIONS@32", "B-ONE-SUBCONCLUSION@32",
                // second block declares only OR: MAX, so its AND is MIN (Basic)
                "E-RULEBLOCKS@34", "E-ACT-MIN@34", "E-OR-MAX@35", "B-ACCU-MAX@36",   // no ACT on point terms: MIN
                "B-SUBCONDITIONS@37", "B-SUBCONDITIONS@37", "B-AND-MIN@37", "B-ONE-SUBCONCLUSION@37"), uses(report));
        assertEquals(ConformanceLevel.OPEN, report.level());
    }

    @Test
    void usesAreSortedByLocation() {
        FeatureReport report = detector.detect(valid("extension.fcl", Programs.text("features/extension.fcl")));
        for (int i = 1; i < report.uses().size(); i++) {
            assertTrue(report.uses().get(i - 1).location().compareTo(report.uses().get(i).location()) <= 0);
        }
    }

    /*
     * Without ACT a block concluding on point terms is activated by MIN (docs/semantics.md, point 3): E-ACT-MIN at
     * the rule block (line 9), as implied AND/OR are counted. On singleton terms MIN and PROD agree: no feature.
     */
    @Test
    void impliedActivationByMinIsCountedAtTheRuleBlock() {
        String points = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM up := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y
                  TERM t := (0, 0) (5, 1) (10, 0);
                  METHOD : CoG; DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK r
                  AND : MIN; ACCU : MAX;
                  RULE 1 : IF x IS up THEN y IS t;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        assertTrue(uses(detector.detect(valid("p.fcl", points))).contains("E-ACT-MIN@9"));
        String singletons = points.replace("TERM t := (0, 0) (5, 1) (10, 0);", "TERM t := 5;")
                .replace("METHOD : CoG;", "METHOD : CoGS;");
        assertTrue(uses(detector.detect(valid("s.fcl", singletons))).stream().noneMatch(u -> u.startsWith("E-ACT")));
        assertTrue(uses(detector.detect(valid("a.fcl", points.replace("AND : MIN;", "AND : MIN; ACT : PROD;"))))
                .stream().noneMatch(u -> u.startsWith("E-ACT-MIN")));
    }
}
