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
     * After a strict reading with syntax errors: when the text shows a library dialect's signs and reading it
     * as that dialect gives fewer errors, and fewer syntax errors, than the strict reading, one line naming the dialect to use
     * ({@code fclcert: FILE: read as fuzzylite (...) it has 0 errors instead of 3: use --dialect fuzzylite, ...}).
     * A dialect that would not make things better is never suggested (a hint that adds errors is worse than none).
     */
    void hintWhenLibraryDialect(String file, String text, java.util.List<org.fclcert.model.Diagnostic> found,
            PrintWriter err) {
        if (this != strict || found.stream().noneMatch(d -> d.isError() && d.code().startsWith("FCL-S"))) {
            return;
        }
        DialectReaders.Choice choice = DialectReaders.auto(text);
        if (choice.dialect() == Dialect.STRICT) {
            return;
        }
        java.util.List<org.fclcert.model.Diagnostic> asDialect = org.fclcert.check.Analysis.analyze(
                DialectReaders.reader(choice.dialect()), file, text).diagnostics();
        long strictErrors = found.stream().filter(org.fclcert.model.Diagnostic::isError).count();
        long dialectErrors = asDialect.stream().filter(org.fclcert.model.Diagnostic::isError).count();
        // fewer errors in all, and fewer syntax errors: a dialect that only forgives a check (no DEFAULT) while the
        // syntax error stays does not explain the syntax error
        if (dialectErrors >= strictErrors || syntaxErrors(asDialect) >= syntaxErrors(found)) {
            return;
        }
        String signs = choice.explanation().substring(choice.explanation().indexOf(": ") + 2);
        String option = "--dialect " + choice.dialect().cliName();
        err.println("fclcert: " + file + ": read as " + choice.dialect().displayName() + " (" + signs + ") it has "
                + DiagnosticPrinter.count(dialectErrors, "error") + " instead of " + strictErrors + ": use " + option
                + ", or 'fclcert convert --from " + choice.dialect().cliName() + " " + file
                + "' to turn it into standard FCL");
    }

    private static long syntaxErrors(java.util.List<org.fclcert.model.Diagnostic> diagnostics) {
        return diagnostics.stream().filter(d -> d.isError() && d.code().startsWith("FCL-S")).count();
    }
}
