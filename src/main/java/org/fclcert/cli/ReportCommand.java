package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fclcert.harness.ResultsFile;
import java.util.List;
import org.fclcert.report.ReportFiles;
import org.fclcert.report.ReportVerifier;
import org.fclcert.report.Report;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert report}: rebuilds every report from a (possibly partial) {@code results.jsonl}. */
@Command(name = "report", mixinStandardHelpOptions = true,
        description = {"Rebuild report.json, report.md, report.html and junit.xml from a results.jsonl "
                + "written by 'fclcert certify' (also one cut short: cases not run are reported as skipped). Every"
                + " verdict is recomputed by judging each case line's recorded replies again against the corpus and"
                + " the run's fresh vectors (regenerated from its seed); the hash chain and the corpus digest are"
                + " checked. With --verify DIR: check that the results and the four reports in DIR are one"
                + " consistent run, writing nothing.",
            "Exit 0 when the reports were written (or DIR holds up), 1 when the results or reports are inconsistent"
                + " (the first inconsistency is named), 2 when the results file cannot be used."})
final class ReportCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--from", paramLabel = "FILE", description = "The results.jsonl to read")
    Path from;

    @Option(names = "--verify", paramLabel = "DIR", description = "Check the results.jsonl and the four reports of"
            + " DIR: one run, the chain intact, the corpus the run's, every verdict what the evidence gives")
    Path verify;

    @Option(names = "--corpus", paramLabel = "DIR", description = "The run's corpus (default: the directory the run"
            + " header names, else the built-in corpus); its sha256 must be the run's")
    Path corpus;

    @Option(names = "--out", paramLabel = "DIR", description = "Output directory (default: the results file's)")
    Path out;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        if (verify != null) {
            return verify(err);
        }
        if (from == null) {
            return cannot(err, "give --from FILE (a results.jsonl) or --verify DIR");
        }
        if (!Files.exists(from)) {
            return cannot(err, from + ": no such file");
        }
        Path dir = out != null ? out : from.getParent() != null ? from.getParent() : Path.of(".");
        ReportVerifier.Rebuilt rebuilt;
        try {
            rebuilt = ReportVerifier.rebuild(from, corpus, java.time.Instant.now());
        } catch (ResultsFile.InvalidResultsException e) {
            return cannot(err, e.getMessage());
        } catch (IOException e) {
            return cannot(err, "cannot read " + from + ": " + e.getMessage());
        }
        if (!rebuilt.consistent()) {
            return inconsistent(err, from.toString(), rebuilt.inconsistencies());
        }
        try {
            rebuilt.report().run().problems().forEach(p -> err.println("warning: " + TerminalText.visible(p)));
            rebuilt.notes().forEach(p -> err.println("warning: " + TerminalText.visible(p)));
            Report report = rebuilt.report();
            ReportFiles.writeAll(report, dir);
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

    private int verify(PrintWriter err) {
        if (!Files.isDirectory(verify)) {
            return cannot(err, verify + ": no such directory");
        }
        try {
            List<String> problems = ReportVerifier.verify(verify, corpus);
            if (!problems.isEmpty()) {
                return inconsistent(err, verify.toString(), problems);
            }
        } catch (IOException e) {
            return cannot(err, "cannot read " + verify + ": " + e.getMessage());
        }
        PrintWriter o = spec.commandLine().getOut();
        o.println(verify + ": consistent: the results chain is intact, the corpus is the run's, every verdict is what"
                + " the recorded evidence gives, and the four reports are what the results give (a digest shows"
                + " consistency, not authorship: rerun with the seed to see the results again)");
        o.flush();
        return CertifyCommand.OK;
    }

    /** Names the first inconsistency (and how many more), exit 1. */
    private static int inconsistent(PrintWriter err, String what, List<String> problems) {
        err.println("fclcert report: " + TerminalText.visible(what) + " is inconsistent: "
                + TerminalText.visible(problems.get(0)));
        problems.stream().skip(1).limit(9).forEach(p -> err.println("  also: " + TerminalText.visible(p)));
        if (problems.size() > 10) {
            err.println("  … and " + (problems.size() - 10) + " more");
        }
        err.flush();
        return CertifyCommand.FAILED;
    }

    private static int cannot(PrintWriter err, String message) {
        err.println("fclcert report: " + message);
        err.flush();
        return CertifyCommand.CANNOT_RUN;
    }
}
