package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import org.fclcert.check.Analysis;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.model.Diagnostic;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;
import org.fclcert.write.StandardConversion.Finding;
import org.fclcert.write.StandardConversion.Kind;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.RoundTrip;
import org.fclcert.write.Written;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert convert}: a dialect program written as standard FCL, with what converted how. */
@Command(name = "convert", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Convert a program written in a library's format (--from: FFLL, jFuzzyLogic or fuzzylite FCL, ...) to "
                + "standard IEC 61131-7 FCL in canonical layout. Every non-standard construct is listed on stderr "
                + "with its place and how it converted: exactly, approximated (with the largest membership error) "
                + "or not expressible. Curves are approximated only when --approximate-points is given; a construct "
                + "that is not expressible makes the conversion refused unless --allow-lossy is given. With --to "
                + "and a library's format the program is written in that library's layout instead: what the "
                + "library cannot say is listed (FCL-X1nn), what it is known to compute otherwise too (FCL-X2nn), and "
                + "the written text is read back with fclcert's reader of that dialect and evaluated against the "
                + "original on a grid.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {"0:the program converted (exactly, or with --allow-lossy)",
            "1:the program has errors, or a construct is not expressible (or the written program evaluates"
                + " differently) and --allow-lossy was not given",
            ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE})
final class ConvertCommand implements Callable<Integer> {
    /** What {@code --to} takes: strict and every format with a writer ({@link DialectWriters#libraries()}). */
    static final class Targets implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            List<String> names = new java.util.ArrayList<>(List.of(Dialect.STRICT.cliName()));
            DialectWriters.libraries().forEach(d -> names.add(d.cliName()));
            return names.iterator();
        }
    }

    @Spec
    CommandSpec spec;

    @Option(names = "--from", defaultValue = "auto", paramLabel = "DIALECT",
            completionCandidates = DialectName.Names.class,
            description = "the format FILE is written in: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE})")
    DialectName from;

    @Option(names = "--to", defaultValue = "strict", paramLabel = "DIALECT",
            completionCandidates = ConvertCommand.Targets.class,
            description = "the layout to write: ${COMPLETION-CANDIDATES} (strict: standard FCL) (default: ${DEFAULT-VALUE})")
    DialectName to;

    @Option(names = "--approximate-points", defaultValue = "0", paramLabel = "N",
            description = "approximate curved membership functions by N points, 2 to 10000 (default: do not approximate)")
    int approximatePoints;

    @Option(names = "--allow-lossy", description = "write the result even when it does not mean exactly the same")
    boolean allowLossy;

    @Option(names = "--out", paramLabel = "FILE", description = "write the program here instead of stdout")
    String outFile;

    @Parameters(paramLabel = "FILE", description = "an FCL source file, or - for standard input")
    String file;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (approximatePoints != 0 && approximatePoints < 2) {
            err.println("fclcert: --approximate-points must be at least 2 (got " + approximatePoints + ")");
            return ExitCodes.USAGE;
        }
        if (approximatePoints > StandardConversion.Options.MAX_APPROXIMATE_POINTS) {
            err.println("fclcert: --approximate-points must be at most " + StandardConversion.Options.MAX_APPROXIMATE_POINTS
                    + " (got " + approximatePoints + ")");
            return ExitCodes.USAGE;
        }
        try {
            CheckedSource source = CheckedSource.read(file, from, "converted", err);
            if (source.program().isEmpty()) {
                return ExitCodes.ERRORS;
            }
            Dialect dialect = source.dialect();
            if (to.auto() || !to.is(Dialect.STRICT) && !DialectWriters.libraries().contains(to.dialect().get())) {
                err.println("fclcert: --to takes " + String.join(", ", new Targets()) + ", not "
                        + to.dialect().map(Dialect::cliName).orElse("auto"));
                return ExitCodes.USAGE;
            }
            if (!to.is(Dialect.STRICT)) {
                return toLibrary(source, to.dialect().get(), out, err);
            }
            StandardConversion.Result result = new StandardConversion()
                    .convert(source.program().get(), new StandardConversion.Options(approximatePoints));
            printFindings(err, result.findings(), allowLossy);
            String standard = new CanonicalWriter().write(result.program());
            Analysis back = Analysis.analyze(new StrictReader(), SourceFiles.name(file) + " (converted)",
                    standard);
            if (back.hasErrors()) {
                err.println("fclcert: internal error: the converted program is not valid standard FCL: "
                        + back.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow());
                return ExitCodes.INTERNAL;
            }
            err.println("fclcert: " + summary(dialect, result));
            if (!result.expressible() && !allowLossy) {
                err.println("fclcert: " + SourceFiles.name(file) + " not converted: standard FCL cannot say exactly what it says;"
                        + " add --allow-lossy to write the nearest standard program anyway");
                return ExitCodes.ERRORS;
            }
            commentsLeftOut(err, source.program().get().comments().size() - result.program().comments().size(),
                    "a program whose constructs were converted");
            if (outFile != null) {
                SourceFiles.write(outFile, standard);
                err.println("fclcert: wrote " + outFile);
            } else {
                out.print(standard);
                out.flush();
            }
            return ExitCodes.OK;
        } catch (FileProblem e) {
            err.println("fclcert: " + e.getMessage());
            return ExitCodes.USAGE;
        }
    }

    /**
     * The program read (in whatever dialect) written in a library's layout, its losses and the library's known
     * deviations listed, and the written text read back and compared on a grid.
     */
    private int toLibrary(CheckedSource source, Dialect target, PrintWriter out, PrintWriter err) throws FileProblem {
        Written written = DialectWriters.writer(target).write(source.program().get());
        for (Diagnostic d : written.notExpressible()) {
            err.println(allowLossy ? Diagnostic.warning(d.location(), d.diagnosticCode(), d.message()) : d);
        }
        written.differences().forEach(err::println);
        RoundTrip back = DialectWriters.readBackAndCompare(source.program().get(), written);
        err.println("fclcert: written for " + target.displayName() + ": " + DiagnosticPrinter.count(
                written.notExpressible().size(), "construct") + " not expressible, " + DiagnosticPrinter.count(
                written.differences().size(), "known deviation") + " of " + target.displayName() + "; " + back.summary());
        back.mismatches().stream().skip(1).limit(2).forEach(m -> err.println("fclcert:   " + m));
        if (back.readBack().isEmpty() || written.exact() && !back.equal()) {
            err.println("fclcert: internal error: the " + target.cliName() + " writer's text "
                    + (back.readBack().isEmpty() ? "does not read back" : "is said to be exact but evaluates otherwise"));
            back.diagnostics().stream().filter(Diagnostic::isError).limit(5).forEach(d -> err.println("  " + d));
            return ExitCodes.INTERNAL;
        }
        if ((!written.exact() || !back.equal()) && !allowLossy) {
            err.println("fclcert: " + SourceFiles.name(file) + " not converted: " + target.displayName() + " cannot say exactly what it"
                    + " says; add --allow-lossy to write the nearest " + target.displayName() + " program anyway");
            return ExitCodes.ERRORS;
        }
        commentsLeftOut(err, source.program().get().comments().size(), target.displayName() + "'s text");
        if (outFile != null) {
            SourceFiles.write(outFile, written.text());
            err.println("fclcert: wrote " + outFile);
        } else {
            out.print(written.text());
            out.flush();
        }
        return ExitCodes.OK;
    }

    /** Says how many comments the written text leaves out, so that none is lost unsaid (the writers write none). */
    private void commentsLeftOut(PrintWriter err, int lost, String where) {
        if (lost > 0) {
            err.println("fclcert: note: " + DiagnosticPrinter.count(lost, "comment") + " of " + SourceFiles.name(file)
                    + " not written: fclcert writes no comments into " + where);
        }
    }

    /** One located line per finding: exact ones as notes, the others as diagnostics (FCL-X001, FCL-X002). */
    static void printFindings(PrintWriter err, List<Finding> findings, boolean lossyAllowed) {
        for (Finding f : findings) {
            f.diagnostic(lossyAllowed).ifPresentOrElse(err::println,
                    () -> err.println(f.location() + ": note " + f.construct() + ": converted exactly: " + f.message()));
        }
    }

    static String summary(Dialect dialect, StandardConversion.Result result) {
        long exact = result.findings().stream().filter(f -> f.kind() instanceof Kind.Exact).count();
        long approximated = result.findings().stream().filter(f -> f.kind() instanceof Kind.Approximated).count();
        long lost = result.findings().size() - exact - approximated;
        return "converted from " + dialect.displayName() + ": " + DiagnosticPrinter.count(result.findings().size(),
                "non-standard construct") + ", " + exact + " exact, " + approximated + " approximated, " + lost
                + " not expressible";
    }
}
