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
            + " fuzzylite, or auto (the dialect with the most signs; says which) (default: ${DEFAULT-VALUE})";

    /** The dialect to read {@code text} in; for auto, the choice is explained on err ({@code fclcert: FILE: read as ...}). */
    Dialect resolve(String file, String text, PrintWriter err) {
        if (this != auto) {
            return Dialect.byCliName(name()).orElseThrow();
        }
        DialectReaders.Choice choice = DialectReaders.auto(text);
        err.println("fclcert: " + file + ": " + choice.explanation());
        return choice.dialect();
    }

    FclReader reader(String file, String text, PrintWriter err) {
        return DialectReaders.reader(resolve(file, text, err));
    }
}
