package org.fclcert.cli;

/** The exit codes of every fclcert command (listed in README.md and in each command's --help). */
public final class ExitCodes {
    /** The command did its job and found no error (warnings allowed). */
    public static final int OK = 0;
    /** A program has errors (or, for later commands, a check failed). */
    public static final int ERRORS = 1;
    /** Bad command line, or a file that cannot be read or written. */
    public static final int USAGE = 2;
    /** A bug in fclcert: an unexpected exception, reported in one line. */
    public static final int INTERNAL = 3;

    // For picocli's exitCodeList in each command's --help (annotation values must be constants).
    static final String HEADING = "%nExit codes:%n";
    static final String OK_LINE = "0:no errors (warnings allowed)";
    static final String ERRORS_LINE = "1:a program has errors";
    static final String USAGE_LINE = "2:usage problem, or a file that cannot be read or written";
    static final String INTERNAL_LINE = "3:internal error in fclcert (a bug; please report it)";

    private ExitCodes() {
    }
}
