package org.fclcert.cli;

import java.time.Duration;
import org.fclcert.iut.IutOptions;
import org.fclcert.orchestration.Defaults;
import picocli.CommandLine.Option;

/** The options that name and open the implementation under test, shared by {@code certify}, {@code probe} and {@code fuzz}. */
final class IutMixin {
    @Option(names = "--iut", paramLabel = "SPEC", defaultValue = "reference",
            description = "reference | java:CLASS | process:COMMAND | fuzzylite[:PATH] | jfuzzylite[:JAR] | jfuzzylogic:JAR | ffll[:LIBRARY]"
                    + " (default: ${DEFAULT-VALUE})")
    String spec;

    @Option(names = "--classpath", paramLabel = "PATHS",
            description = "Where java:CLASS is found (jars or directories, separated as the platform's class path)")
    String classpath;

    @Option(names = "--timeout", paramLabel = "DURATION", defaultValue = Defaults.TIMEOUT,
            converter = DurationConverter.class,
            description = "Per-request timeout for the implementation, e.g. 5s, 500ms (default: ${DEFAULT-VALUE})")
    Duration timeout;

    /** The options for opening the implementation: the timeout and the --classpath. */
    IutOptions options() {
        return IutArguments.options(timeout, classpath);
    }
}
