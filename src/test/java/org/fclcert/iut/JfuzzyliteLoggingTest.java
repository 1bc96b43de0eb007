package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogManager;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

/**
 * jfuzzylite's FuzzyLite class reconfigures java.util.logging for the whole JVM when it is initialised (root level
 * ALL); the adapter puts the root logger back, so the build log does not fill with every library's FINER records.
 */
class JfuzzyliteLoggingTest {
    private static URLClassLoader fresh() throws Exception {
        URL jar = Path.of(ChildJvm.location(Class.forName("com.fuzzylite.Engine")).orElseThrow()).toUri().toURL();
        return new URLClassLoader(new URL[] {jar}, null);   // a class of its own, so its static initialiser runs again
    }

    @Test
    void initialisingFuzzyLiteLeavesTheRootLoggerAsItWas() throws Exception {
        Logger root = Logger.getLogger("");
        Level before = root.getLevel();
        Handler[] handlers = root.getHandlers();
        try (URLClassLoader unguarded = fresh(); URLClassLoader guarded = fresh()) {
            root.setLevel(Level.WARNING);
            // unguarded, the library does what this test guards against
            Class.forName("com.fuzzylite.FuzzyLite", true, unguarded);
            assertEquals(Level.ALL, root.getLevel(), "jfuzzylite 6.0.1 sets the root level to ALL");
            LogManager.getLogManager().readConfiguration();
            root.setLevel(Level.WARNING);
            Handler[] kept = root.getHandlers();

            JfuzzyliteImplementation.initialiseKeepingLogging("com.fuzzylite.FuzzyLite", guarded);
            assertEquals(Level.WARNING, root.getLevel());
            assertArrayEquals(kept, root.getHandlers());
        } finally {
            LogManager.getLogManager().readConfiguration();
            root.setLevel(before);
            for (Handler h : root.getHandlers()) {
                root.removeHandler(h);
            }
            for (Handler h : handlers) {
                root.addHandler(h);
            }
        }
    }
}
