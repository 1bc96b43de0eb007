package org.fclcert.sandbox;

/**
 * The isolation a run's implementation ran under, as the certificate records it.
 *
 * @param kind        how it was isolated
 * @param description one sentence for the reports: the engine and its version with the limits, or why there was
 *                    none (with how to install bubblewrap where it was missing)
 */
public record Isolation(Kind kind, String description) {
    /** How an implementation was isolated. */
    public enum Kind {
        /** in a bubblewrap sandbox (namespaces, read-only system, limits) */
        SANDBOX,
        /** no sandbox, because {@code --no-sandbox} was given */
        DISABLED,
        /** no sandbox, because bubblewrap is missing or does not work here */
        UNAVAILABLE,
        /** called inside fclcert's own JVM ({@code java:} with {@code --in-process}, or the reference) */
        IN_PROCESS
    }

    /** Whether the implementation ran without any isolation from the host. */
    public boolean unisolated() {
        return kind != Kind.SANDBOX;
    }

    public static Isolation inProcess(String why) {
        return new Isolation(Kind.IN_PROCESS, "none: " + why);
    }
}
