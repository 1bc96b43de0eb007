package org.fclcert.model;

import java.util.Locale;

/** FCL names are not case-sensitive (IEC 61131-3, B.1.1): {@code Temp} and {@code TEMP} are one name. */
public final class Names {
    private Names() {
    }

    /** The key under which a name is looked up: upper case, locale-independent. */
    public static String key(String name) {
        return name.toUpperCase(Locale.ROOT);
    }

    public static boolean same(String a, String b) {
        return a.equalsIgnoreCase(b);
    }
}
