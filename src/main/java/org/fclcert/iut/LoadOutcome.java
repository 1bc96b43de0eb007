package org.fclcert.iut;

import java.util.List;
import java.util.Objects;
import java.util.OptionalInt;

/** How an implementation answered a {@code load}: it accepted the program, or rejected it cleanly. */
public sealed interface LoadOutcome {

    /** The program loaded; {@code blocks} are its function block names in the order written. */
    record Loaded(List<String> blocks) implements LoadOutcome {
        public Loaded {
            blocks = blocks.stream().map(IutText::kept).toList();
        }
    }

    /**
     * The implementation refused the program, with its message and (when it gives one) the 1-based
     * line of the first error, counted in the text as sent.
     */
    record Rejected(String message, OptionalInt line) implements LoadOutcome {
        public Rejected {
            message = IutText.kept(Objects.requireNonNull(message, "message"));
            Objects.requireNonNull(line, "line");
        }
    }
}
