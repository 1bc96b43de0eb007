package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.databind.util.StdConverter;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The wire form of a {@link CaseResult}: the flat object of a {@code "type":"case"} line in
 * {@code results.jsonl} and of an entry of {@code report.json}'s {@code cases}, its fields in the order
 * {@code docs/report-format.md} lists them. Absent parts are left out. {@code expected}/{@code actual} are
 * output maps (a non-finite value written as the string {@code "NaN"}, {@code "Infinity"} or
 * {@code "-Infinity"}) or sentences.
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
record CaseResultJson(
        String id,
        String title,
        String level,
        List<String> tests,
        List<String> flags,
        CaseStatus status,
        String message,
        Integer step,
        Map<String, Double> inputs,
        Object expected,
        Object actual,
        String error,
        Double maxError,
        ReferenceTrace reference,
        String tolerance,
        ExportStatus exportStatus,
        String exportMessage,
        List<String> notes,
        String block,
        String program,
        Long durationMs,
        RejectionPlace rejection,
        PresentedJson presented,
        List<Exchange> replies,
        Integer crashes,
        Integer restarts) {

    /** The semantic axis of a case ({@link CaseResult.Presented}), flat like the case itself. */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record PresentedJson(String dialect, PresentedStatus status, String message, Integer step,
            Map<String, Double> inputs, Object expected, Object actual, String error, Double maxError,
            ReferenceTrace reference, List<String> notes, String program) {

        static PresentedJson of(CaseResult.Presented p) {
            if (p == null) {
                return null;
            }
            CaseResult.Evidence e = p.evidence();
            CaseResult.Step step = e.step();
            CaseResult.Mismatch m = e.mismatch();
            return new PresentedJson(p.dialect(), p.status(), p.message(), step == null ? null : step.number(),
                    step == null ? null : step.inputs(), m == null ? null : m.expected(),
                    m == null ? null : m.actual(), e.error(), e.maxError(), e.reference(),
                    p.notes().isEmpty() ? null : p.notes(), p.program());
        }

        CaseResult.Presented toPresented() {
            CaseResult.Step s = step == null ? null : new CaseResult.Step(step, inputs);
            return new CaseResult.Presented(dialect, status == null ? PresentedStatus.SKIPPED : status, message,
                    notes, new CaseResult.Evidence(s, mismatch(expected, actual), error, maxError, reference), program);
        }
    }

    static CaseResultJson of(CaseResult r) {
        CaseResult.Evidence e = r.evidence();
        CaseResult.Step step = e.step();
        CaseResult.Mismatch m = e.mismatch();
        return new CaseResultJson(r.id(), r.title(), r.level(), r.tests(), r.flags(), r.status(), r.message(),
                step == null ? null : step.number(), step == null ? null : step.inputs(),
                m == null ? null : m.expected(), m == null ? null : m.actual(), e.error(), e.maxError(),
                e.reference(), r.setup().tolerance(), r.export().status(), r.export().message(), r.verdict().notes(),
                r.setup().block(), r.setup().program(), r.setup().durationMs(), r.verdict().rejection(),
                PresentedJson.of(r.presented()), r.replies(), r.setup().crashes(), r.setup().restarts());
    }

    CaseResult toResult() {
        PlannedCase plan = new PlannedCase(id, title, level, tests == null ? List.of() : tests,
                flags == null ? List.of() : flags);
        CaseResult.Step s = step == null ? null : new CaseResult.Step(step, inputs);
        return new CaseResult(plan, new CaseResult.Verdict(status, message, notes, rejection),
                new CaseResult.Evidence(s, mismatch(expected, actual), error, maxError, reference),
                new CaseResult.Export(exportStatus, exportMessage),
                new CaseResult.Setup(block, tolerance, program, durationMs, crashes, restarts),
                presented == null ? null : presented.toPresented(), replies);
    }

    private static CaseResult.Mismatch mismatch(Object expected, Object actual) {
        if (expected == null && actual == null) {
            return null;
        }
        if (expected instanceof Map<?, ?> || actual instanceof Map<?, ?>) {
            return new CaseResult.Mismatch.Outputs(outputs(expected), outputs(actual));
        }
        return new CaseResult.Mismatch.Sentences(expected == null ? null : expected.toString(),
                actual == null ? null : actual.toString());
    }

    /** An output map read back: numbers, the strings Jackson writes for non-finite values, or null. */
    private static Map<String, Double> outputs(Object value) {
        Map<String, Double> outputs = new LinkedHashMap<>();
        if (value instanceof Map<?, ?> map) {
            map.forEach((k, v) -> outputs.put(String.valueOf(k), v instanceof Number n ? Double.valueOf(n.doubleValue())
                    : v == null ? null : parse(v.toString())));
        }
        return outputs;
    }

    private static Double parse(String text) {
        try {
            return Double.valueOf(text);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /** Jackson's side: a result is written as its flat form. */
    static final class FromResult extends StdConverter<CaseResult, CaseResultJson> {
        @Override
        public CaseResultJson convert(CaseResult value) {
            return of(value);
        }
    }

    /** Jackson's side: the flat form is read into a result. */
    static final class ToResult extends StdConverter<CaseResultJson, CaseResult> {
        @Override
        public CaseResult convert(CaseResultJson value) {
            return value.toResult();
        }
    }
}
