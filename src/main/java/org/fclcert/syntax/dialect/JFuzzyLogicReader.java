package org.fclcert.syntax.dialect;

import java.util.List;
import org.fclcert.syntax.ReadResult;

/**
 * Reads the FCL dialect of jFuzzyLogic (../shared/notes/peers.md): the standard's grammar plus
 * {@code //} and {@code /* *\/} comments, RANGE in FUZZIFY, named shapes ({@code trian}, {@code trape},
 * {@code gauss}, {@code gauss2}, {@code gbell}, {@code sigm}, {@code dsigm}, {@code cosine},
 * {@code singletons}), ACCU PROBOR and SUM, METHOD COGF and MM, and the settings it supplies when left
 * out (ACCU SUM, METHOD CoG, DEFAULT NC, each with FCL-W304). Where jFuzzyLogic gives a program another
 * meaning (coupled AND/OR, one priority for AND and OR, case-sensitive names, NSUM as BSUM) it warns.
 * docs/dialects.md lists what is read and its Open Level features.
 */
public final class JFuzzyLogicReader implements DialectReader {
    @Override
    public Dialect dialect() {
        return Dialect.JFUZZYLOGIC;
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return LibraryDialectParser.read(sourceName, text, false);
    }

    @Override
    public List<Giveaway> giveaways(String text) {
        return Giveaways.find(text, false);
    }
}
