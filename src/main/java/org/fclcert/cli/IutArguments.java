package org.fclcert.cli;

import java.io.File;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;

/** What {@code certify} and {@code probe} share in opening the implementation their --iut names. */
final class IutArguments {
    private IutArguments() {
    }

    /** The IUT options for a request timeout and a --classpath (platform path separator; null for none). */
    static IutOptions options(Duration requestTimeout, String classpath) {
        IutOptions options = IutOptions.defaults().withTimeout(requestTimeout);
        if (classpath != null) {
            options = options.withClasspath(Arrays.stream(classpath.split(File.pathSeparator))
                    .filter(s -> !s.isBlank()).map(Path::of).toList());
        }
        return options;
    }

    /** The end of the implementation's standard error to append to a message about e; empty when it wrote none. */
    static String stderrTail(IutException e) {
        String tail = e.stderrTail();
        return tail == null || tail.isBlank() ? "" : "\n--- its stderr ---\n" + TerminalText.visibleLines(tail.strip());
    }
}
