package org.fclcert.fuzz;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.corpus.Comparison;
import org.fclcert.corpus.Tolerance;
import org.fclcert.iut.IutException;
import org.fclcert.iut.LoadOutcome;

/**
 * Puts one program (as standard FCL or in a library's layout) and its steps to an implementation and compares every
 * step with the reference.
 */
final class Trial {
    private Trial() {
    }

    /**
     * The first deviation, if any. The implementation is restarted after a fatal one.
     *
     * @throws IutException of kind INFRA when the implementation cannot be reopened
     */
    static Optional<Deviation> run(IutSession session, ReferenceProgram ref, Presentation.Sent sent,
            List<ReferenceProgram.Step> expected) throws IutException {
        Optional<Deviation> d = attempt(session, ref, sent, expected);
        if (d.isPresent() && d.get().kind().fatal()) {
            session.restart();
        }
        return d;
    }

    private static Optional<Deviation> attempt(IutSession session, ReferenceProgram ref, Presentation.Sent sent,
            List<ReferenceProgram.Step> expected) throws IutException {
        try {
            LoadOutcome outcome = sent.layout().isPresent() ? session.iut().loadWritten(sent.text(), sent.layout().get())
                    : session.iut().load(sent.text());
            if (outcome instanceof LoadOutcome.Rejected rejected) {
                return Optional.of(Deviation.atLoad(DeviationKind.REJECTED, "rejected the valid program: "
                        + rejected.message() + rejected.line().stream().mapToObj(l -> " (line " + l + ")").findFirst().orElse("")));
            }
        } catch (IutException e) {
            return Optional.of(Deviation.atLoad(kind(e), "on load: " + describe(e)));
        }
        try {
            session.iut().reset();
        } catch (IutException e) {
            return Optional.of(Deviation.atLoad(kind(e), "on reset: " + describe(e)));
        }
        for (int i = 0; i < expected.size(); i++) {
            ReferenceProgram.Step step = expected.get(i);
            Map<String, Double> actual;
            try {
                actual = session.iut().eval(null, step.inputs());
            } catch (IutException e) {
                return Optional.of(new Deviation(kind(e), i, "", Double.NaN, Double.NaN,
                        "step " + (i + 1) + ": " + describe(e), Map.of()));
            }
            List<Comparison> comparisons = Tolerance.CONTINUOUS.compareAll(step.outputs(), actual, ref.scales());
            for (Comparison c : comparisons) {
                if (!c.passed()) {
                    return Optional.of(deviation(i, c, actual));
                }
            }
        }
        return Optional.empty();
    }

    private static Deviation deviation(int step, Comparison c, Map<String, Double> actual) {
        Double got = lookup(actual, c.output());
        DeviationKind kind = got == null ? DeviationKind.MISSING_OUTPUT
                : Double.isFinite(got) ? DeviationKind.WRONG_VALUE : DeviationKind.NOT_A_NUMBER;
        String message = got == null ? "step " + (step + 1) + ": no value for " + c.output() + " (reference " + c.expected() + ")"
                : "step " + (step + 1) + ": " + c.output() + " = " + got + " where the reference gives " + c.expected()
                        + " (error " + Math.abs(got - c.expected()) + ", allowed " + c.allowed() + ")";
        return new Deviation(kind, step, c.output(), c.expected(), got == null ? Double.NaN : got, message, actual);
    }

    private static Double lookup(Map<String, Double> actual, String name) {
        return actual.entrySet().stream().filter(e -> e.getKey().equalsIgnoreCase(name)).map(Map.Entry::getValue)
                .filter(v -> v != null).findFirst().orElse(null);
    }

    static DeviationKind kind(IutException e) {
        return switch (e.kind()) {
            case EVAL_ERROR -> DeviationKind.EVAL_ERROR;
            case TIMEOUT -> DeviationKind.HANG;
            case PROTOCOL -> DeviationKind.GARBAGE;
            case CRASH, GAVE_UP, INFRA, STOPPED -> DeviationKind.CRASH;   // fuzz guards no call: STOPPED never comes
        };
    }

    private static String describe(IutException e) {
        String tail = e.stderrTail().isBlank() ? "" : " (stderr: " + lastLine(e.stderrTail()) + ")";
        return e.getMessage() + tail;
    }

    private static String lastLine(String s) {
        String[] lines = s.strip().split("\n");
        return lines[lines.length - 1];
    }
}
