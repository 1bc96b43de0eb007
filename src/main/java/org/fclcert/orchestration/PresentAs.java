package org.fclcert.orchestration;

import java.util.Locale;
import java.util.Optional;
import org.fclcert.syntax.dialect.Dialect;

/**
 * {@code --present-as}: in which library's layout the positive cases are also sent, the semantic axis of a
 * certification. {@link #AUTO} picks the layout of a built-in library adapter (fuzzylite and jfuzzylite:
 * fuzzylite's; jfuzzylogic: jFuzzyLogic's; ffll: FFLL's) and none for the reference, {@code java:} and {@code process:}.
 */
public enum PresentAs {
    AUTO,
    NONE,
    FUZZYLITE,
    JFUZZYLOGIC,
    FFLL;

    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The layout for an implementation reached by {@code iutSpec}; empty: the language axis only. */
    public Optional<Dialect> resolve(String iutSpec) {
        return switch (this) {
            case NONE -> Optional.empty();
            case FUZZYLITE -> Optional.of(Dialect.FUZZYLITE);
            case JFUZZYLOGIC -> Optional.of(Dialect.JFUZZYLOGIC);
            case FFLL -> Optional.of(Dialect.FFLL);
            case AUTO -> auto(iutSpec);
        };
    }

    private static Optional<Dialect> auto(String iutSpec) {
        String spec = iutSpec.strip();
        String adapter = spec.contains(":") ? spec.substring(0, spec.indexOf(':')) : spec;
        return switch (adapter.toLowerCase(Locale.ROOT)) {
            case "fuzzylite", "jfuzzylite" -> Optional.of(Dialect.FUZZYLITE);
            case "jfuzzylogic" -> Optional.of(Dialect.JFUZZYLOGIC);
            case "ffll" -> Optional.of(Dialect.FFLL);
            default -> Optional.empty();
        };
    }

    public static PresentAs byWord(String word) {
        return valueOf(word.strip().toUpperCase(Locale.ROOT));
    }
}
