package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.StopSignal;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.orchestration.Defaults;
import org.fclcert.orchestration.OutputDirectory;
import org.fclcert.probe.Prober;
import org.fclcert.probe.Table11;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert probe}: measures the Table 11 data check list of an implementation and prints it. */
@Command(name = "probe", mixinStandardHelpOptions = true,
        description = {"Measure the Table 11 data check list (clause 6.2) of an implementation under test with "
                + "generated programs judged by the reference evaluator, and print it.",
            "The probe ends at --budget: the row under way keeps what it established, the rows after it are not"
                    + " measured. Ctrl-C ends it the same way and shows what was measured.",
            "Exit 0: measured; 2: the implementation could not be probed or an option is wrong."})
final class ProbeCommand implements Callable<Integer> {
    static final String FILE = "data-check-list.json";

    @Spec
    CommandSpec spec;

    @Mixin
    IutMixin iut;

    @Option(names = "--out", paramLabel = "DIR", description = "Also write the list to DIR/" + FILE)
    Path out;

    @Option(names = "--cap", paramLabel = "N", defaultValue = Defaults.PROBE_CAP_TEXT,
            description = "Largest size probed for each limit (default: ${DEFAULT-VALUE})")
    long cap;

    @Option(names = "--budget", paramLabel = "DURATION", defaultValue = Defaults.PROBE_BUDGET,
            converter = DurationConverter.class,
            description = "Time for the whole probe, e.g. 3m, 90s; the probe ends there (default: ${DEFAULT-VALUE})")
    Duration budget;

    @Option(names = "--format", paramLabel = "FORMAT", defaultValue = "text", description = "text | json")
    OutputFormat format;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        if (cap < 1) {
            err.println("fclcert probe: --cap must be at least 1");
            err.flush();
            return ExitCodes.USAGE;
        }
        // a second probe into the same --out refuses at once, naming the first (as certify does)
        OutputDirectory.Lock lock = null;
        if (out != null) {
            try {
                lock = OutputDirectory.lock(out);
            } catch (OutputDirectory.InUse e) {
                err.println("fclcert probe: " + TerminalText.visibleLines(e.getMessage()));
                err.flush();
                return ExitCodes.USAGE;
            }
        }
        try (OutputDirectory.Lock held = lock) {
            return probe(stdout, err);
        }
    }

    private int probe(PrintWriter stdout, PrintWriter err) {
        IutOptions options = iut.options();
        StopSignal stop = new StopSignal();
        List<DataCheckEntry> measured = Collections.synchronizedList(new ArrayList<>());
        AtomicBoolean shown = new AtomicBoolean();
        CountDownLatch done = new CountDownLatch(1);
        Thread onSignal = new Thread(() -> interrupted(stop, done, measured, shown, stdout, err), "fclcert-interrupted");
        Runtime.getRuntime().addShutdownHook(onSignal);
        EarlySignals.handledByCommand();
        try {
            List<DataCheckEntry> entries;
            try {
                entries = Prober.probe(() -> Iuts.open(iut.spec, options), new Prober.Options(cap, budget, Set.of()),
                        new Prober.Listener() {
                            @Override
                            public void row(Table11 row, int index, int count) {
                                progress(err, row.id(), index, count);
                            }

                            @Override
                            public void measured(DataCheckEntry entry) {
                                measured.add(entry);
                            }
                        }, stop);
            } catch (IutException e) {
                clearProgress(err);
                err.println("fclcert probe: cannot probe '" + iut.spec + "': " + TerminalText.visible(e.getMessage()) + IutArguments.stderrTail(e));
                err.flush();
                return ExitCodes.USAGE;
            }
            clearProgress(err);
            if (!shown.compareAndSet(false, true)) {
                return ExitCodes.OK;   // the shutdown hook gave up waiting and showed what was measured
            }
            int exit = show(entries, stdout, err);
            if (stop.stopped()) {
                err.println("fclcert probe: stopped (" + stop.reason() + ") after " + measuredRows(entries) + " of "
                        + entries.size() + " rows; the others are not measured");
                err.flush();
            }
            return exit;
        } finally {
            done.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(onSignal);
            } catch (IllegalStateException shuttingDown) {
                // the hook is running: it waits for 'done'
            }
        }
    }

    private static long measuredRows(List<DataCheckEntry> entries) {
        return entries.stream().filter(e -> !e.bound().equals(DataCheckEntry.NOT_MEASURED)).count();
    }

    /** Prints the list and writes it to --out; the exit code. */
    private int show(List<DataCheckEntry> entries, PrintWriter stdout, PrintWriter err) {
        if (format == OutputFormat.json) {
            stdout.println(DataCheckPrinter.json(entries));
            stdout.flush();
        } else {
            DataCheckPrinter.text(stdout, entries);
        }
        if (out != null) {
            try {
                Files.createDirectories(out);
                Files.writeString(out.resolve(FILE), DataCheckPrinter.json(entries) + "\n", StandardCharsets.UTF_8);
            } catch (IOException e) {
                err.println("fclcert probe: cannot write " + out.resolve(FILE) + ": " + e.getMessage());
                err.flush();
                return ExitCodes.USAGE;
            }
        }
        return ExitCodes.OK;
    }

    /**
     * Ctrl-C or a kill during the probe (a shutdown hook): the probe is stopped, ends the row under way, closes the
     * implementation and shows what it measured, on its own thread; this waits for that, since the JVM ends when
     * its hooks do. An implementation deaf to the stop for {@link Defaults#STOP_GRACE} is killed from here, and the
     * rows measured so far are shown.
     */
    private void interrupted(StopSignal stop, CountDownLatch done, List<DataCheckEntry> measured, AtomicBoolean shown,
            PrintWriter stdout, PrintWriter err) {
        stop.stop(StopSignal.INTERRUPTED);
        try {
            if (done.await(Defaults.STOP_GRACE.toMillis(), TimeUnit.MILLISECONDS)) {
                return;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        stop.closeAll();
        if (!shown.compareAndSet(false, true)) {
            return;
        }
        List<DataCheckEntry> rows = new ArrayList<>(List.copyOf(measured));
        List<DataCheckEntry> all = Prober.notMeasured("not measured: the probe was stopped: " + StopSignal.INTERRUPTED);
        rows.addAll(all.subList(Math.min(rows.size(), all.size()), all.size()));
        clearProgress(err);
        show(rows, stdout, err);
        err.println("fclcert probe: interrupted; the implementation did not stop within "
                + Defaults.STOP_GRACE.toSeconds() + " s and was killed; " + measuredRows(rows) + " of " + rows.size()
                + " rows were measured");
        err.flush();
    }

    private static void progress(PrintWriter err, String id, int index, int count) {
        if (System.console() != null) {
            err.print("\r\u001b[Kprobing " + index + "/" + count + ": " + id);
            err.flush();
        }
    }

    private static void clearProgress(PrintWriter err) {
        if (System.console() != null) {
            err.print("\r\u001b[K");
            err.flush();
        }
    }
}
