package org.fclcert.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fclcert.corpus.CorpusLint;
import org.fclcert.corpus.CorpusProblem;
import org.fclcert.corpus.LintReport;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code fclcert corpus ...}: commands about the conformance corpus. */
@Command(
        name = "corpus",
        description = "Work with the conformance corpus (conformance/).",
        mixinStandardHelpOptions = true,
        subcommands = {CorpusCommand.Lint.class})
public final class CorpusCommand implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /** {@code fclcert corpus lint [DIR]}: exit 0 clean, 1 findings, 2 bad usage. */
    @Command(
            name = "lint",
            description = {
                "Check every case of the corpus against the toolkit: metadata, ids, declared level and features "
                        + "(against the feature detector), expected errors of negative cases, expected outputs "
                        + "(against the reference evaluator), and coverage of Tables 8, 9 and 10.",
                "Exit status: 0 clean, 1 findings, 2 usage error."},
            mixinStandardHelpOptions = true)
    static final class Lint implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Parameters(index = "0", arity = "0..1", paramLabel = "DIR", description = "corpus directory (default: conformance)")
        Path dir = Path.of("conformance");

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            if (!Files.isDirectory(dir)) {
                err.println("fclcert corpus lint: " + dir + " is not a directory (give the corpus directory, e.g. conformance)");
                return 2;
            }
            LintReport report = new CorpusLint().lint(dir);
            for (CorpusProblem p : report.caseFindings()) {
                out.println(p);
            }
            for (String gap : report.coverageGaps()) {
                out.println(dir + ": coverage: " + gap);
            }
            int findings = report.caseFindings().size() + report.coverageGaps().size();
            out.println(report.cases() + " cases (" + report.positive() + " positive, " + report.negative()
                    + " negative): " + (findings == 0 ? "clean" : findings + " finding(s)"));
            out.flush();
            return findings == 0 ? 0 : 1;
        }
    }
}
