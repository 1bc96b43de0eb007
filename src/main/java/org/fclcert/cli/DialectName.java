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

    /**
     * After a strict reading with syntax errors: when the text shows a library dialect's signs, one line
     * saying so ({@code fclcert: FILE looks like jFuzzyLogic (...): try --dialect auto or fclcert convert}).
     */
    void hintWhenLibraryDialect(String file, String text, java.util.List<org.fclcert.model.Diagnostic> found,
            PrintWriter err) {
        if (this != strict || found.stream().noneMatch(d -> d.isError() && d.code().startsWith("FCL-S"))) {
            return;
        }
        DialectReaders.Choice choice = DialectReaders.auto(text);
        if (choice.dialect() != Dialect.STRICT) {
            String signs = choice.explanation().substring(choice.explanation().indexOf(": ") + 2);
            err.println("fclcert: " + file + ": this looks like " + choice.dialect().displayName() + " (" + signs
                    + "): try --dialect auto, or 'fclcert convert " + file + "' to turn it into standard FCL");
        }
    }
}
