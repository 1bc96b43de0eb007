package org.fclcert.harness;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.iut.ImplementationUnderTest;

/**
 * Runs the selected cases one after another on one implementation and hands each result to the sink as
 * soon as it is known, so an interrupted run keeps what it did. Once the implementation has exhausted its
 * restart budget the remaining cases are skipped with that reason (never counted as passed).
 */
public final class Runner {
    private final CaseRunner caseRunner;
    private final RunListener listener;

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

    public List<CaseResult> run(ImplementationUnderTest iut, RunHeader header, List<RunCase> cases,
            ResultSink sink) throws IOException {
        sink.header(header);
        List<CaseResult> results = new ArrayList<>();
        String gaveUpAt = null;
        for (int i = 0; i < cases.size(); i++) {
            RunCase c = cases.get(i);
            listener.caseStarted(c, i, cases.size());
            CaseResult result;
            if (gaveUpAt != null) {
                result = caseRunner.notPresented(c, CaseResult.skipped(c.plan(),
                        "not run: the implementation was given up at case " + gaveUpAt + " (restart budget exhausted)"));
            } else {
                CaseRunner.Ran ran = caseRunner.run(iut, c);
                result = ran.result();
                gaveUpAt = ran.gaveUp() ? c.id() : null;
            }
            sink.accept(result);
            results.add(result);
            listener.caseFinished(result, i, cases.size());
        }
        return results;
    }
}
