package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The lint on small hand-made corpora, each wrong in one known way. */
class CorpusLintTest {
    @TempDir
    Path dir;

    /** Figure 7 without its WITH (B-COGS-001's program) and one vector: temp 5, pressure 60 gives 950/13. */
    private static final String PROGRAM = """
            FUNCTION_BLOCK valve_control
            VAR_INPUT
                temp : REAL;
                pressure : REAL;
            END_VAR
            VAR_OUTPUT
                valve : REAL;
            END_VAR
            FUZZIFY temp
                TERM cold := (3, 1) (27, 0);
                TERM hot := (3, 0) (27, 1);
            END_FUZZIFY
            FUZZIFY pressure
                TERM low := (55, 1) (95, 0);
                TERM high := (55, 0) (95, 1);
            END_FUZZIFY
            DEFUZZIFY valve
                TERM drainage := -100;
                TERM closed := 0;
                TERM inlet := 100;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF temp IS cold AND pressure IS low THEN valve IS inlet;
                RULE 2 : IF temp IS cold AND pressure IS high THEN valve IS closed;
                RULE 3 : IF temp IS hot AND pressure IS low THEN valve IS closed;
                RULE 4 : IF temp IS hot AND pressure IS high THEN valve IS drainage;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private static final String FEATURES = "[B-FB, B-IN-TERM, B-OUT-SINGLETON, B-AND-MIN, B-ACCU-MAX, B-COGS, "
            + "B-DEFAULT-VALUE, B-ONE-RULEBLOCK, B-SUBCONDITIONS, B-ONE-SUBCONCLUSION]";

    // the metadata takes lines 1..13, so the program's line n is the file's line n + 13
    private static final String GOOD = """
            (*---
            id: B-COGS-001
            title: valve
            level: basic
            features: %s
            tests: [B-COGS]
            tolerance: exact
            flags: []
            derivation: (87.5 - 100/12) / (13/12) = 950/13
            vectors:
              - in: {temp: 5, pressure: 60}
                out: {valve: 73.07692307692308}
            ---*)
            """.formatted(FEATURES) + PROGRAM;

    private static final String NEGATIVE = """
            (*---
            id: N-C002-001
            title: undefined term
            level: basic
            features: %s
            tests: []
            expect: reject
            error: {code: FCL-C002, line: 40}
            ---*)
            """.formatted(FEATURES) + PROGRAM.replace("pressure IS high THEN valve IS closed",
            "pressure IS medium THEN valve IS closed");   // 9 metadata lines: rule 2 (program line 28) is file line 37

    private void write(String relative, String text) throws IOException {
        Path p = dir.resolve(relative);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
    }

    private List<String> findings() {
        return new CorpusLint().lint(dir).caseFindings().stream().map(CorpusProblem::toString).toList();
    }

    private void assertOneFinding(String fragment) {
        List<String> f = findings();
        assertEquals(1, f.size(), f.toString());
        assertTrue(f.get(0).contains(fragment), f.get(0));
    }

    @Test
    void aCorrectCaseHasNoFinding() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD);
        assertEquals(List.of(), findings());
    }

    @Test
    void aWrongExpectationIsShownWithTheExactNumbers() throws IOException {
        // per-rule CoGS accumulation would give 950/14 = 67.857...
        write("basic/B-COGS-001.fcl", GOOD.replace("73.07692307692308", "67.85714285714286"));
        assertOneFinding(":10: vector 1: 'valve' expected 67.85714285714286, the reference evaluator gives "
                + "73.07692307692308 (error 5.2197802197802");   // 950/13 - 950/14 = 950/182
    }

    @Test
    void aFeatureTheDetectorFindsButTheCaseDoesNotDeclareIsReportedWhereItIsUsed() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD.replace(" B-DEFAULT-VALUE,", ""));
        // DEFAULT := 0 is program line 22, file line 35
        assertOneFinding("B-COGS-001.fcl:35: the program uses B-DEFAULT-VALUE");
    }

    @Test
    void aDeclaredFeatureTheProgramDoesNotUseIsReported() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD.replace("B-ONE-SUBCONCLUSION]", "B-ONE-SUBCONCLUSION, E-NOT]")
                .replace("level: basic", "level: extension").replace("basic/", "extension/"));
        List<String> f = findings();
        assertTrue(f.stream().anyMatch(s -> s.contains("declares E-NOT but the feature detector does not find it")), f.toString());
        assertTrue(f.stream().anyMatch(s -> s.contains("level is extension but the program's features make it basic")),
                f.toString());
    }

    /** conformance/README.md, Tolerance: a CoG over point terms judged exactly would fail every correct integrator. */
    @Test
    void anOutputDefuzzifiedByCoGOverPointTermsMustBeJudgedContinuous() throws IOException {
        String cog = java.nio.file.Files.readString(java.nio.file.Path.of("conformance/extension/E-COG-073.fcl"));
        write("extension/E-COG-073.fcl", cog);
        assertEquals(List.of(), findings());
        write("extension/E-COG-073.fcl", cog.replace("tolerance: continuous", "tolerance: exact"));
        assertOneFinding("E-COG-073.fcl:1: output 'y' is defuzzified by CoG over point terms: its tolerance must be "
                + "continuous, not exact");
    }

    @Test
    void testsMustBeAmongTheFeatures() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD.replace("tests: [B-COGS]", "tests: [B-COGS, E-LM]"));
        assertOneFinding("'tests' names features the case does not use: [E-LM]");
    }

    @Test
    void aBasicCaseNeedsADerivation() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD.replace("derivation: (87.5 - 100/12) / (13/12) = 950/13\n", ""));
        assertOneFinding("a Basic case needs a 'derivation'");
    }

    @Test
    void idMustMatchFileNameDirectoryAndNotBeRetired() throws IOException {
        write("extension/B-COGS-002.fcl", GOOD);
        write("RETIRED", "# retired ids\nB-COGS-001   renamed when ...\n");
        List<String> f = findings();
        assertEquals(3, f.size(), f.toString());
        assertTrue(f.get(0).contains("id B-COGS-001 does not match the file name B-COGS-002.fcl"), f.get(0));
        assertTrue(f.get(1).contains("id B-COGS-001 is retired"), f.get(1));
        assertTrue(f.get(2).contains("a basic case belongs in the directory basic/"), f.get(2));
    }

    @Test
    void aCaseWhoseStepsDependOnEachOtherMustBeFlaggedStateful() throws IOException {
        // the second step sets only temp: pressure keeps 60 from the first step
        String twoSteps = GOOD.replace("""
                    out: {valve: 73.07692307692308}
                """, """
                    out: {valve: 73.07692307692308}
                  - in: {temp: 5}
                    out: {valve: 73.07692307692308}
                """);
        write("basic/B-COGS-001.fcl", twoSteps);
        assertOneFinding("vector 2 depends on the steps before it");
        write("basic/B-COGS-001.fcl", twoSteps.replace("flags: []", "flags: [stateful]"));
        assertEquals(List.of(), findings());
    }

    @Test
    void aNegativeCaseMustHaveExactlyItsDeclaredError() throws IOException {
        write("negative/N-C002-001.fcl", NEGATIVE.replace("line: 40", "line: 37"));
        assertEquals(List.of(), findings());
        write("negative/N-C002-001.fcl", NEGATIVE);
        assertOneFinding("expected error FCL-C002 at line 40, the analysis found");
        write("negative/N-C002-001.fcl", NEGATIVE.replace("line: 40", "line: 37")
                .replace("THEN valve IS inlet", "THEN valve IS intake"));
        assertOneFinding("a negative case must have exactly one error, the analysis found 2");
    }

    @Test
    void aPositiveCaseWhoseProgramHasAnErrorIsReported() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD.replace("    METHOD : CoGS;\n", ""));
        List<String> f = findings();
        assertTrue(f.get(0).contains("the program of a positive case has an error") && f.get(0).contains("FCL-C016"),
                f.toString());
    }

    @Test
    void coverageCountsPositiveTestsTargetsAndNegativeCases() throws IOException {
        write("basic/B-COGS-001.fcl", GOOD);
        List<String> gaps = new CorpusLint().lint(dir).coverageGaps();
        assertTrue(gaps.contains("B-COGS (Table 8, METHOD CoGS, centre of gravity for singletons) is the 'tests' "
                + "target of 1 positive case(s); at least 3 needed"), gaps.toString());
        assertTrue(gaps.contains("0 negative case(s); at least 40 needed"), gaps.toString());
        assertTrue(gaps.stream().anyMatch(g -> g.startsWith("O-VAR-DEGREE") && g.endsWith("at least 1 needed")),
                gaps.toString());
    }

    /*
     * LM over singletons lo = 0, hi = 100 with degrees 1 − a and a. a = 0.5 ties them: LM = 0, but a one ulp
     * higher gives hi the larger degree and LM = 100: vector 1 is a knife edge. a = 0.8: hi alone, LM = 100, fair.
     */
    private static final String KNIFE = """
            (*---
            id: E-LM-009
            title: tie
            level: extension
            features: [B-FB]
            tests: [B-FB]
            tolerance: exact
            flags: %s
            vectors:
              - in: {a: 0.5}
                out: {y: 0.0}
              - in: {a: 0.8}
                out: {y: 100.0}
            ---*)
            FUNCTION_BLOCK tie
            VAR_INPUT a : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY a TERM on := (0, 0) (1, 1); END_FUZZIFY
            DEFUZZIFY y TERM lo := 0; TERM hi := 100; METHOD : LM; DEFAULT := -1; END_DEFUZZIFY
            RULEBLOCK r AND : MIN; ACCU : MAX;
                RULE 1 : IF a IS on THEN y IS hi;
                RULE 2 : IF a IS NOT on THEN y IS lo;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private List<String> fairnessFindings() {
        return findings().stream().filter(f -> f.contains("knife")).toList();
    }

