package org.fclcert.cli;

import java.util.Locale;

/** The default report directory name for an implementation: {@code reports/<iut-name>}. */
final class OutDirs {
    private OutDirs() {
    }

    /** {@code reference} for fclcert's own evaluator, else the name the implementation gives. */
    static String forIut(String spec, String name) {
        return spec.strip().equals("reference") ? "reference" : forName(name);
    }

    /** Lower case, runs of anything but letters, digits, '.', '_' and '-' turned into one '-'. */
    static String forName(String name) {
        String cleaned = (name == null ? "" : name).toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9._-]+", "-")
                .replaceAll("^[-.]+|-+$", "");
        return cleaned.isEmpty() ? "iut" : cleaned;
    }
}
