package org.fclcert.maven;

import java.util.Locale;
import java.util.function.Consumer;
import org.apache.maven.plugin.logging.Log;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;
import org.fclcert.report.Report;
import org.fclcert.report.Tally;

/**
 * The certification run in the Maven log, as Surefire writes it. While the cases run: a progress line at most every
 * ten seconds. When the report is made ({@link #failures}): every failure that counts (a Basic Level or negative
 * case, or a claimed feature's) at WARNING, every error at ERROR, each with its title, its step's inputs, expected
 * and actual, the reference evaluator's trace and the Maven command that reruns just that case; the failures of
 * features the implementation does not claim — skipped in {@code TEST-fclcert.xml} — at INFO, one line each with
 * the reproduce command; so that the log's blocks are exactly the counts of its "Tests run" line ({@link Tally}).
 */
final class ProgressLog implements RunListener {
    /** A CI log shows the run is alive at least this often (Surefire says nothing until the end). */
    static final long PROGRESS_EVERY_NANOS = 10_000_000_000L;

    private final Log log;
    private long lastLine = System.nanoTime();
    private int passed;

    ProgressLog(Log log) {
        this.log = log;
    }

    @Override
    public void caseFinished(CaseResult result, int index, int total) {
        if (result.status() == CaseStatus.PASSED) {
            passed++;
        }
        if (System.nanoTime() - lastLine >= PROGRESS_EVERY_NANOS) {
            log.info("progress: " + (index + 1) + " of " + total + " cases run, " + passed + " passed");
            lastLine = System.nanoTime();
        }
    }

    /** The cases that did not pass, as the counts of {@link Tally} file them. */
    static void failures(Report r, Log log) {
        int total = r.cases().size();
        int index = 0;
        boolean unclaimedHeading = false;
        for (CaseResult c : r.cases()) {
            index++;
            if (c.status() != CaseStatus.FAILED && c.status() != CaseStatus.ERRORED || Tally.unclaimed(r, c)) {
                continue;
            }
            String line = "[" + index + "/" + total + "] " + c.id() + " " + c.status().name().toLowerCase(Locale.ROOT)
                    + title(c) + (c.message() == null ? "" : ": " + c.message());
            details(c, line, c.status() == CaseStatus.FAILED ? log::warn : log::error);
        }
        index = 0;
        for (CaseResult c : r.cases()) {
            index++;
            if (!Tally.unclaimed(r, c)) {
                continue;
            }
            if (!unclaimedHeading) {
                log.info("Not claimed by " + r.iut().name() + " (skipped in TEST-fclcert.xml, never a failure of the"
                        + " build):");
                unclaimedHeading = true;
            }
            log.info("[" + index + "/" + total + "] " + c.id() + " " + c.status().name().toLowerCase(Locale.ROOT)
                    + title(c) + (c.message() == null ? "" : ": " + c.message()) + " — reproduce: " + reproduce(c.id()));
        }
    }

    private static String title(CaseResult c) {
        return c.title() == null ? "" : " (" + c.title() + ")";
    }

    /** The failure, its step's inputs, expected and actual, the reference's trace, and how to rerun it. */
    private static void details(CaseResult r, String line, Consumer<CharSequence> out) {
        out.accept(line);
        CaseResult.Step step = r.evidence().step();
        if (step != null && !step.inputs().isEmpty()) {
            out.accept("  step " + step.number() + ", inputs: " + values(step.inputs()));
        }
        r.mismatch().ifPresent(m -> {
            out.accept("  expected: " + values(m.expected()));
            out.accept("  actual:   " + values(m.actual()));
        });
        if (r.evidence().reference() != null) {
            r.evidence().reference().lines().forEach(l -> out.accept("  reference: " + l));
        }
        out.accept("  reproduce: " + reproduce(r.id()));
    }

    private static String values(Object value) {
        return value instanceof java.util.Map<?, ?> map ? map.entrySet().stream().map(e -> e.getKey() + " = " + e.getValue())
                .collect(java.util.stream.Collectors.joining(", ")) : String.valueOf(value);
    }

    /** The Maven command that runs just this case (the mojo reads {@code fclcert.cases}; no probes by default). */
    static String reproduce(String caseId) {
        return "mvn verify -Dfclcert.cases=" + caseId;
    }
}
