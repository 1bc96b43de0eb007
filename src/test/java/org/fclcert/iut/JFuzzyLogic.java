package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * Where the unmodified jFuzzyLogic build is, for the tests that drive it: {@code ../shared/peers/jfuzzylogic/}
 * beside the clone (as in CI), else {@code /work/shared/peers/jfuzzylogic/}. In CI (environment variable
 * {@code CI} set) a missing jar fails the tests; elsewhere they are skipped with the reason.
 */
public final class JFuzzyLogic {
    static final List<Path> PLACES = List.of(Path.of("").toAbsolutePath().resolve("../shared/peers/jfuzzylogic").normalize(),
            Path.of("/work/shared/peers/jfuzzylogic"));

    private JFuzzyLogic() {}

    /** The jar, when one of the places holds a {@code jFuzzyLogic*.jar}. */
    public static Optional<Path> jar() {
        for (Path dir : PLACES) {
            if (!Files.isDirectory(dir)) {
                continue;
            }
            try (Stream<Path> files = Files.list(dir)) {
                Optional<Path> jar = files.filter(p -> p.getFileName().toString().matches("jFuzzyLogic.*\\.jar"))
                        .sorted().findFirst();
                if (jar.isPresent()) {
                    return jar;
                }
            } catch (IOException e) {
                // try the next place
            }
        }
        return Optional.empty();
    }

    /** The jar, or the test is skipped (outside CI) or fails (in CI). */
    public static Path assumeJar() {
        Optional<Path> jar = jar();
        if (jar.isEmpty()) {
            String why = "no jFuzzyLogic*.jar in " + PLACES;
            if (System.getenv("CI") != null) {
                fail("CI is set but the jFuzzyLogic build is missing: " + why);
            }
            assumeTrue(false, "jFuzzyLogic is not available, so the tests that drive it are skipped (" + why
                    + "; with CI set they fail instead)");
        }
        return jar.get();
    }

    /** The spec {@code jfuzzylogic:JAR}. */
    public static String spec() {
        return "jfuzzylogic:" + assumeJar();
    }
}
