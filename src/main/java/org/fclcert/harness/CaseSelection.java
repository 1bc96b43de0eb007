package org.fclcert.harness;

import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.fclcert.model.ConformanceLevel;

/**
 * The {@code --level}, {@code --feature} and {@code --case} filters. A case is selected when it passes every
 * filter given: its level is one of the levels, its {@code tests} name one of the features, its id matches
 * one of the globs ({@code *} any run of characters, {@code ?} one; case-insensitive). No filter, no narrowing.
 */
public record CaseSelection(Set<ConformanceLevel> levels, Set<String> features, List<String> globs) {
    public CaseSelection {
        levels = Set.copyOf(levels);
        features = features.stream().map(f -> f.toUpperCase(Locale.ROOT)).collect(Collectors.toUnmodifiableSet());
        globs = List.copyOf(globs);
    }

    public static CaseSelection all() {
        return new CaseSelection(Set.of(), Set.of(), List.of());
    }

    public boolean selects(RunCase c) {
        return (levels.isEmpty() || levels.contains(c.level()))
                && (features.isEmpty() || c.tests().stream().anyMatch(t -> features.contains(t.toUpperCase(Locale.ROOT))))
                && (globs.isEmpty() || globs.stream().anyMatch(g -> matches(g, c.id())));
    }

    public List<RunCase> apply(List<RunCase> cases) {
        return cases.stream().filter(this::selects).toList();
    }

    static boolean matches(String glob, String id) {
        StringBuilder regex = new StringBuilder();
        for (char ch : glob.toCharArray()) {
            switch (ch) {
                case '*' -> regex.append(".*");
                case '?' -> regex.append('.');
                default -> regex.append(Pattern.quote(String.valueOf(ch)));
            }
        }
        return Pattern.compile(regex.toString(), Pattern.CASE_INSENSITIVE).matcher(id).matches();
    }
}
