package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Whether pyfuzzylite can be driven, for the tests that drive it: as {@code --iut pyfuzzylite} finds its Python
 * ({@code FCLCERT_PYFUZZYLITE}, {@code -Dfclcert.pyfuzzylite}, else the virtual environment scripts/ensure-pyfuzzylite
 * makes, which the Maven build runs first). In CI (environment variable {@code CI} set) a missing one fails the tests;
 * elsewhere they are skipped with the reason.
 */
final class Pyfuzzylite {
    private Pyfuzzylite() {}

    static void assumeInstalled() {
        if (PyfuzzyliteIut.defaultPython().isPresent()) {
            return;
        }
        String why = "no Python with pyfuzzylite at " + PyfuzzyliteIut.environment() + " (scripts/ensure-pyfuzzylite"
                + " makes it) nor in " + PyfuzzyliteIut.ENVIRONMENT;
        if (System.getenv("CI") != null) {
            fail("CI is set but pyfuzzylite cannot be driven: " + why);
        }
        assumeTrue(false, "pyfuzzylite is not available, so the tests that drive it are skipped (" + why
                + "; with CI set they fail instead)");
    }
}
