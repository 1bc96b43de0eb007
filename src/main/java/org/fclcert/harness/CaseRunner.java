package org.fclcert.harness;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;
import org.fclcert.corpus.ExpectedError;
import org.fclcert.corpus.OutputComparison;
import org.fclcert.corpus.Vector;
import org.fclcert.eval.EvaluationCode;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutHealth;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.syntax.dialect.Dialect;

/**
 * Runs one case against an implementation: load, then either judge the rejection (negative case) or run the
 * steps in order on one instance, rerun them in reverse order after {@code reset()} (stateless cases), and
 * check the export.
 */
final class CaseRunner {
    /** The result, and whether the implementation has given up for good (restart budget exhausted). */
    record Ran(CaseResult result, boolean gaveUp) {
    }

    /** The beginning of the message of a dialect case the implementation is not sent (it does not read the dialect). */
    static final String NOT_PRESENTABLE = "not presentable: ";

    private final ExportCheck exportCheck;
    private final Presenter presenter;
    /** Which dialects the implementation is sent cases in as they are ({@link Iuts#reads}); the standard always. */
    private Predicate<Dialect> reads = d -> d == Dialect.STRICT;

    CaseRunner(ExportCheck exportCheck) {
        this(exportCheck, null);
    }

    /** With {@code presenter} (null: none), every positive case also runs on the semantic axis. */
    CaseRunner(ExportCheck exportCheck, Presenter presenter) {
        this.exportCheck = exportCheck;
        this.presenter = presenter;
    }

    Ran run(ImplementationUnderTest iut, RunCase c) {
        return run(iut, c, iut, c);
    }

    /** The implementation behind {@code spec} is sent the dialect cases it reads ({@link Iuts#reads}). */
    CaseRunner readingAs(String spec) {
        reads = d -> Iuts.reads(spec, d);
        return this;
    }

    /**
     * As {@link #run(ImplementationUnderTest, RunCase)}, with {@code c} the case as sent ({@link Disguise}) over
     * {@code iut}, and {@code plain} the same case as the corpus writes it, over {@code plainIut}: the reference's
     * trace and the semantic axis work on the plain case. The implementation's breakdowns during the case are
     * counted by the difference of its health around it.
     */
    Ran run(ImplementationUnderTest iut, RunCase c, ImplementationUnderTest plainIut, RunCase plain) {
        return run(iut, c, plainIut, plain, Optional.<Disguise.Twin>empty());
    }

    /**
     * As {@link #run(ImplementationUnderTest, RunCase, ImplementationUnderTest, RunCase)}; a negative case with an
     * accepted {@code twin} ({@link RepairedTwin}) passes only when the implementation rejects the case and then
     * loads the twin.
     */
    Ran run(ImplementationUnderTest iut, RunCase c, ImplementationUnderTest plainIut, RunCase plain,
            Optional<Disguise.Twin> twin) {
        return run(iut, c, plainIut, plain, twin, null);
    }

    /**
     * As above, with {@code disguise} (null: none) the disguise {@code c} was sent under: the semantic axis then
     * presents the disguised program over {@code iut}, so that its exchanges are part of the case's evidence.
     */
    Ran run(ImplementationUnderTest iut, RunCase c, ImplementationUnderTest plainIut, RunCase plain,
            Optional<Disguise.Twin> twin, Disguise disguise) {
        IutHealth before = iut.health();
        Ran ran = runCounted(iut, c, plainIut, plain, twin, disguise);
        IutHealth during = iut.health().since(before);
        return new Ran(ran.result().withBreakdowns(during.crashes(), during.restarts()), ran.gaveUp());
    }

