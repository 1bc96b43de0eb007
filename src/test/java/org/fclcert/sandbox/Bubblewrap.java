package org.fclcert.sandbox;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Whether bubblewrap makes sandboxes here, for the tests that attack the sandbox. The build installs it where it
 * can ({@code scripts/ensure-bubblewrap}); with the environment variable {@code CI} set a missing or broken
 * bubblewrap fails these tests, elsewhere they are skipped with the reason.
 */
public final class Bubblewrap {
    private Bubblewrap() {}

    public static void assumeWorking() {
        Sandbox sandbox = Sandbox.of(SandboxSettings.defaults());
        if (!sandbox.active()) {
            String why = sandbox.isolation().description();
            if (System.getenv("CI") != null) {
                fail("CI is set but bubblewrap makes no sandbox here (scripts/ensure-bubblewrap should have installed"
                        + " it): " + why);
            }
            assumeTrue(false, "bubblewrap makes no sandbox here, so the sandbox tests are skipped (apt-get install"
                    + " bubblewrap, or run scripts/ensure-bubblewrap; with CI set they fail instead): " + why);
        }
    }
}
