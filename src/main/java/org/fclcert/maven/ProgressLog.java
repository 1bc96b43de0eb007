package org.fclcert.maven;

import org.apache.maven.plugin.logging.Log;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;

/** Progress of a certification run in the Maven log: a line for each case that does not pass. */
final class ProgressLog implements RunListener {
    private final Log log;

    ProgressLog(Log log) {
        this.log = log;
    }

    @Override
    public void caseFinished(CaseResult result, int index, int total) {
        if (result.status() != CaseStatus.PASSED) {
            log.info("[" + (index + 1) + "/" + total + "] " + result.id() + " " + result.status().name().toLowerCase(
                    java.util.Locale.ROOT) + (result.message() == null ? "" : ": " + result.message()));
        }
    }
}