    private Ran runCounted(ImplementationUnderTest iut, RunCase c, ImplementationUnderTest plainIut, RunCase plain,
            Optional<Disguise.Twin> twin, Disguise disguise) {
        long start = System.nanoTime();
        if (c.inDialect() && !reads.test(c.dialect())) {
            // the language axis sends a case as the corpus writes it; this text is not one the implementation reads
            CaseResult skipped = CaseResult.skipped(c.plan(), NOT_PRESENTABLE + "the case is written in "
                    + c.dialect().displayName() + "'s dialect (" + c.dialect().summary() + "), which this implementation"
                    + " is not sent; it counts for and against no row");
            return presented(iut, c, plainIut, plain, disguise, skipped, false);
        }
        ResultBuilder r = new ResultBuilder(c);
        boolean gaveUp = false;
        try {
            // the twin goes before or after the case as the disguise drew it, so that the order gives nothing away
            LoadOutcome twinOutcome = twin.isPresent() && twin.get().first() ? iut.load(twin.get().text()) : null;
            LoadOutcome outcome = load(iut, c);
            if (c.expectReject()) {
                if (twin.isPresent() && !twin.get().first()) {
                    twinOutcome = iut.load(twin.get().text());
                }
                judgeRejection(c, outcome, r);
                if (twinOutcome != null && r.status() == CaseStatus.PASSED) {
                    judgeTwin(twinOutcome, r);
                }
            } else {
                runPositive(iut, c, outcome, r);
            }
        } catch (IutException e) {
            // a load that ends in anything but a clean Loaded/Rejected is a breakdown, never a verdict
            r.errored("load: the implementation " + IutFaults.describe(e), IutFaults.errorText(e));
            gaveUp = e.kind() == IutException.Kind.GAVE_UP;
        } catch (StepBreakdown b) {
            gaveUp = b.gaveUp;
        } catch (RuntimeException e) {
            // the contract allows only IutException; an in-process implementation may still break it
            r.errored("the implementation failed unexpectedly: " + e, String.valueOf(e));
        } catch (StackOverflowError e) {
            // an in-process implementation recursing without end: its fault, and the run goes on
            r.errored("the implementation overflowed the stack", "java.lang.StackOverflowError");
        }
        if (!c.expectReject()) {
            r.traceReference(plain);
        }
        return presented(iut, c, plainIut, plain, disguise, r.build((System.nanoTime() - start) / 1_000_000), gaveUp);
    }

    /** The result with the case presented on the semantic axis, when there is one. */
    private Ran presented(ImplementationUnderTest iut, RunCase c, ImplementationUnderTest plainIut, RunCase plain,
            Disguise disguise, CaseResult result, boolean gaveUp) {
        if (presenter != null && !c.expectReject()) {
            if (gaveUp) {
                result = notPresented(c, result, "the implementation was given up");
            } else {
                Presenter.Presentation p = disguise == null ? presenter.present(plainIut, plain)
                        : presenter.present(iut, c, plain, disguise);
                result = result.withPresented(p.presented());
                gaveUp = p.gaveUp();
            }
        }
        return new Ran(result, gaveUp);
    }

    /**
     * Sends the case's program: standard FCL as it is ({@link ImplementationUnderTest#load}); a case written in a
     * dialect as a text in that library's layout ({@link ImplementationUnderTest#loadWritten}: the library gets it as
     * it is, the reference reads it with fclcert's reader of the dialect). Only an implementation that reads the
     * dialect is sent it ({@link org.fclcert.iut.Iuts#reads}; the others: {@link Runner}).
     */
    static LoadOutcome load(ImplementationUnderTest iut, RunCase c) throws IutException {
        return c.inDialect() ? iut.loadWritten(c.program(), c.dialect()) : iut.load(c.program());
    }

    /** {@code result} of a case that was not run: a positive one is not presented either, for reason {@code why}. */
    CaseResult notPresented(RunCase c, CaseResult result, String why) {
        if (presenter == null || c.expectReject()) {
            return result;
        }
        return result.withPresented(new CaseResult.Presented(presenter.dialect().cliName(), PresentedStatus.SKIPPED,
                "not presented: " + why, List.of(), null, null));
    }

