package org.fclcert.cli;

import java.io.PrintWriter;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunCase;
import org.fclcert.harness.RunListener;

/**
 * The progress line of {@code certify}: on a terminal one line rewritten in place; every case that does not
 * pass gets a line of its own (also when the output is a log file).
 */
final class ProgressLine implements RunListener {
    private final PrintWriter err;
    private final boolean terminal;
    private int passed;
    private int notPassed;

    ProgressLine(PrintWriter err, boolean terminal) {
        this.err = err;
        this.terminal = terminal;
    }

    @Override
    public void caseStarted(RunCase c, int index, int total) {
        if (terminal) {
            err.print("\r\033[K[" + (index + 1) + "/" + total + "] " + passed + " passed, " + notPassed
                    + " not passed · " + c.id());
            err.flush();
        }
    }

    @Override
    public void caseFinished(CaseResult result, int index, int total) {
        if (result.status() == CaseStatus.PASSED) {
            passed++;
            return;
        }
        notPassed++;
        err.print(terminal ? "\r\033[K" : "");
        err.println(result.status().word().toUpperCase(java.util.Locale.ROOT) + " " + result.id() + ": "
                + TerminalText.visible(firstLine(result.message())));
        err.flush();
    }

    void finish() {
        if (terminal) {
            err.print("\r\033[K");
            err.flush();
        }
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
