package org.fclcert.harness;

import static org.fclcert.harness.TestCases.negative;
import static org.fclcert.harness.TestCases.positive;
import static org.fclcert.harness.TestCases.step;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import org.fclcert.iut.IutException;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.model.ConformanceLevel;
import org.junit.jupiter.api.Test;

class RunnerTest {
    private static final ExportCheck NO_EXPORT_CHECK = (text, c) -> new ExportCheck.Verdict(ExportStatus.PASSED, "");

    /** The two steps of a tiny case: y = x + 1, which the scripted implementations below compute or not. */
    private static final RunCase PLUS_ONE = positive("B-COGS-001", List.of(
            step(Map.of("x", 1.0), Map.of("y", 2.0)),
            step(Map.of("x", 5.0), Map.of("y", 6.0))));

    private static CaseResult runOne(ScriptedIut iut, RunCase c) throws IOException {
        return run(iut, List.of(c)).get(0);
    }

    private static List<CaseResult> run(ScriptedIut iut, List<RunCase> cases) throws IOException {
        List<CaseResult> sunk = new ArrayList<>();
        ResultSink sink = new ResultSink() {
            @Override
            public void header(RunHeader header) {
            }

            @Override
            public void accept(CaseResult result) {
                sunk.add(result);
            }
        };
        List<CaseResult> returned = new Runner(NO_EXPORT_CHECK, RunListener.NONE).run(iut, null, cases, sink);
        assertEquals(returned, sunk, "every result is streamed to the sink");
        return returned;
    }

    private static ScriptedIut plusOne() {
        return ScriptedIut.loading((call, in) -> Map.of("y", in.get("x") + 1));
    }

    @Test
    void correctOutputsPassAndTheStepsAreRerunInReverseAfterReset() throws IOException {
        ScriptedIut iut = plusOne();
        CaseResult r = runOne(iut, PLUS_ONE);
        assertEquals(CaseStatus.PASSED, r.status(), r.message());
        assertEquals(0.0, r.evidence().maxError());
        assertEquals(List.of("load", "eval {x=1.0}", "eval {x=5.0}", "reset", "eval {x=5.0}", "eval {x=1.0}", "export"),
                iut.calls);
        assertEquals(ExportStatus.UNSUPPORTED, r.export().status());
        assertNull(r.setup().program(), "passed cases do not carry their program");
    }

    /*
     * Step 2 flagged knife-edge:2: the implementation's 6.5 where 6 is expected is reported as not judged, the
     * case passes on step 1, and the error of the unjudged step is not measured. Step 1 flagged instead: the
     * wrong step 2 still fails the case.
     */
    @Test
    void aKnifeEdgeVectorIsNotJudged() throws IOException {
        ScriptedIut iut = ScriptedIut.loading((call, in) -> Map.of("y", in.get("x") == 5.0 ? 6.5 : 2.0));
        RunCase flagged = positive("E-LM-001", ConformanceLevel.EXTENSION, List.of("E-LM"), List.of("knife-edge:2"),
                PLUS_ONE.vectors());
        CaseResult r = runOne(iut, flagged);
        assertEquals(CaseStatus.PASSED, r.status(), r.message());
        assertEquals("1 step(s) within tolerance, 1 not judged (knife edge)", r.message());
        assertEquals(0.0, r.evidence().maxError());
        assertEquals(java.util.Set.of(2), r.notJudgedSteps());
        List<String> notes = r.verdict().notes();
        assertTrue(notes.get(0).startsWith("step 2 not judged (knife edge, flag knife-edge:2): differs: y = 6.5"),
                notes.toString());
        RunCase other = positive("E-LM-001", ConformanceLevel.EXTENSION, List.of("E-LM"), List.of("knife-edge:1"),
                PLUS_ONE.vectors());
        CaseResult failed = runOne(ScriptedIut.loading((call, in) -> Map.of("y", in.get("x") == 5.0 ? 6.5 : 2.0)),
                other);
        assertEquals(CaseStatus.FAILED, failed.status());
        assertEquals(2, failed.evidence().step().number());
    }

    @Test
    void statefulCasesAreNotRerun() throws IOException {
        ScriptedIut iut = plusOne();
        RunCase stateful = positive("B-DEFAULT-NC-001", ConformanceLevel.BASIC, List.of("B-DEFAULT-NC"),
                List.of("stateful"), PLUS_ONE.vectors());
        assertEquals(CaseStatus.PASSED, runOne(iut, stateful).status());
        assertEquals(List.of("load", "eval {x=1.0}", "eval {x=5.0}", "export"), iut.calls);
    }

