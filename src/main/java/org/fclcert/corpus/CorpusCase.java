package org.fclcert.corpus;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;

/**
 * One conformance case: a self-contained FCL file whose leading {@code (*--- ... ---*)} comment holds
 * YAML metadata.
 *
 * @param id            stable id ({@code B-COGS-001}); never renamed or reused
 * @param title         one line saying what the case does
 * @param level         the conformance level of the program (the highest level of its features)
 * @param features      every feature the program uses, in the order the file lists them
 * @param tests         the features this case is evidence for (a subset of {@code features})
 * @param tolerance     how outputs are compared
 * @param flags         {@code stateful}, {@code interpretation:<point of docs/semantics.md>},
 *                      {@code knife-edge:<vector>} (a vector not fair to judge: docs/corpus-format.md)
 * @param derivation    the hand derivation of the expected numbers, when given
 * @param block         the function block to instantiate, when the file has several (else the first)
 * @param vectors       ordered steps on one instance (positive cases; empty for negative ones)
 * @param expectReject  true for a negative case: a conforming implementation must reject the program
 * @param expectedError the single error of a negative case
 * @param programText   the file with the metadata comment replaced by as many line breaks as it spanned,
 *                      so every line of the program keeps the line number it has in the file (implementations
 *                      report lines, and negative cases cite them)
 * @param path          the case file
 * @param dialect       the syntax the program is written in ({@code dialect:} in the metadata): {@link
 *                      Dialect#STRICT} (the default) for standard FCL plus the Open Level methods that fit its syntax,
 *                      else a library's dialect, read with fclcert's reader of it (conformance/README.md, "Open Level
 *                      methods and dialects")
 */
public record CorpusCase(
        String id,
        String title,
        ConformanceLevel level,
        List<Feature> features,
        List<Feature> tests,
        Tolerance tolerance,
        List<String> flags,
        Optional<String> derivation,
        Optional<String> block,
        List<Vector> vectors,
        boolean expectReject,
        Optional<ExpectedError> expectedError,
        String programText,
        Path path,
        Dialect dialect) {

    /** The flag that marks a case whose steps depend on the state left by earlier steps. */
    public static final String STATEFUL = "stateful";

    /** Prefix of the flag naming the {@code docs/semantics.md} point a case depends on. */
    public static final String INTERPRETATION = "interpretation:";

    /** Prefix of the flag naming a vector (1-based) that is a knife edge, judged by no one (FairVectors). */
    public static final String KNIFE_EDGE = "knife-edge:";

    /** The form of a case id (conformance/README.md): {@code B-COGS-001}. */
    public static final java.util.regex.Pattern ID_FORM = java.util.regex.Pattern.compile(
            "[BEON]-[A-Z0-9]+(-[A-Z0-9]+)*-[0-9]{3}");

    /** The form of a flag: {@link #STATEFUL}, {@link #INTERPRETATION} with a point, {@link #KNIFE_EDGE} with a step. */
    public static final java.util.regex.Pattern FLAG_FORM = java.util.regex.Pattern.compile(
            "stateful|interpretation:[0-9A-Za-z.]+|knife-edge:[1-9][0-9]*");

    public CorpusCase {
        Objects.requireNonNull(id, "id");
        features = List.copyOf(features);
        tests = List.copyOf(tests);
        flags = List.copyOf(flags);
        vectors = List.copyOf(vectors);
        Objects.requireNonNull(dialect, "dialect");
    }

    /** The reader of this case's program ({@link #reader(Dialect)}). */
    public FclReader reader() {
        return reader(dialect);
    }

    /**
     * The one reading of a case's program in a dialect: standard FCL plus the Open Level methods that fit its syntax
     * ({@link StrictReader#openLevel()}) for {@link Dialect#STRICT}, else fclcert's reader of the dialect. The lint,
     * the harness and the reference read a case with it.
     */
    public static FclReader reader(Dialect dialect) {
        return dialect == Dialect.STRICT ? StrictReader.openLevel() : dialect.reader();
    }

    /** Whether the program is written in a library's dialect rather than in standard FCL. */
    public boolean inDialect() {
        return dialect != Dialect.STRICT;
    }

    /** True when the steps must run in order on one instance (never replayed in reverse). */
    public boolean stateful() {
        return flags.contains(STATEFUL);
    }

    /** The 1-based vectors flagged {@code knife-edge:<n>}, ascending. */
    public java.util.SortedSet<Integer> knifeEdges() {
        return knifeEdges(flags);
    }

    /** The vectors named by {@code knife-edge:<n>} flags in a list of flags. */
    public static java.util.SortedSet<Integer> knifeEdges(List<String> flags) {
        java.util.SortedSet<Integer> steps = new java.util.TreeSet<>();
        for (String f : flags) {
            if (f.startsWith(KNIFE_EDGE)) {
                try {
                    steps.add(Integer.parseInt(f.substring(KNIFE_EDGE.length())));
                } catch (NumberFormatException e) {
                    // the reader admits only digits; anything else is not a knife-edge flag
                }
            }
        }
        return steps;
    }

    /** The semantics point this case's expectations depend on, when it is flagged {@code interpretation:N}. */
    public Optional<String> interpretation() {
        return flags.stream()
                .filter(f -> f.startsWith(INTERPRETATION))
                .map(f -> f.substring(INTERPRETATION.length()))
                .findFirst();
    }
}
