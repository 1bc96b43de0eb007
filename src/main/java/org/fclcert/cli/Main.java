package org.fclcert.cli;

import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import org.fclcert.orchestration.PresentAs;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code fclcert} command line: the only place that prints to the terminal or picks an exit code. */
@Command(
        name = "fclcert",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Conformance toolkit for IEC 61131-7 Fuzzy Control Language (FCL).",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {ExitCodes.SUCCESS_LINE, ExitCodes.ANY_FAILURE_LINE, ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE},
        subcommands = {
            CommandLine.HelpCommand.class,
            CheckCommand.class,
            FeaturesCommand.class,
            FmtCommand.class,
            ConvertCommand.class,
            CorpusCommand.class,
            CertifyCommand.class,
            ProbeCommand.class,
            ReportCommand.class,
            CompareCommand.class,
            EvalCommand.class,
            PlotCommand.class,
            FuzzCommand.class,
            LspCommand.class,
        })
public final class Main implements java.util.concurrent.Callable<Integer> {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        // first of all: a signal from here on ends fclcert with a message, never silently (issue 27)
        EarlySignals.install(System.err);
        int exit = run(args);
        EarlySignals.finished();
        System.exit(exit);
    }

    /** Runs the command line on the process's stdout and stderr and returns its exit code. */
    public static int run(String... args) {
        return run(stream(System.out), stream(System.err), args);
    }

    /** Runs the command line with the given output streams (tests capture them) and returns its exit code. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        try {
            return execute(commandLine(out, err), err, args);
        } finally {
            out.flush();
            err.flush();
        }
    }

    /** The configured command line (tests add commands to it to exercise the error handling). */
    static CommandLine commandLine(PrintWriter out, PrintWriter err) {
        CommandLine cli = new CommandLine(new Main());
        // enum options are typed (--fail-on, --level, --format) and written in lower case
        cli.setCaseInsensitiveEnumValuesAllowed(true);
        // the formats and layouts are drawn from their registries (Dialect, DialectWriters), not enums of cli's own
        cli.registerConverter(DialectName.class, new DialectName.Converter());
        cli.registerConverter(PresentAs.class, PresentAsNames::convert);
        cli.setOut(out);
        cli.setErr(err);
        cli.setExecutionStrategy(parsed -> {
            EarlySignals.commandStarted();
            return new CommandLine.RunLast().execute(parsed);
        });
        cli.setParameterExceptionHandler((e, args) -> {
            // one line saying what is wrong, and where the whole help is: the help itself buries the line
            err.println(e.getMessage());
            CommandLine.UnmatchedArgumentException.printSuggestions(e, err);
            err.println("Try '" + e.getCommandLine().getCommandSpec().qualifiedName() + " --help' for more information.");
            return ExitCodes.USAGE;
        });
        cli.setExecutionExceptionHandler((e, command, parsed) -> {
            // a bug must still not greet the user with a stack trace
            err.println("fclcert: internal error: " + describe(e));
            return ExitCodes.INTERNAL;
        });
        return cli;
    }

    /**
     * Stack of the thread every command runs on. Conditions may legally nest {@code Limits.MAX_NESTING_DEPTH}
     * deep (and an IUT's export may too); reading, checking, evaluating and writing them recurse once or a few
     * times per level, which overflows the JVM's default 1 MiB thread stack near depth 700. 512 MiB is address
     * space reserved, not memory used: pages are committed only as deep programs touch them.
     */
    static final long COMMAND_STACK_BYTES = 512L * 1024 * 1024;

    /**
     * Executes on a thread with {@link #COMMAND_STACK_BYTES} of stack (the one place the CLI's depth is set);
     * an Error (stack overflow, out of memory) bypasses picocli's handler, so it is caught here.
     */
    static int execute(CommandLine cli, PrintWriter err, String... args) {
        int[] exit = {ExitCodes.INTERNAL};
        Throwable[] thrown = {null};
        Thread worker = new Thread(null, () -> {
            try {
                exit[0] = cli.execute(args);
            } catch (Throwable e) {
                thrown[0] = e;
            }
        }, "fclcert", COMMAND_STACK_BYTES);
        worker.start();
        boolean interrupted = false;
        while (true) {
            try {
                worker.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (thrown[0] instanceof Error e) {
            err.println("fclcert: internal error: " + describe(e));
            return ExitCodes.INTERNAL;
        }
        if (thrown[0] instanceof RuntimeException e) {
            throw e;
        }
        return exit[0];
    }

    private static String describe(Throwable e) {
        return e.getMessage() != null ? e.getMessage() : e.getClass().getName();
    }

    private static PrintWriter stream(PrintStream s) {
        return new PrintWriter(new OutputStreamWriter(s, StandardCharsets.UTF_8), true);
    }

    /** No command given: a usage problem, so the usage goes to stderr and the exit code is 2. */
    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return ExitCodes.USAGE;
    }
}
