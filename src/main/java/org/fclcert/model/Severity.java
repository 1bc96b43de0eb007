package org.fclcert.model;

/** How serious a diagnostic is: an error makes a program non-conforming, a warning does not. */
public enum Severity {
    ERROR,
    WARNING;

    /** Lower-case word used in text output ({@code error}, {@code warning}). */
    public String word() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
