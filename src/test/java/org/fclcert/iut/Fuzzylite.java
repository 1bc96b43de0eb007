package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.time.Duration;

/**
 * Whether the real fuzzylite 6.0 command line is installed, for the tests that drive it. The build installs it
 * where it can ({@code scripts/ensure-fuzzylite}); in CI (the environment variable {@code CI} set) a missing
 * fuzzylite fails the tests loudly, elsewhere they are skipped with the reason.
 */
public final class Fuzzylite {
    private static Boolean installed;
    private static String why = "";

    private Fuzzylite() {}

    public static IutOptions options() {
        return IutOptions.defaults().withTimeout(Duration.ofSeconds(20));
    }

    public static synchronized void assumeInstalled() {
        if (installed == null) {
            try (ImplementationUnderTest iut = Iuts.open("fuzzylite", options())) {
                iut.hello();
                installed = true;
            } catch (IutException e) {
                installed = false;
                why = e.getMessage();
            }
        }
        if (!installed) {
            if (System.getenv("CI") != null) {
                fail("CI is set but fuzzylite cannot be run (scripts/ensure-fuzzylite should have installed it): " + why);
            }
            assumeTrue(false, "fuzzylite is not installed, so the tests that drive it are skipped "
                    + "(apt-get install fuzzylite, or run scripts/ensure-fuzzylite; with CI set they fail instead): " + why);
        }
    }
}