    @Test
    void aKnifeEdgeVectorMustBeFlaggedAndAFlaggedVectorMustBeOne() throws IOException {
        write("extension/E-LM-009.fcl", KNIFE.formatted("[]"));
        List<String> f = fairnessFindings();
        assertEquals(1, f.size(), f.toString());
        assertTrue(f.get(0).contains("vector 1 is a knife edge, not fair to judge: step 1: y = 0.0, but 100.0 with input a"
                + " one ulp up") && f.get(0).contains("flag the case knife-edge:1"), f.get(0));
        write("extension/E-LM-009.fcl", KNIFE.formatted("[knife-edge:1]"));
        assertEquals(List.of(), fairnessFindings());
        write("extension/E-LM-009.fcl", KNIFE.formatted("[knife-edge:1, knife-edge:2]"));
        f = fairnessFindings();
        assertEquals(2, f.size(), f.toString());
        assertTrue(f.get(0).contains("flag knife-edge:2, but vector 2 is fair to judge; remove the flag"), f.toString());
        assertTrue(f.get(1).contains("every vector is flagged knife-edge"), f.toString());
    }

    /** GOOD with a SINT output whose inlet is 200: at temp 5, pressure 60 the CoGS is (175 - 25/3) / (13/12) = 153.8. */
    private static String refusing(String flags, String vectors) {
        return GOOD.replace("flags: []", "flags: " + flags)
                .replace("""
                          - in: {temp: 5, pressure: 60}
                            out: {valve: 73.07692307692308}
                        """, vectors)
                .replace("valve : REAL;", "valve : SINT;").replace("TERM inlet := 100;", "TERM inlet := 200;");
    }

