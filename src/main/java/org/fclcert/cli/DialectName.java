package org.fclcert.cli;

import java.io.PrintWriter;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;

/** {@code --dialect}: the dialect a program is written in, or {@code auto}. Lower case so --help lists them as typed. */
enum DialectName {
    strict,
    ffll,
    jfuzzylogic,
    fuzzylite,
    auto;

    static final String DESCRIPTION = "the FCL dialect FILE is written in: strict (IEC 61131-7), ffll, jfuzzylogic,"
            + " fuzzylite, or auto (the dialect with clearly the most signs; says which, and asks for --dialect on a"
            + " close call) (default: ${DEFAULT-VALUE})";

    /** The dialect to read {@code text} in; for auto, the choice is explained on err ({@code fclcert: FILE: read as ...}). */
    Dialect resolve(String file, String text, PrintWriter err) {
        if (this != auto) {
            return Dialect.byCliName(name()).orElseThrow();
        }
        DialectReaders.Choice choice = DialectReaders.auto(text);
        err.println("fclcert: " + file + ": " + choice.explanation());
        return choice.dialect();
    }

    /**
     * The reader for FILE: the named dialect's, or auto's choice (explained on err); when auto cannot tell, a
     * reader that reports the close call as a located FCL-S311 (or a detection failure as FCL-S999).
     */
    FclReader reader(String file, String text, PrintWriter err) {
        if (this != auto) {
            return DialectReaders.reader(resolve(file, text, err));
        }
        DialectReaders.Choice choice = DialectReaders.auto(text);
        err.println("fclcert: " + file + ": " + choice.explanation());
        return choice.reader();
    }
}
