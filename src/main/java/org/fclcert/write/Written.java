package org.fclcert.write;

import java.util.List;
import java.util.Objects;
import org.fclcert.model.Diagnostic;
import org.fclcert.syntax.dialect.Dialect;

/**
 * A program written in a library's FCL layout.
 *
 * @param dialect        the library the text is written for
 * @param text           the program text, ending in a newline
 * @param notExpressible what the library's FCL cannot say (errors, {@code FCL-X1nn}), each located at the construct
 *                       of the original program; the text holds the nearest thing the library can say instead
 * @param differences    what the text says as the original does (as fclcert reads the dialect) but the library is
 *                       known to compute otherwise (warnings, {@code FCL-X2nn}), each located at the original construct
 */
public record Written(Dialect dialect, String text, List<Diagnostic> notExpressible, List<Diagnostic> differences) {
    public Written {
        Objects.requireNonNull(dialect, "dialect");
        Objects.requireNonNull(text, "text");
        notExpressible = List.copyOf(notExpressible);
        differences = List.copyOf(differences);
    }

    /** True when the text means what the original means (nothing was not expressible). */
    public boolean exact() {
        return notExpressible.isEmpty();
    }

    /** Every diagnostic, the losses first. */
    public List<Diagnostic> diagnostics() {
        return java.util.stream.Stream.concat(notExpressible.stream(), differences.stream()).toList();
    }
}
