package org.fclcert.write;

import java.util.List;
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
        return switch (dialect) {
            case FUZZYLITE -> new FuzzyliteWriter();
            case JFUZZYLOGIC -> new JFuzzyLogicWriter();
            case FFLL -> new FfllWriter();
            case STRICT -> throw new IllegalArgumentException("standard FCL is written by CanonicalWriter");
        };
    }

    /** The dialects there are writers for. */
    public static List<Dialect> libraries() {
        return List.of(Dialect.FFLL, Dialect.JFUZZYLOGIC, Dialect.FUZZYLITE);
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
