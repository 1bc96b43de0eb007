package org.fclcert.report;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ReferenceTrace;
import org.junit.jupiter.api.Test;

/**
 * Causes from messages written as the real libraries and issue 29's vendors write them (copied from their output on
 * corpus cases) and from hand-made wrong values: one group per thing said, quoted verbatim, the largest group first,
 * interpretation cases left out.
 */
class CausesTest {
    private static final String PROGRAM = String.join("\n",
            "FUNCTION_BLOCK f",
            "VAR_INPUT x : REAL := 1.0; END_VAR",
            "VAR_OUTPUT y : REAL; END_VAR",
            "FUZZIFY x TERM on := (0, 0) (1, 1); END_FUZZIFY",
            "DEFUZZIFY y",
            "    RANGE (0 .. 100);",
            "    a, b : REAL;",
            "END_DEFUZZIFY");

    static CaseResult failed(String id, String message, Object expected, Object actual, String... flags) {
        return MadeResults.made(id, "basic", List.of(id.replaceFirst("-\\d+$", "")), List.of(flags), CaseStatus.FAILED,
                message, expected, actual, null, PROGRAM);
    }

    static CaseResult errored(String id, String message) {
        return MadeResults.made(id, "extension", List.of("E-COND-VARIABLE"), List.of(), CaseStatus.ERRORED, message,
                null, null, null, PROGRAM);
    }

    private static String cause(CaseResult c) {
        String[] label = Causes.classify(c);
        return label[0] + ": " + label[1];
    }

    /**
     * Issue 29's vendors: the group is what the implementation said, quoted as the first case said it, however
     * fclcert would have guessed the construct ("`RANGE (a .. b)` without `:=`" was wrong for both).
     */
    @Test
    void aRejectionIsFiledUnderWhatTheImplementationSaid() {
        assertEquals("rejected at load: 'RANGE' is not supported at the Basic Level", cause(failed("E-RANGE-001",
                "rejected a program the standard accepts at line 6: 'RANGE' is not supported at the Basic Level",
                "load and evaluate", "rejected")));
        assertEquals("rejected at load: unexpected 'RANGE' in DEFUZZIFY", cause(failed("E-COG-001",
                "rejected a program the standard accepts at line 6: unexpected 'RANGE' in DEFUZZIFY", "load and evaluate",
                "rejected")));
        // the line holds a comment, but the implementation named NOT: NOT it is
        assertEquals("rejected at load: 'NOT' is not supported", cause(failed("E-NOT-002",
                "rejected a program the standard accepts at line 2: 'NOT' is not supported", "load and evaluate",
                "rejected")));
        // the numbers stay as it wrote them
        assertEquals("rejected at load: jFuzzyLogic: line 4:3 mismatched input 'FOO' expecting 12 tokens",
                cause(failed("B-FB-009", "rejected a program the standard accepts at line 4: jFuzzyLogic: line 4:3"
                        + " mismatched input 'FOO' expecting 12 tokens", "load and evaluate", "rejected")));
    }

    @Test
    void aRejectionWithoutAWordGetsTheConstructOfItsLineAsAHint() {
        assertEquals("rejected at load: no message; hint: the line it points at has `RANGE (a .. b)`", cause(failed(
                "E-RANGE-002", "rejected a program the standard accepts at line 6: ", "load and evaluate", "rejected")));
        assertEquals("rejected at load: no message; hint: the line it points at has several variables in one"
                + " declaration", cause(failed("B-FB-002", "rejected a program the standard accepts at line 7: ",
                "load and evaluate", "rejected")));
        assertEquals("rejected at load: no message", cause(failed("B-FB-003",
                "rejected a program the standard accepts: ", "load and evaluate", "rejected")));
    }

