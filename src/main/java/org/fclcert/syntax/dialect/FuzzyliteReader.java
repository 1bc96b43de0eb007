package org.fclcert.syntax.dialect;

import java.util.List;
import org.fclcert.syntax.ReadResult;

/**
 * Reads the FCL dialect of fuzzylite 5 and 6 ({@link FuzzyliteDialect} says what it accepts and means;
 * docs/dialects.md lists every construct). A construct fuzzylite drops silently (an upper-case {@code IF})
 * is an error here.
 */
public final class FuzzyliteReader implements DialectReader {
    private static final LibraryDialect DIALECT = new FuzzyliteDialect();

    @Override
    public Dialect dialect() {
        return Dialect.FUZZYLITE;
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return DialectParser.read(sourceName, text, DIALECT);
    }

    @Override
    public DialectMethods methods() {
        return DialectMethods.of(DIALECT);
    }

    @Override
    public List<Giveaway> giveaways(String text) {
        return Giveaways.find(text, DIALECT);
    }
}