    private static final String REFUSED_THEN_DRAINAGE = """
              - in: {temp: 5, pressure: 60}
                error: FCL-V004
              - in: {temp: 27, pressure: 95}
                out: {valve: -100}
            """;

    @Test
    void aStepTheReferenceRefusesWithTheCodeNamedIsClean() throws IOException {
        write("basic/B-COGS-001.fcl", refusing("[]", REFUSED_THEN_DRAINAGE));
        assertEquals(List.of(), findings());
    }

    @Test
    void aRefusedStepMustBeRefusedWithItsCode() throws IOException {
        write("basic/B-COGS-001.fcl", refusing("[]", REFUSED_THEN_DRAINAGE.replace("FCL-V004", "FCL-V006")));
        assertOneFinding("vector 1: expected the evaluation to be refused with FCL-V006, the reference evaluator refuses"
                + " it with FCL-V004: value 153.84615384615");
        write("basic/B-COGS-001.fcl", refusing("[]", REFUSED_THEN_DRAINAGE.replace("pressure: 60}", "pressure: 95}")));
        // temp 5, pressure 95: closed at 11/12, drainage at 1/12: -100/12 = -8.33, stored as SINT -8
        assertOneFinding("vector 1: expected the evaluation to be refused with FCL-V004, the reference evaluator gives"
                + " {valve=-8.0}");
    }

    @Test
    void onlyTheErrorsAProgramCanCauseMayBeExpected() throws IOException {
        write("basic/B-COGS-001.fcl", refusing("[]", REFUSED_THEN_DRAINAGE.replace("FCL-V004", "FCL-V001")));
        assertOneFinding("vector 1: 'error' must name an evaluation error a program can cause (FCL-V004, FCL-V005,"
                + " FCL-V006), not 'FCL-V001'");
    }

    @Test
    void noRefusedStepInAStatefulCaseNorOnlyRefusedSteps() throws IOException {
        write("basic/B-COGS-001.fcl", refusing("[stateful]", REFUSED_THEN_DRAINAGE));
        assertOneFinding("a stateful case cannot expect a step to be refused");
        write("basic/B-COGS-001.fcl", refusing("[]", """
                  - in: {temp: 5, pressure: 60}
                    error: FCL-V004
                """));
        assertOneFinding("every step expects an evaluation error: a case needs a step with outputs too");
    }
}
