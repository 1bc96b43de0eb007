package org.fclcert.syntax.dialect;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

/** The FFLL sample programs of src/test/resources/org/fclcert/syntax/dialect/ffll, written for these tests. */
final class FfllSamples {
    /** Samples that read without error. */
    static final List<String> VALID = List.of("guard.fcl", "heater.fcl", "mixer.fcl");

    private FfllSamples() {
    }

    static String text(String name) {
        try (InputStream in = FfllSamples.class.getResourceAsStream("ffll/" + name)) {
            if (in == null) {
                throw new IllegalArgumentException("no sample " + name);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
