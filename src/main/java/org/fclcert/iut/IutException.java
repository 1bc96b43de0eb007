package org.fclcert.iut;

import java.util.Objects;

/**
 * An implementation under test failed to answer a request properly. The {@link Kind} decides how the
 * harness records the case; the message says what happened in a plain sentence; the stderr tail is
 * the end of what a process IUT wrote to its standard error (empty for in-process IUTs).
 */
public final class IutException extends Exception {
    private static final long serialVersionUID = 1L;

    /** What went wrong. */
    public enum Kind {
        /** The IUT answered cleanly that it could not evaluate ({@code ok:false}, kind {@code error}). */
        EVAL_ERROR,
        /** The IUT died or threw something it should not have (a process exited, a Java call failed). */
        CRASH,
        /** The IUT did not answer within the per-request timeout. */
        TIMEOUT,
        /** The reply was not JSON, not the reply asked for, or too large. */
        PROTOCOL,
        /** The IUT failed so often that the restart budget is used up; no more requests are sent. */
        GAVE_UP,
        /** fclcert could not reach the IUT at all (bad spec, class not found, command not startable). */
        INFRA,
        /**
         * fclcert itself stopped the run (Ctrl-C, SIGTERM, the run budget) before or while the request was under
         * way ({@link StopSignal}): no fault of the IUT; the step is reported as not run.
         */
        STOPPED
    }

    private final Kind kind;
    private final String stderrTail;

    public IutException(Kind kind, String message, String stderrTail) {
        super(IutText.kept(message));
        this.kind = Objects.requireNonNull(kind, "kind");
        this.stderrTail = stderrTail == null ? "" : IutText.wellFormed(stderrTail);   // bounded by stderrTailBytes
    }

    public IutException(Kind kind, String message) {
        this(kind, message, "");
    }

    public Kind kind() {
        return kind;
    }

    /** The last part of the IUT's standard error when it failed; empty when none. */
    public String stderrTail() {
        return stderrTail;
    }

    @Override
    public String toString() {
        return kind + ": " + getMessage();
    }
}