    @Test
    void aWrongOutputFailsWithTheStepTheValuesAndTheMeasuredError() throws IOException {
        // second step: 5 + 1.5 = 6.5 where 6 is expected, error 0.5
        ScriptedIut iut = ScriptedIut.loading((call, in) -> Map.of("y", in.get("x") == 5.0 ? 6.5 : 2.0));
        CaseResult r = runOne(iut, PLUS_ONE);
        assertEquals(CaseStatus.FAILED, r.status());
        assertEquals(2, r.evidence().step().number());
        assertEquals(Map.of("x", 5.0), r.evidence().step().inputs());
        assertEquals(Map.of("y", 6.0), r.mismatch().orElseThrow().expected());
        assertEquals(Map.of("y", 6.5), r.mismatch().orElseThrow().actual());
        assertEquals(0.5, r.evidence().maxError());
        assertTrue(r.message().startsWith("step 2 of 2: y = 6.5 where 6.0 is expected"), r.message());
        assertNotNull(r.setup().program(), "a failed case keeps its program for the report");
    }

    @Test
    void theErrorWithinToleranceIsStillMeasured() throws IOException {
        ScriptedIut iut = ScriptedIut.loading((call, in) -> Map.of("y", in.get("x") + 1.004));
        CaseResult r = runOne(iut, TestCases.withTolerance(PLUS_ONE, Tolerances.absolute("continuous", 0.01)));
        assertEquals(CaseStatus.PASSED, r.status(), r.message());
        assertEquals(0.004, r.evidence().maxError(), 1e-12);
        assertEquals("continuous (±0.01)", r.setup().tolerance());
    }

    @Test
    void outputNamesAreCaseInsensitiveAndAMissingOutputFails() throws IOException {
        assertEquals(CaseStatus.PASSED,
                runOne(ScriptedIut.loading((call, in) -> Map.of("Y", in.get("x") + 1)), PLUS_ONE).status());
        CaseResult missing = runOne(ScriptedIut.loading((call, in) -> Map.of("z", 0.0)), PLUS_ONE);
        assertEquals(CaseStatus.FAILED, missing.status());
        assertEquals("step 1 of 2: no value for output y", missing.message());
    }

    @Test
    void aNaNOutputIsNeverWithinTolerance() throws IOException {
        CaseResult r = runOne(ScriptedIut.loading((call, in) -> Map.of("y", Double.NaN)), PLUS_ONE);
        assertEquals(CaseStatus.FAILED, r.status());
        assertEquals(Double.POSITIVE_INFINITY, r.evidence().maxError());
    }

    @Test
    void aStateLeakFailsTheCase() throws IOException {
        // adds 0.25 when the previous input was 5, and reset() does not forget it: in order (1, then 5) every
        // answer is right; after reset, in reverse order, step 2 (x=5) comes right after the forward x=5
        double[] last = {0};
        ScriptedIut iut = ScriptedIut.loading((call, in) -> {
            double y = in.get("x") + 1 + (last[0] == 5.0 ? 0.25 : 0);
            last[0] = in.get("x");
            return Map.of("y", y);
        });
        CaseResult r = runOne(iut, PLUS_ONE);
        assertEquals(CaseStatus.FAILED, r.status());
        assertEquals("state leaks between evaluations: after reset() and with the steps in reverse order, step 2 "
                + "gives y = 6.25 instead of 6.0", r.message());
        assertEquals(2, r.evidence().step().number());
    }

    @Test
    void anEvaluationErrorFailsButACrashOrTimeoutErrorsWithTheStderrTail() throws IOException {
        CaseResult failed = runOne(ScriptedIut.loading((call, in) -> {
            throw new IutException(IutException.Kind.EVAL_ERROR, "division by zero", "");
        }), PLUS_ONE);
        assertEquals(CaseStatus.FAILED, failed.status());
        assertEquals("step 1 of 2: the implementation reported an evaluation error: division by zero",
                failed.message());

        CaseResult crashed = runOne(ScriptedIut.loading((call, in) -> {
            if (call == 2) {
                throw new IutException(IutException.Kind.CRASH, "exit code 139", "Segmentation fault\n");
            }
            return Map.of("y", in.get("x") + 1);
        }), PLUS_ONE);
        assertEquals(CaseStatus.ERRORED, crashed.status());
        assertEquals("step 2 of 2: the implementation crashed: exit code 139", crashed.message());
        assertTrue(crashed.evidence().error().endsWith("Segmentation fault"), crashed.evidence().error());
        assertEquals(2, crashed.evidence().step().number());
        assertEquals(ExportStatus.NOT_RUN, crashed.export().status());

        CaseResult timedOut = runOne(ScriptedIut.loading((call, in) -> {
            throw new IutException(IutException.Kind.TIMEOUT, "no reply within 5 s", "");
        }), PLUS_ONE);
        assertEquals(CaseStatus.ERRORED, timedOut.status());
    }

    @Test
    void anImplementationThatThrowsDespiteTheContractIsErroredAndTheRunGoesOn() throws IOException {
        ScriptedIut iut = ScriptedIut.loading((call, in) -> {
            throw new IllegalStateException("bug in the vendor's code");
        });
        List<CaseResult> results = run(iut, List.of(PLUS_ONE, negative("B-NEG-001", "FCL-C002", 3)));
        assertEquals(CaseStatus.ERRORED, results.get(0).status());
        assertEquals("the implementation failed unexpectedly: java.lang.IllegalStateException: bug in the vendor's "
                + "code", results.get(0).message());
        assertEquals(CaseStatus.FAILED, results.get(1).status(), "the next case still ran");
    }