    private static void judgeRejection(RunCase c, LoadOutcome outcome, ResultBuilder r) {
        ExpectedError want = c.expectedError().orElseThrow();
        String expected = "reject: " + want.code() + " at line " + want.line();
        if (outcome instanceof LoadOutcome.Rejected rejected) {
            String where = rejected.line().isPresent() ? " at line " + rejected.line().getAsInt() : "";
            r.passed("rejected" + where + ": " + rejected.message())
                    .sentences(expected, "rejected" + where + ": " + rejected.message());
            if (rejected.line().isEmpty()) {
                r.rejection(RejectionPlace.UNLOCATED)
                        .note("the implementation gave no line for its rejection; the error is at line " + want.line());
            } else if (rejected.line().getAsInt() != want.line()) {
                r.rejection(RejectionPlace.OTHER_LINE)
                        .note("the implementation reports line " + rejected.line().getAsInt() + "; the error ("
                        + want.code() + ") is at line " + want.line());
            } else {
                r.rejection(RejectionPlace.AT_ERROR_LINE);
            }
        } else {
            r.failed("accepted a program the standard rejects: " + want.code() + " at line " + want.line())
                    .sentences(expected, "accepted");
        }
    }

    /** The twin must load: a rejection of it too shows the implementation refuses the program, not this error. */
    private static void judgeTwin(LoadOutcome outcome, ResultBuilder r) {
        if (outcome instanceof LoadOutcome.Rejected rejected) {
            String where = rejected.line().isPresent() ? " at line " + rejected.line().getAsInt() : "";
            r.failed("rejected the case's accepted twin (the same program with the defect repaired, which the standard"
                    + " accepts)" + where + ": " + rejected.message() + "; so the rejection of the case does not show"
                    + " that this error was found");
        } else {
            r.note("loaded the case's accepted twin (the same program with the defect repaired)");
        }
    }

    private void runPositive(ImplementationUnderTest iut, RunCase c, LoadOutcome outcome, ResultBuilder r)
            throws StepBreakdown {
        if (outcome instanceof LoadOutcome.Rejected rejected) {
            String where = rejected.line().isPresent() ? " at line " + rejected.line().getAsInt() : "";
            r.failed("rejected a program the standard accepts" + where + ": " + rejected.message())
                    .sentences("load and evaluate", "rejected" + where + ": " + rejected.message());
            return;
        }
        List<Map<String, Double>> forward = runForward(iut, c, r);
        if (r.status() == CaseStatus.PASSED && !c.stateful()) {
            checkNoStateLeak(iut, c, forward, r);
        }
        checkExport(iut, c, r);
    }

    static List<Map<String, Double>> runForward(ImplementationUnderTest iut, RunCase c, ResultBuilder r)
            throws StepBreakdown {
        List<Map<String, Double>> actuals = new ArrayList<>();
        int wrong = 0;
        int refused = 0;
        for (int i = 0; i < c.vectors().size(); i++) {
            Vector v = c.vectors().get(i);
            // a knife-edge vector (FairVectors) is not judged: its value rests on a tie rounding may break;
            // its error is neither counted nor part of maxError
            boolean knifeEdge = Flags.knifeEdges(c.flags()).contains(i + 1);
            Optional<String> problem;
            String answer = null;   // a refused step's answer in words, for the report
            if (v.refused()) {
                Attempt a = attempt(iut, c, v, i + 1, r);
                actuals.add(a.outputs());
                problem = refusalProblem(v, a);
                answer = a.refusal() == null ? "gave outputs " + a.outputs() : "refused: " + a.refusal();
                refused += knifeEdge ? 0 : 1;
            } else {
                Map<String, Double> got = evaluate(iut, c, v, i + 1, r);
                actuals.add(got);
                problem = StepComparison.compare(c, v.out(), got, knifeEdge ? new ResultBuilder(c) : r);
            }
            if (knifeEdge) {
                r.note("step " + (i + 1) + " not judged (knife edge, flag knife-edge:" + (i + 1) + "): "
                        + problem.map(p -> "differs: " + p).orElse("within tolerance"));
                continue;
            }
            if (problem.isPresent() && wrong++ == 0) {
                r.failed("step " + (i + 1) + " of " + c.vectors().size() + ": " + problem.get()).at(i + 1, v.in());
                if (answer != null) {
                    r.sentences("the evaluation refused with " + v.error().get(), answer);
                } else {
                    r.outputs(v.out(), actuals.get(i));
                }
            }
        }
        if (wrong > 1) {
            r.note(wrong + " of " + c.vectors().size() + " steps gave a wrong result");
        }
        if (r.status() == CaseStatus.PASSED) {
            int notJudged = Flags.knifeEdges(c.flags()).size();
            r.passed((c.vectors().size() - notJudged - refused) + " step(s) within tolerance"
                    + (refused > 0 ? ", " + refused + " refused as required" : "")
                    + (notJudged > 0 ? ", " + notJudged + " not judged (knife edge)" : ""));
        }
        return actuals;
    }

