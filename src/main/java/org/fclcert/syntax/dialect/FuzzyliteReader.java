package org.fclcert.syntax.dialect;

import java.util.List;
import org.fclcert.syntax.ReadResult;

/**
 * Reads the FCL dialect of fuzzylite 6 (../shared/notes/peers.md): {@code //} and {@code #} comments, one
 * statement per line, lower-case rule keywords ({@code if … is … and … then … with}), rules without
 * {@code ;}, conclusions joined by {@code and}, ACCU inside DEFUZZIFY, shapes by name
 * ({@code Triangle a b c}, {@code Gaussian mean sd}, …, {@code Discrete}), {@code RANGE := (-inf .. inf)},
 * {@code ENABLED}, {@code LOCK}, {@code DEFAULT := nan}, hedges ({@code very}, {@code somewhat},
 * {@code extremely}, {@code seldom}, {@code any}, {@code not}), ACCU ASUM (probabilistic OR) and SUM,
 * METHOD MM and COGSS. A construct fuzzylite drops silently (an upper-case {@code IF}) is an error here.
 */
public final class FuzzyliteReader implements DialectReader {
    @Override
    public Dialect dialect() {
        return Dialect.FUZZYLITE;
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return LibraryDialectParser.read(sourceName, text, true);
    }

    @Override
    public List<Giveaway> giveaways(String text) {
        return Giveaways.find(text, true);
    }
}
