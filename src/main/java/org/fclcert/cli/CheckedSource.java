package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.Optional;
import org.fclcert.check.Analysis;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;

/**
 * A source file read and checked in the dialect a command's option names, as eval, fmt and convert do it.
 *
 * @param text    the file's text
 * @param dialect the dialect it was read in (auto resolved)
 * @param program the program, empty when the file has errors
 */
record CheckedSource(String text, Dialect dialect, Optional<Program> program) {
    /**
     * Reads and checks FILE ({@code -}: standard input, named {@code <stdin>}); the choice of auto and the diagnostics go to err, and for a program with errors
     * {@code fclcert: FILE has errors; not <notDone>}.
     */
    static CheckedSource read(String path, DialectName name, String notDone, PrintWriter err) throws FileProblem {
        String text = SourceFiles.read(path);
        String file = SourceFiles.name(path);
        Dialect dialect;
        Analysis analysis;
        if (name.auto()) {
            DialectReaders.Choice choice = DialectReaders.auto(text);
            err.println("fclcert: " + file + ": " + choice.explanation());
            dialect = choice.dialect();
            analysis = Analysis.analyze(choice.reader(), file, text);
        } else {
            dialect = name.resolve(file, text, err);
            analysis = Analysis.analyze(dialect.reader(), file, text);
        }
        DiagnosticPrinter.text(err, analysis.diagnostics());
        name.hintWhenLibraryDialect(file, text, analysis.diagnostics(), err);
        if (analysis.program().isEmpty()) {
            err.println("fclcert: " + file + " has errors; not " + notDone);
        }
        return new CheckedSource(text, dialect, analysis.program());
    }
}
