package org.fclcert.syntax.dialect;

import java.util.List;
import org.fclcert.syntax.FclReader;

/**
 * A reader for one library's FCL dialect. It reads into the same model as the strict reader; every
 * construct outside the standard that it accepts is recorded in {@link org.fclcert.model.Program#dialectFeatures()}
 * as an Open Level feature at the place it was written, and where the library gives a program another
 * meaning than the standard would, the reader warns.
 */
public interface DialectReader extends FclReader {

    Dialect dialect();

    /**
     * The constructs in {@code text} that only this dialect uses (not the standard, not usually the other
     * dialects), in source order; empty when nothing gives the dialect away. {@code --dialect auto} picks
     * the dialect with the strongest evidence and shows it to the user. Never throws, whatever the text.
     */
    List<Giveaway> giveaways(String text);

    /**
     * The words the dialect reads after {@code AND :}, {@code OR :}, {@code ACT :}, {@code ACCU :} and
     * {@code METHOD :}; the standard's for a format without those statements (FLL, FIS).
     */
    default DialectMethods methods() {
        return DialectMethods.STANDARD;
    }

    /**
     * One piece of evidence for a dialect: a construct in words, the 1-based line it is on, and how specific
     * it is (1: another library writes it too; 3: no other dialect has it).
     */
    record Giveaway(String construct, int line, int weight) {
        public Giveaway(String construct, int line) {
            this(construct, line, 1);
        }
    }
}
