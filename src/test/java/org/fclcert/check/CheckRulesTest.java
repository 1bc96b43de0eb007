package org.fclcert.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.model.Diagnostic;
import org.junit.jupiter.api.Test;

/** Finer points of individual rules: what they accept, what they report, how their messages read. */
class CheckRulesTest {
    /** The base of the negative programs (without its expectation line): clean, no findings. */
    private static final String BASE = """
            FUNCTION_BLOCK t
            VAR_INPUT
                temp : REAL;
            END_VAR
            VAR_OUTPUT
                valve : REAL;
            END_VAR
            FUZZIFY temp
                TERM cold := (3, 1) (27, 0);
                TERM hot := (3, 0) (27, 1);
            END_FUZZIFY
            DEFUZZIFY valve
                TERM closed := 0;
                TERM open := 100;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK r
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF temp IS cold THEN valve IS open;
                RULE 2 : IF temp IS hot THEN valve IS closed;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;
    private static final String RULE2 = "    RULE 2 : IF temp IS hot THEN valve IS closed;\n";

    private static List<Diagnostic> check(String text) {
        return Programs.analyze("t.fcl", text).diagnostics();
    }

    private static List<String> codes(String text) {
        return check(text).stream().map(d -> d.code() + "@" + d.location().line()).toList();
    }

    private static String withRule(String rule) {
        return BASE.replace(RULE2, RULE2 + "    " + rule + "\n");
    }

    @Test
    void baseProgramIsClean() {
        assertEquals(List.of(), check(BASE));
    }

    @Test
    void namesAreComparedWithoutRegardToCase() {
        assertEquals(List.of(), check(withRule("RULE 3 : IF TEMP IS HOT THEN Valve IS Closed;")));
    }

    @Test
    void ruleNumbersAreComparedAsNumbers() {
        assertEquals(List.of("FCL-C007@23"), codes(withRule("RULE 02 : IF temp IS hot THEN valve IS closed;")));
    }

    @Test
    void aVerticalStepOfEqualXIsAllowed() {
        assertEquals(List.of(), check(BASE.replace("TERM cold := (3, 1) (27, 0);", "TERM cold := (3, 1) (3, 0.5) (27, 0);")));
    }

    @Test
    void constantPointsAreComparedAcrossAVariablePoint() {
        String text = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    bp : REAL;\n")
                .replace("TERM cold := (3, 1) (27, 0);", "TERM cold := (20, 1) (bp, 0.5) (10, 0);");
        assertEquals(List.of("FCL-C010@10"), codes(text));
        String ok = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    bp : REAL;\n")
                .replace("TERM cold := (3, 1) (27, 0);", "TERM cold := (3, 1) (bp, 0.5) (27, 0);");
        assertEquals(List.of(), check(ok));
    }

    @Test
    void anUndefinedVariableIsReportedOnceNotAlsoAsAnUndefinedTerm() {
        List<Diagnostic> found = check(withRule("RULE 3 : IF tmp IS warm THEN valve IS closed;"));
        assertEquals(1, found.size(), found::toString);
        assertEquals("tmp IS warm: 'tmp' is not a declared variable of function block 't'; did you mean 'temp'?"
                + " (its variables: temp, valve); or declare it in VAR_INPUT (5.2.1)", found.get(0).message());
    }

    @Test
    void aMisspeltTermGetsADidYouMeanAndTheTermItMeantIsNotReportedUnused() {
        // 'cold' is used only through the typo: W001 "cold is never used" would be a knock-on of it
        String text = BASE.replace("IF temp IS cold THEN", "IF temp IS clod THEN");
        List<Diagnostic> found = check(text);
        assertEquals(List.of("FCL-C002@21"), codes(text), found::toString);
        assertEquals("temp IS clod: 'clod' is not a term of input 'temp'; did you mean 'cold'? (its terms: cold, hot)",
                found.get(0).message());
    }

    @Test
    void aMisspeltVariableGetsADidYouMeanAndItsTermsAreNotReportedUnused() {
        String text = BASE.replace("IF temp IS cold THEN", "IF tmep IS cold THEN");
        List<Diagnostic> found = check(text);
        assertEquals(List.of("FCL-C001@21"), codes(text), found::toString);
        assertTrue(found.get(0).message().contains("did you mean 'temp'?"), found.get(0).message());
    }

    @Test
    void aMisspeltOutputIsOneErrorNotAlsoANeverConcludedOutput() {
        String text = BASE.replace("THEN valve IS open", "THEN vlave IS open")
                .replace("THEN valve IS closed", "THEN vlave IS closed");
        List<Diagnostic> found = check(text);
        assertEquals(List.of("FCL-C001@21", "FCL-C001@22"), codes(text), found::toString);
        assertTrue(found.get(0).message().contains("did you mean 'valve'?"), found.get(0).message());
    }

    @Test
    void aNameFarFromEveryTermGetsNoGuess() {
        List<Diagnostic> found = check(withRule("RULE 3 : IF temp IS lukewarm THEN valve IS open;"));
        assertEquals(1, found.size(), found::toString);
        assertEquals("temp IS lukewarm: 'lukewarm' is not a term of input 'temp' (its terms: cold, hot)",
                found.get(0).message());
    }

    @Test
    void aMissingSemicolonDoesNotHideTheSemanticErrorsAfterIt() {
        String text = BASE.replace("TERM hot := (3, 0) (27, 1);", "TERM hot := (3, 0) (27, 1)")
                .replace("IF temp IS cold THEN", "IF temp IS clod THEN");
        List<Diagnostic> found = check(text);
        // the syntax error at the end of line 10, then the typo of line 21 that the checks still find
        assertEquals(List.of("FCL-S014@10", "FCL-C002@21"), codes(text), found::toString);
        assertEquals(31, found.get(0).location().column());
        assertTrue(found.get(1).message().contains("did you mean 'cold'?"), found.get(1).message());
    }

    @Test
    void aSyntaxErrorNoOneTokenRepairMendsGivesNoSemanticGuesses() {
        // a TERM with no membership function at all: its repair would be a guess, so no checks run
        String text = BASE.replace("TERM hot := (3, 0) (27, 1);", "TERM hot := ;")
                .replace("IF temp IS cold THEN", "IF temp IS clod THEN");
        List<String> found = codes(text);
        assertEquals(1, found.size(), found::toString);
        assertTrue(found.get(0).startsWith("FCL-S"), found::toString);
    }

    @Test
    void aTermOfAnotherInputNamesThatInput() {
        String text = Programs.text("negative/FCL-C003.fcl");
        Diagnostic d = check(text).get(0);
        assertEquals("temp IS low: 'low' is a term of input 'pressure', not of input 'temp' (its terms: cold, hot)",
                d.message());
    }

    @Test
    void aTermOfAnOutputInAConditionIsUndefinedAndTheMessageSaysWhereItIs() {
        Diagnostic d = check(withRule("RULE 3 : IF temp IS open THEN valve IS closed;")).get(0);
        assertEquals("FCL-C002", d.code());
        assertEquals("temp IS open: 'open' is not a term of input 'temp' (its terms: cold, hot); 'open' is a term"
                + " of output 'valve', and a condition tests only inputs", d.message());
    }

    @Test
    void isOnAVariableWithEmptyTermListIsFclC002() {
        String text = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    level : REAL;\n")
                .replace("END_FUZZIFY\n", "END_FUZZIFY\nFUZZIFY level\nEND_FUZZIFY\n");
        String withUse = text.replace(RULE2, RULE2 + "    RULE 3 : IF level IS high THEN valve IS closed;\n");
        assertEquals(List.of("FCL-C002@26"), codes(withUse));
    }

    @Test
    void isOnAnInputWithoutFuzzifyIsFclC027() {
        String text = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    level : REAL;\n")
                .replace(RULE2, RULE2 + "    RULE 3 : IF level IS high THEN valve IS closed;\n");
        assertEquals(List.of("FCL-C027@24"), codes(text));
    }

    @Test
    void bareVariableSubconditionMayReadAnInputOrALocalButNotAnOutput() {
        String text = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    w : REAL;\n")
                .replace("END_VAR\nFUZZIFY", "END_VAR\nVAR\n    x : REAL;\nEND_VAR\nFUZZIFY")
                .replace(RULE2, RULE2 + "    RULE 3 : IF w AND x THEN valve IS closed;\n"
                        + "    RULE 4 : IF valve THEN valve IS closed;\n");
        assertEquals(List.of("FCL-C027@28"), codes(text));
    }

    @Test
    void bareConclusionMayWriteAnOutputOrALocalButIsOnALocalIsFclC031() {
        String text = BASE.replace("END_VAR\nFUZZIFY", "END_VAR\nVAR\n    x : REAL;\nEND_VAR\nFUZZIFY")
                .replace(RULE2, RULE2 + "    RULE 3 : IF temp IS hot THEN x, valve;\n"
                        + "    RULE 4 : IF temp IS hot THEN x IS open;\n");
        assertEquals(List.of("FCL-C031@27"), codes(text));
    }

    @Test
    void declaringOnlyOrIsEnoughForRulesUsingAnd() {
        String text = BASE.replace("    AND : MIN;\n", "    OR : MAX;\n")
                .replace(RULE2, RULE2 + "    RULE 3 : IF temp IS hot AND temp IS cold THEN valve IS closed;\n");
        assertEquals(List.of(), check(text));
    }

    @Test
    void anAndOrPairOfTable3IsAccepted() {
        assertEquals(List.of(), check(BASE.replace("    AND : MIN;\n", "    AND : PROD;\n    OR : ASUM;\n")));
    }

    @Test
    void aVariableDegreeAtAnOuterEndIsNotJudgedByTheBoundednessCheck() {
        String text = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    d : REAL;\n")
                .replace("TERM closed := 0;", "TERM closed := (0, d) (50, 0);")
                .replace("TERM open := 100;", "TERM open := (50, 0) (100, 0);")
                .replace("METHOD : CoGS;", "METHOD : CoG;");
        assertEquals(List.of(), check(text));
    }

    @Test
    void aRangeMakesUnboundedOutputTermsAcceptable() {
        String text = BASE.replace("TERM closed := 0;", "RANGE (0 .. 100);\n    TERM closed := (0, 1) (50, 0);")
                .replace("TERM open := 100;", "TERM open := (50, 0) (100, 1);")
                .replace("METHOD : CoGS;", "METHOD : CoG;");
        assertEquals(List.of(), check(text));
    }

    @Test
    void initialValuesAreJudgedByValue() {
        String ok = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    a : INT := 2.0;\n    b : USINT := 255;\n"
                + "    c : SINT := -128;\n    d : REAL := 1.5;\n");
        assertEquals(List.of(), check(ok));
        String bad = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    a : INT := 1.5;\n    b : UINT := -1;\n");
        assertEquals(List.of("FCL-C030@4", "FCL-C030@5"), codes(bad));
        assertEquals("initial value 1.5 of input 'a' is not a whole number, but INT holds only integers (5.2.1)",
                check(bad).get(0).message());
    }

    /*
     * Issue 18: the 64-bit bounds compared exactly. As doubles, 9223372036854775808 (2^63) equals
     * Long.MAX_VALUE and 18446744073709551616 (2^64) equals ULINT's largest value 2^64 - 1.
     */
    @Test
    void sixtyFourBitBoundsAreComparedExactly() {
        String ok = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    a : LINT := 9223372036854775807;\n"
                + "    b : LINT := -9223372036854775808;\n    c : ULINT := 18446744073709551615;\n");
        assertEquals(List.of(), check(ok));
        String bad = BASE.replace("    temp : REAL;\n", "    temp : REAL;\n    a : LINT := 9223372036854775808;\n"
                + "    b : ULINT := 18446744073709551616;\n    c : LINT := -9223372036854775809;\n");
        assertEquals(List.of("FCL-C030@4", "FCL-C030@5", "FCL-C030@6"), codes(bad));
        assertEquals("initial value 9223372036854775808 of input 'a' is outside the range of LINT"
                + " (-9223372036854775808 .. 9223372036854775807) (5.2.1)", check(bad).get(0).message());
        assertEquals("initial value 18446744073709551616 of input 'b' is outside the range of ULINT"
                + " (0 .. 18446744073709551615) (5.2.1)", check(bad).get(1).message());
    }

    @Test
    void functionBlockNamesDifferingOnlyInCaseAreFclC032() {
        String two = BASE.replace("FUNCTION_BLOCK t", "FUNCTION_BLOCK Fuzzy_FB")
                + BASE.replace("FUNCTION_BLOCK t", "FUNCTION_BLOCK FUZZY_FB");
        assertEquals(List.of("FCL-C032@25"), codes(two));
        assertEquals("function block 'FUZZY_FB' has the same name as the function block 'Fuzzy_FB' at line 1"
                + " (names are not case-sensitive); each function block needs a unique name", check(two).get(0).message());
        String distinct = BASE.replace("FUNCTION_BLOCK t", "FUNCTION_BLOCK Fuzzy_FB")
                + BASE.replace("FUNCTION_BLOCK t", "FUNCTION_BLOCK Fuzzy_FB2");
        assertEquals(List.of(), check(distinct));
    }

    @Test
    void blocksConcludingAnOutputWithTheSameAccumulationAreFine() {
        String text = BASE.replace("END_RULEBLOCK\n", "END_RULEBLOCK\nRULEBLOCK r2\n    AND : MIN;\n    ACCU : MAX;\n"
                + "    RULE 1 : IF temp IS hot THEN valve IS closed;\nEND_RULEBLOCK\n");
        // no accumulation finding; r2's one rule leaves temp <= 3 uncovered ('hot' is 0 up to 3): FCL-W005
        assertEquals(List.of("FCL-W005@24"), codes(text));
    }

    @Test
    void everyMessageStartsWithTheElementAndEndsWithoutAStackTrace() {
        for (Diagnostic d : check(Programs.text("standard/crane_annex_c.fcl"))) {
            assertTrue(!d.message().contains("Exception"), d::toString);
        }
    }
}
