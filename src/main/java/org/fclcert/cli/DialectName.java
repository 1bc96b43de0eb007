package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Optional;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code --dialect} (and {@code convert --from/--to}): a format of {@link Dialect}, or {@code auto}. The names, the
 * help text and the shell completion are drawn from {@link Dialect}, so a new format needs no change here.
 *
 * @param dialect the format named; empty for auto
 */
record DialectName(Optional<Dialect> dialect) {
    static final DialectName AUTO = new DialectName(Optional.empty());

    /** The help text of {@code --dialect} (picocli fills in the names from {@link Names}). */
    static final String DESCRIPTION = "the format FILE is written in: ${COMPLETION-CANDIDATES} (auto: the dialect with"
            + " clearly the most signs; says which, and asks for --dialect on a close call) (default: ${DEFAULT-VALUE})";

    /** Every name, for picocli's help text and completion: each format's, then auto. */
    static final class Names implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            List<String> names = new ArrayList<>(Dialect.cliNames());
            names.add("auto");
            return names.iterator();
        }
    }

    /** Picocli's wording of an enum's values, kept for the names drawn from registries. */
    static final class Naming {
        private Naming() {
        }

        static String list(Iterable<String> names) {
            List<String> all = new ArrayList<>();
            names.forEach(all::add);
            return all.toString();
        }
    }

    /** Reads a name, in any case; an unknown one is a usage error naming the names there are. */
    static final class Converter implements ITypeConverter<DialectName> {
        @Override
        public DialectName convert(String value) {
            if (value.strip().equalsIgnoreCase("auto")) {
                return AUTO;
            }
            return Dialect.byCliName(value.strip()).map(d -> new DialectName(Optional.of(d)))
                    .orElseThrow(() -> new TypeConversionException("expected one of "
                            + Naming.list(new Names()) + " (case-insensitive) but was '" + value + "'"));
        }
    }

    static DialectName of(Dialect dialect) {
        return new DialectName(Optional.of(dialect));
    }

    boolean auto() {
        return dialect.isEmpty();
    }

    boolean is(Dialect d) {
        return dialect.equals(Optional.of(d));
    }

    /** The dialect to read {@code text} in; for auto, the choice is explained on err ({@code fclcert: FILE: read as ...}). */
    Dialect resolve(String file, String text, PrintWriter err) {
        if (dialect.isPresent()) {
            return dialect.get();
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
        if (dialect.isPresent()) {
            return dialect.get().reader();
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
        if (!is(Dialect.STRICT) || found.stream().noneMatch(d -> d.isError() && d.code().startsWith("FCL-S"))) {
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
