package org.fclcert.harness;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

/** The case flags the runner and the reports act on ({@code stateful}, {@code interpretation:<point>}). */
public final class Flags {
    private Flags() {
    }

    public static boolean stateful(List<String> flags) {
        return flags.stream().anyMatch(f -> f.equalsIgnoreCase("stateful"));
    }

    /** The {@code interpretation:*} flag, when the case depends on a reading of the standard. */
    public static Optional<String> interpretation(List<String> flags) {
        return flags.stream().filter(f -> f.toLowerCase(Locale.ROOT).startsWith("interpretation")).findFirst();
    }
}
