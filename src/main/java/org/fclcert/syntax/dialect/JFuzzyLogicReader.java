package org.fclcert.syntax.dialect;

import java.util.List;
import org.fclcert.syntax.ReadResult;

/**
 * Reads the FCL dialect of jFuzzyLogic ({@link JFuzzyLogicDialect} says what it accepts, what it supplies
 * and where it warns; docs/dialects.md lists every construct and its Open Level features).
 */
public final class JFuzzyLogicReader implements DialectReader {
    private static final LibraryDialect DIALECT = new JFuzzyLogicDialect();

    @Override
    public Dialect dialect() {
        return Dialect.JFUZZYLOGIC;
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
