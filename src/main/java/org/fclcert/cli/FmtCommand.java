package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.StandardConversion;
import org.fclcert.write.CanonicalWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert fmt}: a valid program in fclcert's canonical layout. */
@Command(name = "fmt", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Print a valid FCL program in canonical layout (upper-case keywords, four-space indentation, "
                + "one declaration per line, blocks in the order of 5.4). Comments are kept, each on the line "
                + "it stood before or ended. "
                + "A program with errors is left alone and its diagnostics are printed on stderr.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {ExitCodes.OK_LINE, ExitCodes.ERRORS_LINE, ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE})
final class FmtCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--write", description = "rewrite FILE in place instead of printing the text")
    boolean write;

    @Option(names = "--drop-comments", description = "leave the comments out (with --write: also a dialect program's,"
            + " which the conversion to standard FCL does not keep)")
    boolean dropComments;

    @Option(names = "--check", description = "print nothing but a unified diff from FILE to its canonical layout, and"
            + " exit with 1 when there is one (for CI)")
    boolean check;

    @Option(names = "--dialect", defaultValue = "strict", paramLabel = "DIALECT",
            completionCandidates = DialectName.Names.class, description = DialectName.DESCRIPTION
            + "; a dialect program is written as standard FCL when it converts exactly (else see 'fclcert convert')")
    DialectName dialect;

    @Parameters(paramLabel = "FILE", description = "an FCL source file, or - for standard input")
    String file;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (write && check) {
            err.println("fclcert: --write and --check exclude each other: --check only reports");
            return ExitCodes.USAGE;
        }
        if (write && SourceFiles.STDIN.equals(file)) {
            err.println("fclcert: --write rewrites a file; standard input (-) cannot be rewritten");
            return ExitCodes.USAGE;
        }
        String name = SourceFiles.name(file);
        try {
            CheckedSource checked = CheckedSource.read(file, dialect, "formatted", err);
            if (checked.program().isEmpty()) {
                return ExitCodes.ERRORS;
            }
            String source = checked.text();
            Dialect read = checked.dialect();
            Program program = checked.program().get();
            if (read != Dialect.STRICT) {
                StandardConversion.Result converted = new StandardConversion().convert(program);
                if (!converted.exact()) {
                    ConvertCommand.printFindings(err, converted.findings().stream()
                            .filter(f -> !(f.kind() instanceof StandardConversion.Kind.Exact)).toList(), false);
                    err.println("fclcert: " + name + " not formatted: as " + read.displayName() + " it does not convert"
                            + " exactly to standard FCL; 'fclcert convert --allow-lossy' writes the nearest standard"
                            + " program");
                    return ExitCodes.ERRORS;
                }
                program = converted.program();
            }
            if (dropComments) {
                program = program.withComments(List.of());
            }
            String canonical = new CanonicalWriter().write(program);
            // a dialect program's comments do not survive its conversion; --drop-comments asks to lose them
            int lostComments = dropComments ? 0 : occurrences(source, "(*") - occurrences(canonical, "(*");
            if (check) {
                String diff = UnifiedDiff.of(name, source, name + " (canonical)", canonical);
                out.print(diff);
                out.flush();
                noteLostComments(err, lostComments);
                if (diff.isEmpty()) {
                    return ExitCodes.OK;
                }
                err.println("fclcert: " + name + " is not in canonical layout (" + (SourceFiles.STDIN.equals(file)
                        ? "'fclcert fmt -' prints it" : "'fclcert fmt --write " + name + "' rewrites it") + ")");
                return ExitCodes.ERRORS;
            }
            if (!write) {
                out.print(canonical);
                out.flush(); // the text first, then the note, as a terminal would show them
                noteLostComments(err, lostComments);
                return ExitCodes.OK;
            }
            return rewrite(err, source, canonical, lostComments);
        } catch (FileProblem e) {
            err.println("fclcert: " + e.getMessage());
            return ExitCodes.USAGE;
        }
    }

    private int rewrite(PrintWriter err, String source, String canonical, int lostComments) throws FileProblem {
        if (canonical.equals(source)) {
            err.println("fclcert: " + file + " is already in canonical layout");
            return ExitCodes.OK;
        }
        if (lostComments > 0 && !dropComments) {
            // rewriting would destroy them, so only on explicit request
            err.println("fclcert: " + file + " not rewritten: " + DiagnosticPrinter.count(lostComments, "comment")
                    + " would be lost (a dialect program's comments do not survive its conversion to standard FCL);"
                    + " add --drop-comments to rewrite it anyway");
            return ExitCodes.USAGE;
        }
        SourceFiles.write(file, canonical);
        err.println("fclcert: rewrote " + file);
        return ExitCodes.OK;
    }

    private void noteLostComments(PrintWriter err, int lost) {
        if (lost > 0) {
            err.println("fclcert: note: " + DiagnosticPrinter.count(lost, "comment") + " of " + SourceFiles.name(file)
                    + " not kept (a dialect program's comments do not survive its conversion to standard FCL)");
        }
    }

    private static int occurrences(String text, String what) {
        int n = 0;
        for (int i = text.indexOf(what); i >= 0; i = text.indexOf(what, i + what.length())) {
            n++;
        }
        return n;
    }
}