    /**
     * One group per complaint: the cases' own term names, numbers, positions, the statement a library quotes and the
     * letter case of a keyword do not split it; the group quotes its first case verbatim.
     */
    @Test
    void messagesAboutDifferentCasesClusterIntoOneGroup() {
        String fourPoints = "FUNCTION_BLOCK f\nFUZZIFY x\n  TERM %s := (0, 0) (1, 1) (2, 1) (3, 0);\nEND_FUZZIFY";
        CaseResult cool = MadeResults.made("E-IN-TERM-4-003", "extension", List.of("E-IN-TERM-4"), List.of(),
                CaseStatus.FAILED, "rejected a program the standard accepts at line 3: term cool needs 2 or 3 points in"
                        + " ascending order", "load", "rejected", null, fourPoints.formatted("cool"));
        CaseResult mid = MadeResults.made("E-IN-TERM-4-001", "extension", List.of("E-IN-TERM-4"), List.of(),
                CaseStatus.FAILED, "rejected a program the standard accepts at line 3: term mid needs 2 or 3 points in"
                        + " ascending order", "load", "rejected", null, fourPoints.formatted("mid"));
        CaseResult or = failed("E-OR-MAX-001", "rejected a program the standard accepts at line 9: 'OR' is not"
                + " supported at the Basic Level", "load", "rejected");
        CaseResult mixed = failed("E-OR-MAX-002", "rejected a program the standard accepts at line 12: 'Or' is not"
                + " supported at the Basic Level", "load", "rejected");
        CaseResult prod = failed("E-AND-PROD-001", "rejected a program the standard accepts at line 9: 'PROD' is not"
                + " supported at the Basic Level", "load", "rejected");
        CaseResult fl1 = failed("B-FB-001", "rejected a program the standard accepts at line 3: fuzzylite: [syntax"
                + " error] expected <END_VAR> before <VAR_OUTPUT> in line: VAR_OUTPUT y : REAL END_VAR", "load", "r");
        CaseResult fl2 = failed("B-FB-004", "rejected a program the standard accepts at line 5: fuzzylite: [syntax"
                + " error] expected <END_VAR> before <VAR_OUTPUT> in line: VAR_OUTPUT z : REAL END_VAR", "load", "r");
        List<String> causes = Causes.of(List.of(cool, or, mid, mixed, prod, fl1, fl2)).stream()
                .map(Causes.Cause::sentence).toList();
        assertEquals(List.of("2 cases: rejected at load: 'OR' is not supported at the Basic Level",
                "2 cases: rejected at load: fuzzylite: [syntax error] expected <END_VAR> before <VAR_OUTPUT> in line:"
                        + " VAR_OUTPUT y : REAL END_VAR",
                "2 cases: rejected at load: term cool needs 2 or 3 points in ascending order",
                "1 case: rejected at load: 'PROD' is not supported at the Basic Level"), causes);
    }

    @Test
    void wrongValuesAreGroupedByFeatureAndKindOfDeviation() {
        assertEquals("wrong value: E-ACCU-NSUM (ACCU with the NSUM algorithm): wrong value", cause(failed("E-ACCU-NSUM-001",
                "step 1 of 3: y = 33.3 where 25.0 is expected", Map.of("y", 25.0), Map.of("y", 100.0 / 3))));
        // 0.5 % off: the size of a sampled defuzzification's error
        assertEquals("wrong value: E-COG (METHOD CoG, centre of gravity): small deviation (relative error at most 1 %,"
                + " as from sampling)", cause(failed("E-COG-001", "step 1 of 1: y = 40.2 where 40 is expected",
                Map.of("y", 40.0), Map.of("y", 40.2))));
        // the same size of error, where the reference fired a rule at 8.3e-8 (O-SHAPE-BELL-001 against fuzzylite 6.0,
        // whose tolerance drops it): that is the cause to show, not sampling; at 2e-6 the rule is no faint one
        CaseResult bell = failed("O-SHAPE-BELL-001", "step 4 of 11: y = 1.0 where 0.999999917346057 is expected",
                Map.of("y", 0.999999917346057), Map.of("y", 1.0));
        for (double degree : new double[] {8.265394302320317E-8, 2e-6}) {
            ReferenceTrace trace = new ReferenceTrace(4, List.of(new ReferenceTrace.RuleDegree("r", "1", 1, List.of()),
                    new ReferenceTrace.RuleDegree("r", "2", degree, List.of("y IS low"))), List.of());
            CaseResult.Evidence e = bell.evidence();
            CaseResult traced = new CaseResult(bell.plan(), bell.verdict(), new CaseResult.Evidence(e.step(),
                    e.mismatch(), e.error(), e.maxError(), trace), bell.export(), bell.setup(), null, null);
            assertEquals("wrong value: O-SHAPE-BELL (named shape: generalised bell (gbell, Bell)): small deviation "
                    + (degree < 1e-6 ? "where a rule fired at a degree of at most 1e-6 (as from a library that does not"
                    + " fire a rule below a tolerance, as fuzzylite's 1e-6)" : "(relative error at most 1 %, as from"
                    + " sampling)"), cause(traced));
        }
        assertEquals("wrong value: E-COG (METHOD CoG, centre of gravity): NaN where a value is expected", cause(failed(
                "E-COG-002", "step 1 of 1: y = NaN where 40 is expected", Map.of("y", 40.0), Map.of("y", Double.NaN))));
    }

