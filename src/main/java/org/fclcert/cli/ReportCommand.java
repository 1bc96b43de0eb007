package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fclcert.harness.ResultsFile;
import org.fclcert.orchestration.Certification;
import org.fclcert.report.Report;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert report}: rebuilds every report from a (possibly partial) {@code results.jsonl}. */
@Command(name = "report", mixinStandardHelpOptions = true,
        description = {"Rebuild report.json, report.md, report.html and junit.xml from a results.jsonl "
                + "written by 'fclcert certify' (also one cut short: cases not run are reported as skipped).",
            "Exit 0 when the reports were written, 2 when the results file cannot be used."})
final class ReportCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--from", paramLabel = "FILE", required = true, description = "The results.jsonl to read")
    Path from;

    @Option(names = "--out", paramLabel = "DIR", description = "Output directory (default: the results file's)")
    Path out;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        if (!Files.exists(from)) {
            return cannot(err, from + ": no such file");
        }
        Path dir = out != null ? out : from.getParent() != null ? from.getParent() : Path.of(".");
        ResultsFile results;
        try {
            results = ResultsFile.read(from);
        } catch (ResultsFile.InvalidResultsException e) {
            return cannot(err, e.getMessage());
        } catch (IOException e) {
            return cannot(err, "cannot read " + from + ": " + e.getMessage());
        }
        try {
            results.problems().forEach(p -> err.println("warning: " + TerminalText.visible(p)));
            Report report = Certification.rebuildReports(results, dir);
            PrintWriter o = spec.commandLine().getOut();
            o.println(report.summary().cases() + " cases (" + report.summary().passed() + " passed, "
                    + report.summary().skipped() + " skipped); Basic Level: "
                    + report.basicLevel().verdict());
            o.println("Reports written to " + dir);
            o.flush();
            err.flush();
            return CertifyCommand.OK;
        } catch (IOException e) {
            return cannot(err, "cannot write the reports in " + dir + ": " + e.getMessage());
        }
    }

    private static int cannot(PrintWriter err, String message) {
        err.println("fclcert report: " + message);
        err.flush();
        return CertifyCommand.CANNOT_RUN;
    }
}
