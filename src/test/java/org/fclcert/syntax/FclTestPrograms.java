package org.fclcert.syntax;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

/** The FCL programs kept as test resources (written from the standard's figures and by hand). */
final class FclTestPrograms {
    static final List<String> ALL = List.of(
            "figure7_valve.fcl", "annexC_crane.fcl", "annexD_oven.fcl", "every_construct.fcl");

    private FclTestPrograms() {
    }

    static String text(String name) {
        try (InputStream in = FclTestPrograms.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalArgumentException("no test resource " + name);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