    /** A step's answer: the outputs, or the implementation's refusal (an evaluation error, as its message). */
    private record Attempt(Map<String, Double> outputs, String refusal) {
    }

    /** Evaluates a step that may be refused; any answer but outputs or a clean evaluation error is a breakdown. */
    private static Attempt attempt(ImplementationUnderTest iut, RunCase c, Vector v, int step, ResultBuilder r)
            throws StepBreakdown {
        try {
            Map<String, Double> got = iut.eval(c.block().orElse(null), v.in());
            return new Attempt(got == null ? Map.of() : new LinkedHashMap<>(got), null);
        } catch (IutException e) {
            if (e.kind() == IutException.Kind.EVAL_ERROR) {
                return new Attempt(Map.of(), e.getMessage());
            }
            r.at(step, v.in());
            breakdown(r, e, "step " + step + " of " + c.vectors().size());
            throw new AssertionError("unreachable");
        }
    }

    private static final java.util.regex.Pattern EVALUATION_CODE = java.util.regex.Pattern.compile("FCL-V[0-9]{3}");

    /**
     * What is wrong with the answer to a step that must be refused: outputs instead of an evaluation error, or an
     * error that names another {@code FCL-Vnnn} code (an implementation that names no code refuses as well as any).
     */
    private static Optional<String> refusalProblem(Vector v, Attempt a) {
        String want = v.error().orElseThrow();
        String meaning = EvaluationCode.of(want).map(code -> " (" + code.entry().meaning() + ")").orElse("");
        if (a.refusal() == null) {
            return Optional.of("gives " + a.outputs() + " where the evaluation must be refused with " + want + meaning);
        }
        java.util.regex.Matcher m = EVALUATION_CODE.matcher(a.refusal());
        if (m.lookingAt() && !m.group().equals(want)) {
            return Optional.of("refuses the evaluation with " + m.group() + " where " + want + " is expected" + meaning
                    + ": " + a.refusal());
        }
        return Optional.empty();
    }

