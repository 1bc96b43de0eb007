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
        versionProvider = VersionProvider.class,
        subcommands = {CorpusCommand.Lint.class, CorpusCommand.Add.class})
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
            mixinStandardHelpOptions = true,
            versionProvider = VersionProvider.class)
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

    /** {@code fclcert corpus add FILE [--corpus DIR]}: exit 0 added, 1 the lint found problems in the case, 2 bad usage. */
    @Command(
            name = "add",
            description = {
                "Add a case file (e.g. one written by fclcert fuzz) to the corpus: give it the next free id of its "
                        + "prefix, place it in the directory of its level and lint it with the corpus; a case with "
                        + "lint findings is not added.",
                "Exit status: 0 added, 1 lint findings in the case (not added), 2 usage error."},
            mixinStandardHelpOptions = true,
            versionProvider = VersionProvider.class)
    static final class Add implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Parameters(index = "0", paramLabel = "FILE", description = "the case file to add")
        Path file;

        @CommandLine.Option(names = "--corpus", paramLabel = "DIR", description = "corpus directory (default: conformance)")
        Path dir = Path.of("conformance");

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            if (!Files.isDirectory(dir)) {
                err.println("fclcert corpus add: " + dir + " is not a directory (give the corpus directory, e.g. conformance)");
                return 2;
            }
            if (!Files.isRegularFile(file)) {
                err.println("fclcert corpus add: " + file + " is not a file");
                return 2;
            }
            try {
                org.fclcert.corpus.CorpusAdd.Outcome o = org.fclcert.corpus.CorpusAdd.add(dir, file);
                if (o.placed().isEmpty()) {
                    o.findings().forEach(out::println);
                    out.println(file + ": not added: " + o.findings().size() + " lint finding(s) as " + o.id());
                    out.flush();
                    return 1;
                }
                out.println(file + ": added as " + o.placed().get() + " (lint clean)");
                out.flush();
                return 0;
            } catch (org.fclcert.corpus.CorpusAdd.NotACase e) {
                err.println("fclcert corpus add: " + e.getMessage());
                return 2;
            } catch (java.io.IOException e) {
                err.println("fclcert corpus add: " + e.getMessage());
                return 2;
            }
        }
    }
}
