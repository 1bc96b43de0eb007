package org.fclcert.check;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import org.fclcert.syntax.StrictReader;

/** Test programs from the resources next to this package, read with the strict reader. */
final class Programs {
    private Programs() {
    }

    /** The text of {@code src/test/resources/org/fclcert/check/<path>}. */
    static String text(String path) {
        try (InputStream in = Programs.class.getResourceAsStream(path)) {
            if (in == null) {
                throw new IllegalArgumentException("no test resource " + path);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static Analysis analyze(String name, String text) {
        return Analysis.analyze(new StrictReader(), name, text);
    }

    static Analysis analyzeResource(String path) {
        return analyze(path, text(path));
    }
}
