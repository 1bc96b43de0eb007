package org.fclcert.model;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;

/** Facts about this build of fclcert (its version), read from a resource Maven fills in. */
public final class Toolkit {
    private static final String VERSION = load();

    private Toolkit() {
    }

    public static String version() {
        return VERSION;
    }

    private static String load() {
        try (InputStream in = Toolkit.class.getResourceAsStream("/org/fclcert/toolkit.properties")) {
            if (in == null) {
                return "unknown";
            }
            Properties p = new Properties();
            p.load(in);
            return p.getProperty("version", "unknown");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
