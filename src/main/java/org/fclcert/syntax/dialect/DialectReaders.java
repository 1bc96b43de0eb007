package org.fclcert.syntax.dialect;

import java.util.List;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.StrictReader;

/**
 * The reader of each dialect, and {@code --dialect auto}: which dialect a text is written in.
 */
public final class DialectReaders {
    private DialectReaders() {
    }

    /** The reader of a dialect: the strict reader for {@link Dialect#STRICT}. */
    public static FclReader reader(Dialect dialect) {
        return switch (dialect) {
            case STRICT -> new StrictReader();
            case FFLL -> new FfllReader();
            case JFUZZYLOGIC -> new JFuzzyLogicReader();
            case FUZZYLITE -> new FuzzyliteReader();
        };
    }

    /** The dialect readers, in the order that breaks ties in {@link #auto}. */
    static List<DialectReader> dialectReaders() {
        return List.of(new FfllReader(), new JFuzzyLogicReader(), new FuzzyliteReader());
    }

    /**
     * What {@link #auto} chose and why.
     *
     * @param dialect    the dialect chosen
     * @param giveaways  the constructs that decided it (empty for strict)
     * @param tiedWith   dialects with as many giveaways, passed over because of the fixed order
     *                   FFLL, jFuzzyLogic, fuzzylite
     */
    public record Choice(Dialect dialect, List<DialectReader.Giveaway> giveaways, List<Dialect> tiedWith) {
        public Choice {
            giveaways = List.copyOf(giveaways);
            tiedWith = List.copyOf(tiedWith);
        }

        /** One line for the user: {@code read as FFLL: ACCUM: at line 30, term-only subcondition at line 41}. */
        public String explanation() {
            if (dialect == Dialect.STRICT) {
                return "read as standard FCL (strict)";
            }
            StringBuilder s = new StringBuilder("read as ").append(dialect.displayName()).append(": ");
            int shown = Math.min(giveaways.size(), 5);
            for (int i = 0; i < shown; i++) {
                DialectReader.Giveaway g = giveaways.get(i);
                s.append(i == 0 ? "" : ", ").append(g.construct()).append(" at line ").append(g.line());
            }
            if (giveaways.size() > shown) {
                s.append(" and ").append(giveaways.size() - shown).append(" more");
            }
            if (!tiedWith.isEmpty()) {
                s.append(" (as many signs of ").append(String.join(", ", tiedWith.stream()
                        .map(Dialect::displayName).toList())).append("; ties go to the first of FFLL, jFuzzyLogic,"
                        + " fuzzylite)");
            }
            return s.toString();
        }
    }

    /**
     * The dialect of a text: the dialect with the most giveaways (ties broken in the order FFLL, jFuzzyLogic,
     * fuzzylite, and said); strict when no dialect shows any, which is the case for every standard program
     * (giveaways are constructs outside the standard), and then the strict reader's errors, if any, say what
     * is wrong. Giveaways decide even when the strict reader reads the text without a syntax error: an FFLL
     * rule naming only terms parses as standard FCL (bare variables) but means something else. Never throws.
     */
    public static Choice auto(String text) {
        Dialect best = null;
        List<DialectReader.Giveaway> bestGiveaways = List.of();
        List<Dialect> tied = new java.util.ArrayList<>();
        for (DialectReader r : dialectReaders()) {
            List<DialectReader.Giveaway> g = r.giveaways(text == null ? "" : text);
            if (g.isEmpty()) {
                continue;
            }
            if (best == null || g.size() > bestGiveaways.size()) {
                best = r.dialect();
                bestGiveaways = g;
                tied.clear();
            } else if (g.size() == bestGiveaways.size()) {
                tied.add(r.dialect());
            }
        }
        return best == null ? new Choice(Dialect.STRICT, List.of(), List.of()) : new Choice(best, bestGiveaways, tied);
    }
}
