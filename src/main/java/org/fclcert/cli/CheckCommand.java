package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.fclcert.check.Analysis;
import org.fclcert.check.SarifLog;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.model.Diagnostic;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert check}: reads and checks programs against IEC 61131-7 and lists every diagnostic. */
@Command(name = "check", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Check FCL programs against IEC 61131-7: syntax (5.4) and the semantic rules. "
                + "Prints one line per diagnostic (path:line:col: severity CODE: message) and a summary on stderr.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {ExitCodes.OK_LINE, ExitCodes.ERRORS_LINE, ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE})
final class CheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    /** {@code --format} of check: the two common ones and SARIF 2.1.0 for CI. */
    enum Format {
        text,
        json,
        sarif
    }

    @Option(names = "--format", defaultValue = "text", paramLabel = "FORMAT",
            description = "text, json or sarif (SARIF 2.1.0, for code scanning in CI) (default: ${DEFAULT-VALUE})")
    Format format;

    @Option(names = "--dialect", defaultValue = "strict", paramLabel = "DIALECT",
            completionCandidates = DialectName.Names.class, description = DialectName.DESCRIPTION)
    DialectName dialect;

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "FCL source files; - reads standard input"
            + " (named <stdin> in locations)")
    List<String> files;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        List<Diagnostic> all = new ArrayList<>();
        int checked = 0;
        boolean unreadable = false;
        if (files.stream().filter(SourceFiles.STDIN::equals).count() > 1) {
            err.println("fclcert: '-' (standard input) is given more than once; it can be read only once");
            return ExitCodes.USAGE;
        }
        for (String path : files) {
            String file = SourceFiles.name(path);
            try {
                String text = SourceFiles.read(path);
                List<Diagnostic> found = Analysis.analyze(dialect.reader(file, text, err), file, text).diagnostics();
                if (format == Format.text) {
                    DiagnosticPrinter.text(out, found);
                }
                dialect.hintWhenLibraryDialect(file, text, found, err);
                all.addAll(found);
                checked++;
            } catch (FileProblem e) {
                err.println("fclcert: " + e.getMessage());
                unreadable = true;
            }
        }
        if (format == Format.json) {
            DiagnosticPrinter.json(out, all);
        } else if (format == Format.sarif) {
            out.print(SarifLog.render(all));
        }
        err.println("fclcert: " + DiagnosticPrinter.summary(checked, all));
        // an unreadable file means the question was not fully answered, which outranks found errors
        if (unreadable) {
            return ExitCodes.USAGE;
        }
        return all.stream().anyMatch(Diagnostic::isError) ? ExitCodes.ERRORS : ExitCodes.OK;
    }
}
