package org.fclcert.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code fclcert} command line: the only place that prints to the terminal or picks an exit code. */
@Command(
        name = "fclcert",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Conformance toolkit for IEC 61131-7 Fuzzy Control Language (FCL).",
        subcommands = {
            CommandLine.HelpCommand.class,
            CertifyCommand.class,
            ReportCommand.class,
        })
public final class Main implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** Runs the command line and returns its exit code (tests call this instead of {@link #main}). */
    public static int run(String... args) {
        return new CommandLine(new Main()).execute(args);
    }

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}
