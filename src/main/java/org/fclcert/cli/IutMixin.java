package org.fclcert.cli;

import java.time.Duration;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.orchestration.Defaults;
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

    /** {@code --iut}'s specs for picocli's help text and completion, drawn from {@link Iuts#KINDS}. */
    static final class IutSpecs implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return Iuts.syntaxes().iterator();
        }
    }

    /** The options for opening the implementation: the timeout and the --classpath. */
    IutOptions options() {
        return IutArguments.options(timeout, classpath);
    }
}
