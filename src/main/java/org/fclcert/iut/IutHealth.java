package org.fclcert.iut;

/**
 * How often an implementation broke down and was restarted so far in a session: requests that ended in a
 * crash, a timeout (a hang) or a protocol fault, and restarts of its process. Counts only grow; the harness takes
 * the difference around a case to count that case's ({@link ImplementationUnderTest#health()}).
 *
 * @param crashes   requests that ended with the implementation dead or unusable ({@code CRASH}, {@code TIMEOUT},
 *                  {@code PROTOCOL}: each kills the process)
 * @param restarts  times a new process was started after the first
 */
public record IutHealth(int crashes, int restarts) {
    public static final IutHealth NONE = new IutHealth(0, 0);

    /** What happened since {@code before}. */
    public IutHealth since(IutHealth before) {
        return new IutHealth(crashes - before.crashes, restarts - before.restarts);
    }

    public boolean quiet() {
        return crashes == 0 && restarts == 0;
    }
}