    @Test
    void crashesByExceptionAndPlaceAcceptedProgramsAndTimeouts() {
        assertEquals("errored: crashed: NullPointerException in net.sourceforge.jFuzzyLogic.rule.RuleBlock.x:263",
                cause(errored("E-COND-VARIABLE-001", "load: the implementation crashed: the implementation failed"
                        + " internally on 'load': java.lang.NullPointerException: Cannot invoke \"a.b()\" because x is null"
                        + " (at net.sourceforge.jFuzzyLogic.rule.RuleBlock.x:263)")));
        assertEquals("errored: timed out", cause(errored("E-COND-VARIABLE-002",
                "load: the implementation timed out: load did not return within 100 ms")));
        assertEquals("refused to evaluate: jFuzzyLogic: MembershipFunction and Defuzzifier are neither both discrete nor"
                + " both continuous", cause(failed("E-LM-002", "step 1 of 4: the implementation reported an evaluation"
                + " error: the IUT reported an error on 'eval': jFuzzyLogic: MembershipFunction and Defuzzifier are"
                + " neither both discrete nor both continuous\tTerm: ylm IS s1", null, null)));
        assertEquals("accepted an invalid program: no error reported where the standard requires one", cause(failed(
                "N-C016-001", "accepted a program the standard rejects: FCL-C016 at line 26", "reject FCL-C016 at line 26",
                "accepted")));
    }

    @Test
    void causesCountTheirCasesLargestFirstWithoutInterpretationCases() {
        String cogs = "rejected a program the standard accepts: fuzzylite: [factory error] constructor of Defuzzifier"
                + " <CoGS> not registered";
        String line = "rejected a program the standard accepts at line 3: fuzzylite: [syntax error] expected <END_VAR>"
                + " before <VAR_OUTPUT> in line: VAR_OUTPUT y : REAL END_VAR";
        List<Causes.Cause> causes = Causes.of(List.of(failed("B-COGS-001", cogs, "load and evaluate", "r"),
                failed("B-FB-001", line, "load and evaluate", "r"), failed("B-FB-002", line, "load and evaluate", "r"),
                failed("B-COGS-003", cogs, "load and evaluate", "r", "interpretation:1")));
        assertEquals(List.of("2 cases: rejected at load: fuzzylite: [syntax error] expected <END_VAR> before <VAR_OUTPUT>"
                + " in line: VAR_OUTPUT y : REAL END_VAR", "1 case: rejected at load: fuzzylite: [factory error]"
                + " constructor of Defuzzifier <CoGS> not registered"), causes.stream().map(Causes.Cause::sentence).toList());
        assertEquals(List.of("B-FB-001", "B-FB-002"), causes.get(0).cases());
    }
}
