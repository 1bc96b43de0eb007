package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fclcert.fuzz.FuzzReport;
import org.fclcert.fuzz.FuzzSettings;
import org.fclcert.fuzz.Fuzzer;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.StopSignal;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.orchestration.Defaults;
import org.fclcert.orchestration.OutputDirectory;
import org.fclcert.orchestration.PresentAs;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert fuzz}: differential testing of an implementation against the reference on generated programs. */
@Command(name = "fuzz", mixinStandardHelpOptions = true,
        description = {"Generate random valid FCL programs with fair input vectors, run them on the implementation "
                + "and on the reference evaluator, and shrink every disagreement to a minimal corpus case in --out "
                + "(with fuzz.json and fuzz.md).",
            "Exit 0: nothing found; 1: findings; 2: the run could not be done."})
final class FuzzCommand implements Callable<Integer> {
    static final int NOTHING_FOUND = ExitCodes.OK;
    static final int FOUND = ExitCodes.ERRORS;
    static final int CANNOT_RUN = ExitCodes.USAGE;

    @Spec
    CommandSpec spec;

    @Mixin
    IutMixin iutOptions;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1", description = "Seed of the run (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--budget", paramLabel = "DURATION", defaultValue = "1m",
            description = "How long to generate programs, e.g. 30s, 10m (default: ${DEFAULT-VALUE})")
    String budget;

    @Option(names = "--programs", paramLabel = "N", defaultValue = "0",
            description = "Stop after N programs (0: only the budget stops the run); with --jobs 1 a seed and N give the same run")
    long programs;

    @Option(names = "--max-findings", paramLabel = "N", defaultValue = "0",
            description = "Stop once N distinct findings are known (0: no limit)")
    int maxFindings;

    @Option(names = "--level", paramLabel = "LEVEL", defaultValue = "open",
            description = "Highest level of the features used: basic, extension or open (default: ${DEFAULT-VALUE})")
    String level;

    @Option(names = "--feature", paramLabel = "ID", arity = "1..*",
            description = "Favour these feature ids (e.g. E-ACCU-NSUM): most programs use them")
    List<String> features = new ArrayList<>();

    @Option(names = "--jobs", paramLabel = "N", defaultValue = "1",
            description = "Parallel jobs, each with its own implementation session (default: ${DEFAULT-VALUE})")
    int jobs;

