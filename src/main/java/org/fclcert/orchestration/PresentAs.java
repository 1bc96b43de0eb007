package org.fclcert.orchestration;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fclcert.iut.Iuts;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.DialectWriters;

/**
 * {@code --present-as}: in which format the positive cases are also sent, the semantic axis of a certification:
 * {@link #AUTO} (the layout the built-in adapter's entry in {@link Iuts#KINDS} names; none for the reference,
 * {@code java:} and {@code process:}), {@link #NONE}, or any format fclcert writes ({@link DialectWriters#libraries()}).
 * Drawn from those two registries, so a new format or adapter needs no change here.
 *
 * @param word   as typed: {@code auto}, {@code none} or a format's command-line name
 * @param layout the format named; empty for auto and none
 */
public record PresentAs(String word, Optional<Dialect> layout) {
    public static final PresentAs AUTO = new PresentAs("auto", Optional.empty());
    public static final PresentAs NONE = new PresentAs("none", Optional.empty());

    /** The layout {@code dialect}, which fclcert must have a writer of. */
    public static PresentAs of(Dialect dialect) {
        if (!DialectWriters.libraries().contains(dialect)) {
            throw new IllegalArgumentException("fclcert writes no " + dialect.displayName() + " to present cases in");
        }
        return new PresentAs(dialect.cliName(), Optional.of(dialect));
    }

    /** Every word {@code --present-as} takes: auto, none and each format with a writer. */
    public static List<String> words() {
        List<String> out = new ArrayList<>(List.of(AUTO.word, NONE.word));
        DialectWriters.libraries().forEach(d -> out.add(d.cliName()));
        return out;
    }

    /**
     * The value of a word, in any case.
     *
     * @throws IllegalArgumentException naming the words there are
     */
    public static PresentAs byWord(String word) {
        String w = word.strip().toLowerCase(Locale.ROOT);
        if (w.equals(AUTO.word)) {
            return AUTO;
        }
        if (w.equals(NONE.word)) {
            return NONE;
        }
        return Dialect.byCliName(w).filter(DialectWriters.libraries()::contains).map(PresentAs::of)
                .orElseThrow(() -> new IllegalArgumentException("'" + word.strip() + "' is not one of "
                        + String.join(", ", words())));
    }

    /** The layout for an implementation reached by {@code iutSpec}; empty: the language axis only. */
    public Optional<Dialect> resolve(String iutSpec) {
        return this == AUTO || word.equals(AUTO.word) ? Iuts.presentedAs(iutSpec) : layout;
    }
}
