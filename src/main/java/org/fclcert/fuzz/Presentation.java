package org.fclcert.fuzz;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Tolerance;
import org.fclcert.eval.EvaluationException;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.Written;

/**
 * How a generated program is put to the implementation ({@code fuzz --present-as}, as {@code certify} does on its
 * semantic axis): as standard FCL, or written in a library's layout by that library's writer ({@code
 * org.fclcert.write}). A written text is sent only when fclcert can vouch for it: the writer says the layout
 * expresses the program exactly (no {@code FCL-X1nn} loss), fclcert's own reader of the dialect reads it back
 * without an error, and the program read back gives the reference's values on the very steps that will be sent
 * (the exact judging path, within the exact tolerance). Otherwise the program is not presentable, with the reason
 * — the run counts the reasons and goes on to the next program, so a fuzz run never blames an implementation for a
 * text fclcert could not vouch for.
 */
final class Presentation {
    private static final CanonicalWriter CANONICAL = new CanonicalWriter();

    /**
     * The text the implementation gets, its layout (empty: standard FCL), the writer's known differences, and the
     * program fclcert reads in that text (the program itself for standard FCL).
     */
    record Sent(String text, Optional<Dialect> layout, List<Diagnostic> differences, Program seen) {
        Sent {
            differences = List.copyOf(differences);
        }
    }

    /**
     * Either a text to send or why there is none.
     *
     * @param reason the {@code FCL-X1nn} code of the first loss, {@code read-back} or {@code other-values} (a
     *               fault of the writer or of fclcert's reader of the dialect), or {@code writer-failed}
     */
    record Outcome(Optional<Sent> sent, String reason, String detail) {
        static Outcome of(Sent sent) {
            return new Outcome(Optional.of(sent), "", "");
        }

        static Outcome not(String reason, String detail) {
            return new Outcome(Optional.empty(), reason, detail);
        }
    }

    /** Reasons that are faults of fclcert (a writer and its reader disagree), not limits of the layout. */
    static final List<String> FAULTS = List.of("writer-failed", "read-back", "other-values");

    private final Optional<Dialect> layout;

    Presentation(Optional<Dialect> layout) {
        if (layout.isPresent() && layout.get() == Dialect.STRICT) {
            throw new IllegalArgumentException("standard FCL is the layout of no --present-as");
        }
        this.layout = layout;
    }

    static Presentation standard() {
        return new Presentation(Optional.empty());
    }

    Optional<Dialect> layout() {
        return layout;
    }

    /**
     * The text for {@code program} (checked, standard) whatever its steps: standard FCL, or the library's layout
     * when the writer loses nothing and fclcert reads the text back; else why not.
     */
    Outcome write(Program program) {
        if (layout.isEmpty()) {
            return Outcome.of(new Sent(CANONICAL.write(program), Optional.empty(), List.of(), program));
        }
        Dialect dialect = layout.get();
        Written w;
        try {
            w = DialectWriters.writer(dialect).write(program);
        } catch (RuntimeException e) {
            return Outcome.not("writer-failed", String.valueOf(e));
        }
        if (!w.exact()) {
            Diagnostic first = w.notExpressible().get(0);
            return Outcome.not(first.code(), first.message());
        }
        Optional<Program> back = readBack(w.text(), dialect);
        if (back.isEmpty()) {
            return Outcome.not("read-back", "fclcert's " + dialect.cliName() + " reader does not read the written text:\n"
                    + w.text());
        }
        return Outcome.of(new Sent(w.text(), layout, w.differences(), back.get()));
    }

    /**
     * {@code written} (of {@link #write}) when the program fclcert reads in it gives the reference's {@code expected}
     * values on their steps; else why not.
     */
    Outcome vouch(Outcome written, List<ReferenceProgram.Step> expected) {
        if (written.sent().isEmpty() || written.sent().get().layout().isEmpty()) {
            return written;
        }
        try {
            List<ReferenceProgram.Step> again = new ReferenceProgram(written.sent().get().seen()).run(
                    expected.stream().map(ReferenceProgram.Step::inputs).toList());
            for (int i = 0; i < expected.size(); i++) {
                Optional<String> differs = differs(expected.get(i).outputs(), again.get(i).outputs());
                if (differs.isPresent()) {
                    return Outcome.not("other-values", "step " + (i + 1) + ": " + differs.get());
                }
            }
        } catch (EvaluationException | RuntimeException e) {
            return Outcome.not("other-values", "the program read back does not evaluate: " + e.getMessage());
        }
        return written;
    }

    /** {@link #write}, then {@link #vouch} on the reference's {@code expected} values of the program's steps. */
    Outcome present(Program program, List<ReferenceProgram.Step> expected) {
        return vouch(write(program), expected);
    }

    /** The program the implementation is meant to see: fclcert's reading of the text sent for {@code program}. */
    Optional<Program> seen(Program program) {
        return write(program).sent().map(Sent::seen);
    }

    /** fclcert's reading of a written text in its dialect (the program the implementation is meant to see). */
    static Optional<Program> readBack(String text, Dialect dialect) {
        Analysis a = Analysis.analyze(DialectReaders.reader(dialect), "fuzz.fcl", text);
        return a.hasErrors() ? Optional.empty() : a.program();
    }

    private static Optional<String> differs(Map<String, Double> want, Map<String, Double> got) {
        for (Map.Entry<String, Double> e : want.entrySet()) {
            Double g = got.entrySet().stream().filter(x -> x.getKey().equalsIgnoreCase(e.getKey()))
                    .map(Map.Entry::getValue).findFirst().orElse(null);
            double x = e.getValue();
            if (g == null) {
                return Optional.of("no output " + e.getKey() + " read back");
            }
            boolean same = Double.isNaN(x) ? Double.isNaN(g) : Math.abs(g - x) <= Tolerance.EXACT.allowed(x, java.util.OptionalDouble.empty());
            if (!same) {
                return Optional.of(e.getKey() + " = " + g + " read back, " + x + " as generated");
            }
        }
        return Optional.empty();
    }
}
