package org.fclcert.model;

import java.util.Locale;

/** The three levels of clause 6.1: Basic (Table 8), Extension (Table 9), Open (Table 10). */
public enum ConformanceLevel {
    BASIC,
    EXTENSION,
    OPEN;

    /** Lower-case word used in reports and the corpus ({@code basic}, {@code extension}, {@code open}). */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static ConformanceLevel byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT));
    }

    public ConformanceLevel max(ConformanceLevel other) {
        return compareTo(other) >= 0 ? this : other;
    }
}
