package org.fclcert.iut;

/**
 * When an implementation that breaks down is restarted and when it is given up (docs/iut-protocol.md, "Failures,
 * timeouts and restarts"). A crash, a hang or a protocol fault costs only the request that caused it: the process is
 * killed and the next request starts a new one. The implementation is given up only
 * <ul>
 * <li>when it cannot be started: {@link #FAILED_STARTS} starts in a row whose {@code hello} fails, or</li>
 * <li>when each of the last N requests broke it down, N = {@link IutOptions#restartBudget()} + 1 (the restarts
 *     in a row it is granted, default {@link IutOptions#DEFAULT_RESTART_BUDGET}, so N = 6): one request answered
 *     properly starts the count afresh.</li>
 * </ul>
 * An implementation that crashes on some programs therefore runs the whole corpus; one that can no longer answer
 * anything costs at most N requests' time.
 */
final class RestartPolicy {
    /** Starts in a row whose {@code hello} failed, after which the implementation cannot be started. */
    static final int FAILED_STARTS = 3;

    private final int budget;
    private int failuresInARow;
    private int failedStartsInARow;
    private int crashes;
    private int starts;
    private String reason;

    RestartPolicy(int budget) {
        this.budget = Math.max(0, budget);
    }

    /** A request got its proper answer. */
    void answered() {
        failuresInARow = 0;
    }

    /** A request broke the implementation down (it was killed). */
    void brokeDown(String what) {
        crashes++;
        if (++failuresInARow > budget && reason == null) {
            reason = "each of the last " + failuresInARow + " requests crashed, hung or broke the protocol; last: " + what;
        }
    }

    /** A process was started. */
    void started() {
        starts++;
    }

    /** The {@code hello} of a fresh process failed. */
    void helloFailed(String what) {
        if (++failedStartsInARow >= FAILED_STARTS && reason == null) {
            reason = "it could not be started: " + FAILED_STARTS + " starts in a row failed their hello; last: " + what;
        }
    }

    void helloAnswered() {
        failedStartsInARow = 0;
    }

    /** Why the implementation is given up; null while it is not. */
    String gaveUp() {
        return reason;
    }

    IutHealth health() {
        return new IutHealth(crashes, Math.max(0, starts - 1));
    }
}
