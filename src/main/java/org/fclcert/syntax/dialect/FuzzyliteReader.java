package org.fclcert.syntax.dialect;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.ReadResult;

/**
 * PLACEHOLDER on the dialect-core branch: the fuzzylite reader is written on the dialect-shapes branch and
 * replaces this class (same name, public no-arg constructor) when the branches are merged. Until then every
 * read is one located error saying so, and it claims no giveaways.
 */
public final class FuzzyliteReader implements DialectReader {
    @Override
    public Dialect dialect() {
        return Dialect.FUZZYLITE;
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return new ReadResult(Optional.empty(), List.of(Diagnostic.error(
                SourceLocation.of(sourceName == null ? "<input>" : sourceName, 1, 1), "FCL-S999",
                "the fuzzylite dialect reader is not on this branch")));
    }

    @Override
    public List<Giveaway> giveaways(String text) {
        return List.of();
    }
}