    @Test
    void aRejectedValidProgramFails() throws IOException {
        ScriptedIut iut = new ScriptedIut(fcl -> new LoadOutcome.Rejected("unexpected NOT", OptionalInt.of(9)),
                (call, in) -> Map.of());
        CaseResult r = runOne(iut, PLUS_ONE);
        assertEquals(CaseStatus.FAILED, r.status());
        assertEquals("rejected a program the standard accepts at line 9: unexpected NOT", r.message());
        assertEquals(List.of("load"), iut.calls);
    }

    @Test
    void aNegativeCasePassesOnlyOnACleanRejectionAndNotesALineMismatch() throws IOException {
        RunCase bad = negative("B-NEG-001", "FCL-C002", 14);
        CaseResult sameLine = runOne(new ScriptedIut(fcl -> new LoadOutcome.Rejected("no term", OptionalInt.of(14)),
                (call, in) -> Map.of()), bad);
        assertEquals(CaseStatus.PASSED, sameLine.status());
        assertEquals(List.of(), sameLine.verdict().notes());
        assertEquals(RejectionPlace.AT_ERROR_LINE, sameLine.verdict().rejection());

        CaseResult otherLine = runOne(new ScriptedIut(fcl -> new LoadOutcome.Rejected("no term", OptionalInt.of(12)),
                (call, in) -> Map.of()), bad);
        assertEquals(CaseStatus.PASSED, otherLine.status());
        assertEquals(List.of("the implementation reports line 12; the error (FCL-C002) is at line 14"),
                otherLine.verdict().notes());
        assertEquals(RejectionPlace.OTHER_LINE, otherLine.verdict().rejection());

        CaseResult unlocated = runOne(new ScriptedIut(fcl -> new LoadOutcome.Rejected("no", OptionalInt.empty()),
                (call, in) -> Map.of()), bad);
        assertEquals(CaseStatus.PASSED, unlocated.status());
        assertEquals(RejectionPlace.UNLOCATED, unlocated.verdict().rejection());

        CaseResult accepted = runOne(ScriptedIut.loading((call, in) -> Map.of()), bad);
        assertEquals(CaseStatus.FAILED, accepted.status());
        assertEquals("accepted a program the standard rejects: FCL-C002 at line 14", accepted.message());
        assertEquals("accepted", accepted.mismatch().orElseThrow().actual());
        assertEquals(null, accepted.verdict().rejection());

        CaseResult crashed = runOne(new ScriptedIut(fcl -> {
            throw new IutException(IutException.Kind.CRASH, "killed by signal 6", "abort");
        }, (call, in) -> Map.of()), bad);
        assertEquals(CaseStatus.ERRORED, crashed.status(), "a crash is never a rejection");
    }

    @Test
    void exportIsReportedApartFromTheCaseStatus() throws IOException {
        ScriptedIut iut = plusOne().exporting("FUNCTION_BLOCK fb END_FUNCTION_BLOCK");
        List<String> seen = new ArrayList<>();
        ExportCheck failing = (text, c) -> {
            seen.add(text);
            return new ExportCheck.Verdict(ExportStatus.FAILED, "does not read back");
        };
        CaseResult r = new Runner(failing, RunListener.NONE).run(iut, null, List.of(PLUS_ONE), new ResultSink() {
            @Override
            public void header(RunHeader header) {
            }

            @Override
            public void accept(CaseResult result) {
            }
        }).get(0);
        assertEquals(CaseStatus.PASSED, r.status());
        assertEquals(ExportStatus.FAILED, r.export().status());
        assertEquals("does not read back", r.export().message());
        assertEquals(List.of("FUNCTION_BLOCK fb END_FUNCTION_BLOCK"), seen);
    }

    @Test
    void afterTheImplementationIsGivenUpTheRemainingCasesAreSkipped() throws IOException {
        ScriptedIut iut = new ScriptedIut(fcl -> {
            throw new IutException(IutException.Kind.GAVE_UP, "3 restarts used", "");
        }, (call, in) -> Map.of());
        List<CaseResult> results = run(iut, List.of(PLUS_ONE, negative("B-NEG-001", "FCL-C002", 3),
                positive("B-COGS-002", PLUS_ONE.vectors())));
        assertEquals(List.of(CaseStatus.ERRORED, CaseStatus.SKIPPED, CaseStatus.SKIPPED),
                results.stream().map(CaseResult::status).toList());
        assertEquals("not run: the implementation was given up at case B-COGS-001 (it could not be started, or each of its"
                + " last requests crashed or hung)",
                results.get(2).message());
        assertEquals(List.of("load"), iut.calls);
    }
}