    private static void checkNoStateLeak(ImplementationUnderTest iut, RunCase c, List<Map<String, Double>> forward,
            ResultBuilder r) throws StepBreakdown {
        boolean nondeterminismNoted = false;
        try {
            iut.reset();
        } catch (IutException e) {
            breakdown(r, e, "reset");
        }
        for (int i = c.vectors().size() - 1; i >= 0; i--) {
            Vector v = c.vectors().get(i);
            if (v.refused()) {
                Attempt again = attempt(iut, c, v, i + 1, r);
                if (again.refusal() == null && !Flags.knifeEdges(c.flags()).contains(i + 1)) {
                    r.failed("state leaks between evaluations: after reset() and with the steps in reverse order, step "
                            + (i + 1) + " gives " + again.outputs() + " where it was refused before")
                            .at(i + 1, v.in()).sentences("the evaluation refused with " + v.error().get(),
                                    "gave outputs " + again.outputs());
                    return;
                }
                continue;
            }
            Map<String, Double> again = evaluate(iut, c, v, i + 1, r);
            Optional<String> leak = StepComparison.difference(v.out().keySet(), forward.get(i), again);
            if (leak.isEmpty()) {
                continue;
            }
            // judged by the case's tolerance, as any value is: a difference within it is noise, not leaked state
            Map<String, Double> first = new LinkedHashMap<>();
            for (String name : v.out().keySet()) {
                OutputComparison.lookup(forward.get(i), name).ifPresent(x -> first.put(name, x));
            }
            if (StepComparison.compare(c, first, again, new ResultBuilder(c)).isPresent()) {
                r.failed("state leaks between evaluations: after reset() and with the steps in reverse order, step "
                        + (i + 1) + " gives " + leak.get()).at(i + 1, v.in()).outputs(forward.get(i), again);
                return;
            }
            if (!nondeterminismNoted) {
                nondeterminismNoted = true;
                r.note("non-determinism within tolerance (not a state leak): after reset() and with the steps in"
                        + " reverse order, step " + (i + 1) + " gives " + leak.get());
            }
        }
    }

    private void checkExport(ImplementationUnderTest iut, RunCase c, ResultBuilder r) {
        if (c.inDialect()) {
            // clause 6 e) asks for FCL out; a dialect's constructs (curves, hedges, Takagi-Sugeno terms) have no
            // standard text to read back and compare, so the export of a dialect case is not judged
            r.export(ExportStatus.NOT_RUN, "not checked: the case is written in " + c.dialect().displayName()
                    + "'s dialect, and the export check reads standard FCL back");
            return;
        }
        try {
            Optional<String> text = iut.export();
            if (text.isEmpty()) {
                r.export(ExportStatus.UNSUPPORTED, "the implementation does not export FCL");
            } else {
                ExportCheck.Verdict v = exportCheck.check(text.get(), c);
                r.export(v.status(), v.message());
            }
        } catch (IutException e) {
            r.export(ExportStatus.FAILED, "export: the implementation " + IutFaults.describe(e));
        } catch (RuntimeException e) {
            r.export(ExportStatus.FAILED, "export: the exported text could not be checked: " + e);
        } catch (StackOverflowError e) {
            // whatever the implementation exports is its own fault, never the end of the run (results are kept)
            r.export(ExportStatus.FAILED, "export: the exported FCL nests too deeply for fclcert to read and"
                    + " evaluate it on this thread's stack");
        }
    }

    private static Map<String, Double> evaluate(ImplementationUnderTest iut, RunCase c, Vector v, int step,
            ResultBuilder r) throws StepBreakdown {
        try {
            Map<String, Double> got = iut.eval(c.block().orElse(null), v.in());
            return got == null ? Map.of() : new LinkedHashMap<>(got);
        } catch (IutException e) {
            r.at(step, v.in());
            breakdown(r, e, "step " + step + " of " + c.vectors().size());
            throw new AssertionError("unreachable");
        }
    }

    /** Records an exception at a step: an evaluation error is a failure, anything else a breakdown. */
    private static void breakdown(ResultBuilder r, IutException e, String where) throws StepBreakdown {
        if (e.kind() == IutException.Kind.EVAL_ERROR) {
            r.failed(where + ": the implementation reported an evaluation error: " + e.getMessage())
                    .error(IutFaults.errorText(e));
        } else {
            r.errored(where + ": the implementation " + IutFaults.describe(e), IutFaults.errorText(e));
        }
        throw new StepBreakdown(e.kind() == IutException.Kind.GAVE_UP);
    }

    /** Ends a case early once the implementation has answered a step with an error. */
    static final class StepBreakdown extends Exception {
        private static final long serialVersionUID = 1L;
        final boolean gaveUp;

        StepBreakdown(boolean gaveUp) {
            super(null, null, false, false);
            this.gaveUp = gaveUp;
        }
    }
}
