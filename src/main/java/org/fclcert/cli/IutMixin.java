package org.fclcert.cli;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.orchestration.Defaults;
import org.fclcert.sandbox.Limits;
import org.fclcert.sandbox.SandboxSettings;
import picocli.CommandLine.Option;

/** The options that name and open the implementation under test, shared by {@code certify}, {@code probe} and {@code fuzz}. */
final class IutMixin {
    @Option(names = "--iut", paramLabel = "SPEC", defaultValue = "reference",
            completionCandidates = IutSpecs.class,
            description = "${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE})")
    String spec;

    @Option(names = "--classpath", paramLabel = "PATHS",
            description = "Where java:CLASS is found (jars or directories, separated as the platform's class path)")
    String classpath;

    @Option(names = "--timeout", paramLabel = "DURATION", defaultValue = Defaults.TIMEOUT,
            converter = DurationConverter.class,
            description = "Per-request timeout for the implementation, e.g. 5s, 500ms (default: ${DEFAULT-VALUE})")
    Duration timeout;

    @Option(names = "--in-process",
            description = "Call a java:CLASS implementation inside fclcert's own JVM (faster; not isolated, the reports"
                    + " say so) instead of in a child JVM in the sandbox")
    boolean inProcess;

    @Option(names = "--no-sandbox",
            description = "Run the implementation as a plain process of yours, without the bubblewrap sandbox"
                    + " (the reports say so)")
    boolean noSandbox;

    @Option(names = "--sandbox-memory", paramLabel = "SIZE", converter = SizeConverter.class,
            description = "Memory each sandboxed process may write to, e.g. 2g, 512m (default: 2g)")
    Long sandboxMemory;

    @Option(names = "--sandbox-processes", paramLabel = "N", converter = PositiveCount.class,
            description = "Processes and threads the sandboxed implementation may have at once (default: "
                    + Limits.DEFAULT_PROCESSES + ")")
    Integer sandboxProcesses;

    @Option(names = "--sandbox-file-size", paramLabel = "SIZE", converter = SizeConverter.class,
            description = "Largest file the sandboxed implementation may write, also the size of its private /tmp"
                    + " and working directory (default: 256m)")
    Long sandboxFileSize;

    @Option(names = "--sandbox-cpu", paramLabel = "DURATION", converter = DurationConverter.class,
            description = "CPU time the sandboxed implementation may spend on one request, all its processes"
                    + " together (default: 30s)")
    Duration sandboxCpu;

    @Option(names = "--sandbox-bind", paramLabel = "PATH",
            description = "A further file or directory the sandboxed implementation may read (a model, a"
                    + " licence), bound read-only at its own path; repeatable")
    List<Path> sandboxBind = new ArrayList<>();

    /** A count of at least 1. */
    static final class PositiveCount implements picocli.CommandLine.ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            try {
                int n = Integer.parseInt(value.strip());
                if (n >= 1) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // reported below
            }
            throw new picocli.CommandLine.TypeConversionException("'" + value + "' is not a count of at least 1");
        }
    }

    /** {@code --iut}'s specs for picocli's help text and completion, drawn from {@link Iuts#KINDS}. */
    static final class IutSpecs implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return Iuts.syntaxes().iterator();
        }
    }

    /** The options for opening the implementation: the timeout, the --classpath and the sandbox. */
    IutOptions options() {
        return IutArguments.options(timeout, classpath).withSandbox(sandbox()).withInProcess(inProcess);
    }

    /** The sandbox settings the options ask for (defaults where an option is not given). */
    SandboxSettings sandbox() {
        Limits limits = Limits.defaults();
        if (sandboxMemory != null) {
            limits = limits.withMemoryBytes(sandboxMemory);
        }
        if (sandboxProcesses != null) {
            limits = limits.withProcesses(sandboxProcesses);
        }
        if (sandboxFileSize != null) {
            limits = limits.withFileSizeBytes(sandboxFileSize);
        }
        if (sandboxCpu != null) {
            limits = limits.withCpuPerRequest(sandboxCpu);
        }
        SandboxSettings settings = noSandbox ? SandboxSettings.none() : SandboxSettings.defaults();
        return settings.withLimits(limits).withReadOnly(sandboxBind);
    }
}
