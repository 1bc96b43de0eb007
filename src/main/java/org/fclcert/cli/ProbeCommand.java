package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.orchestration.Defaults;
import org.fclcert.probe.Prober;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert probe}: measures the Table 11 data check list of an implementation and prints it. */
@Command(name = "probe", mixinStandardHelpOptions = true,
        description = {"Measure the Table 11 data check list (clause 6.2) of an implementation under test with "
                + "generated programs judged by the reference evaluator, and print it.",
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
            description = "Time for the whole probe, e.g. 3m, 90s (default: ${DEFAULT-VALUE})")
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
        IutOptions options = iut.options();
        List<DataCheckEntry> entries;
        try {
            entries = Prober.probe(() -> Iuts.open(iut.spec, options), new Prober.Options(cap, budget, Set.of()),
                    (row, index, count) -> progress(err, row.id(), index, count));
        } catch (IutException e) {
            clearProgress(err);
            err.println("fclcert probe: cannot probe '" + iut.spec + "': " + TerminalText.visible(e.getMessage()) + IutArguments.stderrTail(e));
            err.flush();
            return ExitCodes.USAGE;
        }
        clearProgress(err);
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