    @Option(names = "--present-as", paramLabel = "LAYOUT", defaultValue = "auto",
            completionCandidates = PresentAsNames.class,
            description = "${COMPLETION-CANDIDATES}: send each program written in that library's"
                    + " layout, when fclcert can vouch for the text, else skip it with the reason counted (default:"
                    + " ${DEFAULT-VALUE}: the built-in library adapters in their library's layout, standard FCL for"
                    + " reference, java: and process:)")
    PresentAs presentAs;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "fuzz-out",
            description = "Where the case files, fuzz.json and fuzz.md go (default: ${DEFAULT-VALUE})")
    Path out;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        Duration total = Durations.parse(budget).orElse(null);
        if (total == null) {
            return usage(err, "--budget: '" + budget + "' is not a duration (write e.g. 30s, 10m)");
        }
        // Fuzzing the reference against itself finds nothing: unlike certify, fuzz wants --iut named.
        if (!spec.commandLine().getParseResult().hasMatchedOption("--iut")) {
            return usage(err, "Missing required option: '--iut=SPEC'");
        }
        String iut = iutOptions.spec;
        if (jobs < 1 || jobs > 64) {
            return usage(err, "--jobs must be between 1 and 64, not " + jobs);
        }
        if (programs < 0) {
            return usage(err, "--programs must not be negative");
        }
        ConformanceLevel lvl;
        try {
            lvl = ConformanceLevel.byWord(level.trim());
        } catch (IllegalArgumentException e) {
            return usage(err, "--level: '" + level + "' is not one of basic, extension, open");
        }
        Set<Feature> focus = EnumSet.noneOf(Feature.class);
        for (String id : features) {
            Feature f = Feature.byId(id.toUpperCase(Locale.ROOT)).orElse(null);
            if (f == null || f.dialectSyntax()) {
                return usage(err, "--feature: '" + id + "' is not a feature the generator can use (ids: "
                        + String.join(" ", FuzzSettings.generatable().stream().map(Feature::id).toList()) + ")");
            }
            if (f.level().compareTo(lvl) > 0) {
                return usage(err, "--feature: " + f.id() + " is above --level " + lvl.word());
            }
            focus.add(f);
        }
        // a second fuzz run into the same --out refuses at once, naming the first (as certify does)
        try (OutputDirectory.Lock held = OutputDirectory.lock(out)) {
            return fuzz(stdout, err, iut, total, lvl, focus);
        } catch (OutputDirectory.InUse e) {
            return usage(err, TerminalText.visibleLines(e.getMessage()));
        }
    }

    private int fuzz(PrintWriter stdout, PrintWriter err, String iut, Duration total, ConformanceLevel lvl,
            Set<Feature> focus) {
        Fuzzer.Options run = Fuzzer.Options.of(seed, total, new FuzzSettings(lvl, focus), jobs).withMaxPrograms(programs)
                .withMaxFindings(Math.max(0, maxFindings)).withLayout(presentAs.resolve(iut));
        boolean terminal = System.console() != null;
        Fuzzer fuzzer = new Fuzzer();
        CountDownLatch printed = new CountDownLatch(1);
        Thread onSignal = new Thread(() -> interrupted(fuzzer, printed, err), "fclcert-interrupted");
        Runtime.getRuntime().addShutdownHook(onSignal);
        EarlySignals.handledByCommand();
        try {
            return fuzz(stdout, err, iut, fuzzer, run, terminal);
        } finally {
            printed.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(onSignal);
            } catch (IllegalStateException shuttingDown) {
                // the hook is running: it waits for 'printed'
            }
        }
    }

    /**
     * Ctrl-C or a kill during the run (a shutdown hook; the JVM ends when it returns): the fuzzer is stopped, and its
     * findings so far are written and the summary printed on the command's thread, which this waits for. An
     * implementation that does not answer within {@link Defaults#STOP_GRACE} has its sessions closed.
     */
    private static void interrupted(Fuzzer fuzzer, CountDownLatch printed, PrintWriter err) {
        fuzzer.stop(StopSignal.INTERRUPTED);
        try {
            if (printed.await(Defaults.STOP_GRACE.toMillis(), TimeUnit.MILLISECONDS)) {
                return;
            }
            fuzzer.abandon();
            if (printed.await(PRINT_GRACE.toMillis(), TimeUnit.MILLISECONDS)) {
                return;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        err.println("fclcert fuzz: " + StopSignal.INTERRUPTED + "; the run did not end in time, and its outputs were"
                + " not written");
        err.flush();
    }

    /** How long the shutdown hook waits, once the sessions are closed, for the outputs and the summary. */
    private static final Duration PRINT_GRACE = Duration.ofSeconds(10);

    private int fuzz(PrintWriter stdout, PrintWriter err, String iut, Fuzzer fuzzer, Fuzzer.Options run,
            boolean terminal) {
        IutOptions options = iutOptions.options();
        Fuzzer.Result result;
        try {
            result = fuzzer.run(() -> Iuts.open(iut, options), run, Duration.ofMillis(terminal ? 500 : 5000),
                    p -> progress(err, p, terminal));
        } catch (IutException e) {
            return usage(err, "cannot run " + iut + ": " + e.getMessage() + IutArguments.stderrTail(e));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return usage(err, "interrupted");
        }
        if (terminal) {
            err.print("\r\033[K");
            err.flush();
        }
        List<FuzzReport.Written> written;
        try {
            written = FuzzReport.write(result, out);
        } catch (IOException e) {
            return usage(err, "cannot write " + out + ": " + e.getMessage());
        }
        Fuzzer.Progress p = result.progress();
        stdout.printf(Locale.ROOT, "%s %s: %d programs, %d vectors in %.1f s (%.1f programs/s, %.1f vectors/s), %d finding(s)%n",
                result.iut().name(), result.iut().version(), p.programs(), p.vectors(), p.elapsedMillis() / 1000.0,
                p.programsPerSecond(), p.vectorsPerSecond(), written.size());
        stdout.printf(Locale.ROOT, "  time of the jobs: %.1f s reference side, %.1f s implementation, %.1f s on disagreements%n",
                p.referenceMillis() / 1000.0, p.implementationMillis() / 1000.0, p.shrinkMillis() / 1000.0);
        run.layout().ifPresent(l -> stdout.println("  sent in " + l.displayName() + "'s layout; " + p.notPresentable()
                + " generated program(s) not presentable" + (result.notPresentable().isEmpty() ? ""
                        : " (" + FuzzReport.reasons(result.notPresentable()) + ")")));
        for (FuzzReport.Written w : written) {
            stdout.println("  " + w.file() + ": " + w.finding().feature().id() + ", " + w.finding().kind().word() + ", "
                    + w.programLines() + " lines: " + w.finding().deviation().message());
        }
        stdout.println("Summary: " + out.resolve(FuzzReport.MARKDOWN) + ", " + FuzzReport.JSON);
        result.stopped().ifPresent(why -> err.println("fclcert fuzz: the run was stopped (" + why + ") after "
                + p.programs() + " programs; the findings up to then are written"));
        if (!result.generatorBugs().isEmpty()) {
            err.println("fclcert fuzz: internal error: " + result.generatorBugs().size() + " generated program(s) were not valid; first: "
                    + result.generatorBugs().get(0));
        }
        result.infrastructureErrors().forEach(e -> err.println("fclcert fuzz: " + e));
        result.presentationFaults().forEach(e -> err.println("fclcert fuzz: internal error: a written text fclcert"
                + " cannot vouch for, " + e.lines().findFirst().orElse("")));
        stdout.flush();
        err.flush();
        if (!written.isEmpty()) {
            return FOUND;
        }
        if (p.programs() == 0 || !result.infrastructureErrors().isEmpty() && written.isEmpty()) {
            err.println("fclcert fuzz: the run could not be done" + (p.programs() == 0 ? " (no program was run)" : ""));
            err.flush();
            return CANNOT_RUN;
        }
        return NOTHING_FOUND;
    }

    private static void progress(PrintWriter err, Fuzzer.Progress p, boolean terminal) {
        String line = String.format(Locale.ROOT, "%.0f s: %d programs, %d vectors, %d finding(s) (%.1f programs/s, %.1f vectors/s)",
                p.elapsedMillis() / 1000.0, p.programs(), p.vectors(), p.findings(), p.programsPerSecond(), p.vectorsPerSecond());
        if (terminal) {
            err.print("\r\033[K" + line);
        } else {
            err.println(line);
        }
        err.flush();
    }

    private static int usage(PrintWriter err, String message) {
        err.println("fclcert fuzz: " + message);
        err.flush();
        return CANNOT_RUN;
    }
}
