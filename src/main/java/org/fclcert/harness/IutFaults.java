package org.fclcert.harness;

import org.fclcert.iut.IutException;

/** Plain sentences for what went wrong inside an implementation. */
final class IutFaults {
    private IutFaults() {
    }

    /** E.g. {@code crashed: exit code 139}, completing "the implementation ...". */
    static String describe(IutException e) {
        String what = switch (e.kind()) {
            case EVAL_ERROR -> "reported an error";
            case CRASH -> "crashed";
            case TIMEOUT -> "timed out";
            case PROTOCOL -> "broke the protocol";
            case GAVE_UP -> "was given up";
            case INFRA -> "could not be driven";
            case STOPPED -> "was stopped by fclcert";
        };
        String message = e.getMessage();
        return message == null || message.isBlank() ? what : what + ": " + message;
    }

    /** The message plus the implementation's last stderr lines, for the {@code error} field. */
    static String errorText(IutException e) {
        String message = e.getMessage() == null ? e.kind().name() : e.getMessage();
        String tail = e.stderrTail();
        return tail == null || tail.isBlank() ? message : message + "\n--- stderr (last lines) ---\n" + tail.strip();
    }
}
