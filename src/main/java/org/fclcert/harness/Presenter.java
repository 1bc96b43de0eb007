package org.fclcert.harness;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Collectors;
import org.fclcert.check.Analysis;
import org.fclcert.check.AnalysisMemo;
import org.fclcert.corpus.Vector;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.ReaderOptions;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.RoundTrip;
import org.fclcert.write.Written;

/**
 * The semantic axis of a certification ({@code --present-as}): a positive case's program written in a library's
 * own layout, so that an implementation that cannot read the standard's text still shows what it computes.
 *
 * <p>A case is presented only when the writer says the layout expresses the program exactly, and fclcert has
 * read the written text back with its own reader of the dialect and found it evaluates as the original (the
 * round trip, on the case's steps and a grid) and to the case's expected values (the reference evaluator on the
 * text read back, judged like any implementation). Otherwise the case is not presentable, with the reason: the
 * semantic axis never blames an implementation for a text fclcert could not vouch for.
 */
final class Presenter {
    private static final int REASONS = 3;

    private final Dialect dialect;

    Presenter(Dialect dialect) {
        if (dialect == Dialect.STRICT) {
            throw new IllegalArgumentException("the semantic axis presents programs in a library's layout, not strict");
        }
        this.dialect = dialect;
    }

    Dialect dialect() {
        return dialect;
    }

    /** The semantic result of positive case {@code c}, and whether the implementation has given up for good. */
    record Presentation(CaseResult.Presented presented, boolean gaveUp) {
    }

    Presentation present(ImplementationUnderTest iut, RunCase c) {
        return present(iut, c, c, null);
    }

    /**
     * As {@link #present(ImplementationUnderTest, RunCase)}, with {@code c}'s program the text sent under
     * {@code disguise} (null: none) and {@code iut} the implementation behind it ({@link DisguisedIut}): the disguised
     * program is what is written in the library's layout, so the semantic axis gets the same renaming, reordering
     * and fresh vectors as the language axis; its vectors stay in the corpus's names and are mapped as they are sent.
     * The reference's trace is of {@code plain}, the case as the corpus writes it.
     */
    Presentation present(ImplementationUnderTest iut, RunCase c, RunCase plain, Disguise disguise) {
        Prepared prepared = prepare(c, disguise);
        if (prepared.reason != null) {
            return new Presentation(new CaseResult.Presented(dialect.cliName(), PresentedStatus.NOT_PRESENTABLE,
                    "not presentable in " + dialect.displayName() + "'s layout: " + prepared.reason, List.of(), null,
                    null), false);
        }
        RunCase written = withProgram(c, prepared.written.text());
        ResultBuilder r = new ResultBuilder(written);
        boolean gaveUp = false;
        try {
            LoadOutcome outcome = iut.loadWritten(written.program(), dialect);
            if (outcome instanceof LoadOutcome.Rejected rejected) {
                String where = rejected.line().isPresent() ? " at line " + rejected.line().getAsInt() : "";
                r.failed("rejected the program written in " + dialect.displayName() + "'s layout" + where + ": "
                        + rejected.message());
            } else {
                CaseRunner.runForward(iut, written, r);
            }
        } catch (IutException e) {
            r.errored("load: the implementation " + IutFaults.describe(e), IutFaults.errorText(e));
            gaveUp = e.kind() == IutException.Kind.GAVE_UP;
        } catch (CaseRunner.StepBreakdown b) {
            gaveUp = b.gaveUp;
        } catch (RuntimeException e) {
            r.errored("the implementation failed unexpectedly: " + e, String.valueOf(e));
        }
        for (Diagnostic d : prepared.written.differences()) {
            r.note("known difference (" + d.code() + "): " + d.message());
        }
        CaseResult ran = r.traceReference(plain).build(0);
        PresentedStatus status = PresentedStatus.of(ran.status());
        return new Presentation(new CaseResult.Presented(dialect.cliName(), status, ran.message(),
                ran.verdict().notes(), ran.evidence(), status == PresentedStatus.PASSED ? null : written.program()),
                gaveUp);
    }

    /** The written text, or why there is none fclcert can vouch for. */
    private record Prepared(Written written, String reason) {
    }

    private Prepared prepare(RunCase c, Disguise disguise) {
        // a dialect case is read in its dialect, then written in the library's layout like any other
        Analysis analysis = c.inDialect() ? Analysis.analyze(c.reader(), c.id(), c.program())
                : AnalysisMemo.analyze(ReaderOptions.OPEN_LEVEL, c.id(), c.program());
        if (analysis.program().isEmpty()) {
            return new Prepared(null, "fclcert cannot read the case's program: " + firstError(analysis.diagnostics()));
        }
        Program program = analysis.program().get();
        Written w;
        try {
            w = DialectWriters.writer(dialect).write(program);
        } catch (RuntimeException e) {
            return new Prepared(null, "the writer failed: " + e);
        }
        if (!w.exact()) {
            String reasons = w.notExpressible().stream().limit(REASONS).map(d -> d.code() + " " + d.message())
                    .collect(Collectors.joining("; "));
            int more = w.notExpressible().size() - REASONS;
            return new Prepared(null, reasons + (more > 0 ? " (and " + more + " more)" : ""));
        }
        List<Map<String, Double>> steps = c.vectors().stream().map(Vector::in)
                .map(in -> disguise == null ? in : disguise.sent(in)).toList();
        String block = c.block().map(b -> disguise == null ? b : disguise.sent(b)).orElse(null);
        RoundTrip rt = DialectWriters.readBackAndCompare(program, w, block, steps);
        if (!rt.equal()) {
            return new Prepared(null, "the written text does not read back as the original: " + rt.summary());
        }
        Optional<String> expected = readBackGivesExpected(c, w, disguise);
        return new Prepared(w, expected.orElse(null));
    }

    /** The reference evaluator on fclcert's reading of the written text, judged against the case's steps. */
    private Optional<String> readBackGivesExpected(RunCase c, Written w, Disguise disguise) {
        RunCase written = withProgram(c, w.text());
        ResultBuilder r = new ResultBuilder(written);
        try (ImplementationUnderTest opened = Iuts.open("reference", IutOptions.defaults())) {
            ImplementationUnderTest reference = disguise == null ? opened : new DisguisedIut(opened, disguise);
            LoadOutcome outcome = reference.loadWritten(w.text(), dialect);
            if (outcome instanceof LoadOutcome.Rejected rejected) {
                return Optional.of("fclcert's reader rejects the written text: " + rejected.message());
            }
            CaseRunner.runForward(reference, written, r);
        } catch (IutException | CaseRunner.StepBreakdown e) {
            return Optional.of("the reference evaluator fails on the written text: " + e.getMessage());
        }
        return r.status() == CaseStatus.PASSED ? Optional.empty()
                : Optional.of("read back, it does not give the case's expected values: " + r.build(0).message());
    }

    /** The case with the written text as its program: read in the layout written, not in the case's dialect. */
    private RunCase withProgram(RunCase c, String text) {
        return new RunCase(c.id(), c.title(), c.level(), c.features(), c.tests(), c.flags(), c.block(), c.vectors(),
                c.expectedError(), c.tolerance(), text, c.source(), dialect);
    }

    private static String firstError(List<Diagnostic> diagnostics) {
        return diagnostics.stream().filter(Diagnostic::isError).findFirst().map(Diagnostic::toString)
                .orElse("(no diagnostic)");
    }
}
