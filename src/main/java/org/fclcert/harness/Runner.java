package org.fclcert.harness;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.StopSignal;

/**
 * Runs the selected cases one after another on one implementation and hands each result to the sink as
 * soon as it is known, so an interrupted run keeps what it did. A crash or a hang costs only the request that
 * caused it (the implementation is restarted); once the implementation is given up (iut's restart policy: it
 * cannot be started, or each of its last requests broke it down) the remaining cases are skipped with that reason
 * (never counted as passed). A run that is
 * stopped ({@link StopSignal}: Ctrl-C, SIGTERM, the run budget) records the case under way and every later
 * case as skipped with the reason, so that the results still hold every selected case exactly once.
 */
public final class Runner {
    /** How the message of a case begins that was not run because the run was stopped; the reason follows. */
    public static final String STOPPED = "not run: the run was stopped: ";

    private final CaseRunner caseRunner;
    private final RunListener listener;
    /** The run seed: each case gets fresh vectors and a disguise drawn from it ({@link FreshEvidence}); null: none. */
    private Long seed;

    public Runner(ExportCheck exportCheck, RunListener listener) {
        this(exportCheck, listener, null);
    }

    /**
     * With {@code presentAs} (null: none) every positive case is also presented in that library's layout
     * (the semantic axis, {@link Presenter}); the caller names the layout in the header
     * ({@link RunHeader#presentedAs}).
     */
    public Runner(ExportCheck exportCheck, RunListener listener, org.fclcert.syntax.dialect.Dialect presentAs) {
        this.caseRunner = new CaseRunner(exportCheck, presentAs == null ? null : new Presenter(presentAs));
        this.listener = listener;
    }

    /** Runner with the reference export check. */
    public Runner(RunListener listener) {
        this(new ReferenceExportCheck(), listener);
    }

    /** This runner, every case run with fresh vectors and a disguise drawn from {@code runSeed} ({@link FreshEvidence}). */
    public Runner withSeed(long runSeed) {
        seed = runSeed;
        return this;
    }

    public List<CaseResult> run(ImplementationUnderTest iut, RunHeader header, List<RunCase> cases,
            ResultSink sink) throws IOException {
        return run(iut, header, cases, sink, null);
    }

    /**
     * As {@link #run(ImplementationUnderTest, RunHeader, List, ResultSink)}, ending early when {@code stop} (null:
     * never) stops the run; {@code iut} should be guarded by it ({@link StopSignal#guard}), so that a request under
     * way ends at once.
     */
    public List<CaseResult> run(ImplementationUnderTest iut, RunHeader header, List<RunCase> cases,
            ResultSink sink, StopSignal stop) throws IOException {
        sink.header(header);
        caseRunner.readingAs(header == null ? null : header.iut().spec());
        List<CaseResult> results = new ArrayList<>();
        String gaveUpAt = null;
        for (int i = 0; i < cases.size(); i++) {
            RunCase c = cases.get(i);
            listener.caseStarted(c, i, cases.size());
            CaseResult result;
            if (stop != null && stop.stopped()) {
                result = notRun(c, STOPPED + stop.reason());
            } else if (gaveUpAt != null) {
                result = notRun(c, "not run: the implementation was given up at case " + gaveUpAt
                        + " (it could not be started, or each of its last requests crashed or hung)");
            } else {
                int cuts = stop == null ? 0 : stop.cuts();
                CaseRunner.Ran ran = seed == null ? caseRunner.run(iut, c) : FreshEvidence.run(caseRunner, iut, c, seed);
                if (stop != null && stop.cuts() != cuts) {
                    // the stop cut one of its requests short: what the case recorded since is fclcert's doing
                    result = notRun(c, STOPPED + stop.reason());
                } else {
                    result = ran.result();
                    gaveUpAt = ran.gaveUp() ? c.id() : null;
                }
            }
            sink.accept(result);
            results.add(result);
            listener.caseFinished(result, i, cases.size());
        }
        return results;
    }

    private CaseResult notRun(RunCase c, String why) {
        return caseRunner.notPresented(c, CaseResult.skipped(c.plan(), why), why.replaceFirst("^not run: ", ""));
    }
}
