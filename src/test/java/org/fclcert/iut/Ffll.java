package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Where the unmodified FFLL 2.2.1 build is, for the tests that drive it: as {@code --iut ffll} finds it
 * ({@code FCLCERT_FFLL}, {@code -Dfclcert.ffll}, else {@code shared/peers/ffll} in the working directory or a parent:
 * {@code ../shared/peers/ffll} beside the clone, as in CI). It needs g++ to build fclcert's bridge. In CI
 * (environment variable {@code CI} set) a missing library or compiler fails the tests; elsewhere they are skipped
 * with the reason.
 */
public final class Ffll {
    private Ffll() {}

    /** The library, or the test is skipped (outside CI) or fails (in CI). */
    public static Path assumeLibrary() {
        Optional<Path> library = FfllIut.defaultLibrary();
        String why = library.isEmpty() ? "no libffll*.so in shared/peers/ffll above " + Path.of("").toAbsolutePath()
                + " (nor in " + FfllIut.ENVIRONMENT + ")" : !gpp() ? "g++ is not installed (the bridge is compiled with it)" : null;
        if (why != null) {
            if (System.getenv("CI") != null) {
                fail("CI is set but FFLL cannot be driven: " + why);
            }
            assumeTrue(false, "FFLL is not available, so the tests that drive it are skipped (" + why
                    + "; with CI set they fail instead)");
        }
        return library.get();
    }

    private static boolean gpp() {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, "g++"))) {
                return true;
            }
        }
        return false;
    }
}
