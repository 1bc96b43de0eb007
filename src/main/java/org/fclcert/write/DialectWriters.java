package org.fclcert.write;

import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.Map;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;

/**
 * The library writers, and the round trip that proves what they write.
 *
 * <pre>{@code
 * Written w = DialectWriters.writer(Dialect.FUZZYLITE).write(program);  // program: checked, standard model
 * w.text();            // the program in fuzzylite's layout
 * w.notExpressible();  // FCL-X1nn errors, located in the original: what fuzzylite's FCL cannot say
 * w.differences();     // FCL-X2nn warnings: what fuzzylite is known to compute otherwise
 * RoundTrip rt = DialectWriters.readBackAndCompare(program, w);
 * rt.equal();          // read back by fclcert's fuzzylite reader, evaluated equal on a grid
 * }</pre>
 *
 * A writer takes any program a reader yields (standard or dialect model); for a dialect program convert it to
 * the standard first ({@link StandardConversion}) when its constructs should be judged against the standard.
 */
public final class DialectWriters {
    private DialectWriters() {
    }

    /**
     * The writer of a library's layout.
     *
     * @throws IllegalArgumentException for {@link Dialect#STRICT}: standard FCL is written by {@link CanonicalWriter}
     */
    public static DialectWriter writer(Dialect dialect) {
        return find(dialect).orElseThrow(() -> new IllegalArgumentException(dialect == Dialect.STRICT
                ? "standard FCL is written by CanonicalWriter" : "fclcert has no writer of " + dialect.displayName()));
    }

    /**
     * The writing side of the format registry ({@link Dialect} is the reading side): one case per format, which
     * the compiler holds complete; empty for the standard (written by {@link CanonicalWriter}) and for a format
     * fclcert only reads. {@code convert --to} and {@code --present-as} offer exactly the formats with a writer.
     */
    private static Optional<DialectWriter> find(Dialect dialect) {
        return Optional.ofNullable(switch (dialect) {
            case STRICT -> null;
            case FFLL -> new FfllWriter();
            case JFUZZYLOGIC -> new JFuzzyLogicWriter();
            case FUZZYLITE -> new FuzzyliteWriter();
            case FLL -> new FllWriter();
            case FIS -> new FisWriter();
        });
    }

    /** The formats there are writers for, in the order of {@link Dialect}. */
    public static List<Dialect> libraries() {
        return Arrays.stream(Dialect.values()).filter(d -> find(d).isPresent()).toList();
    }

    /** {@code written} read back in its dialect and evaluated against {@code original} on a grid of every block. */
    public static RoundTrip readBackAndCompare(Program original, Written written) {
        return RoundTrip.of(original, written, null, List.of());
    }

    /**
     * As {@link #readBackAndCompare(Program, Written)}, first evaluating {@code steps} in order (inputs by name; an
     * input a step leaves out keeps its value) on function block {@code block} (null: the first).
     */
    public static RoundTrip readBackAndCompare(Program original, Written written, String block,
            List<Map<String, Double>> steps) {
        return RoundTrip.of(original, written, block, steps);
    }
}
