package org.fclcert.maven;

import java.util.Locale;
import org.apache.maven.plugin.logging.Log;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;

/**
 * Progress of a certification run in the Maven log, as Surefire writes it: a failed case at WARNING, an
 * errored one at ERROR, each with the Maven command that reruns just that case; a skipped case at INFO.
 */
final class ProgressLog implements RunListener {
    private final Log log;

    ProgressLog(Log log) {
        this.log = log;
    }

    @Override
    public void caseFinished(CaseResult result, int index, int total) {
        if (result.status() == CaseStatus.PASSED) {
            return;
        }
        String line = "[" + (index + 1) + "/" + total + "] " + result.id() + " "
                + result.status().name().toLowerCase(Locale.ROOT) + (result.message() == null ? "" : ": " + result.message());
        switch (result.status()) {
            case FAILED -> {
                log.warn(line);
                log.warn("  reproduce: " + reproduce(result.id()));
            }
            case ERRORED -> {
                log.error(line);
                log.error("  reproduce: " + reproduce(result.id()));
            }
            default -> log.info(line);
        }
    }

    /** The Maven command that runs just this case (the mojo reads {@code fclcert.cases}; no probes by default). */
    static String reproduce(String caseId) {
        return "mvn verify -Dfclcert.cases=" + caseId;
    }
}
