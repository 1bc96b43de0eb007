package org.fclcert.maven;

import java.util.Locale;
import org.apache.maven.plugin.logging.Log;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RunListener;

/**
 * Progress of a certification run in the Maven log, as Surefire writes it: a failed case at WARNING, an
 * errored one at ERROR, each with its step's inputs, expected and actual, the reference evaluator's trace and
 * the Maven command that reruns just that case; a skipped case at INFO; while cases pass, a progress line at
 * most every ten seconds.
 */
final class ProgressLog implements RunListener {
    /** A CI log shows the run is alive at least this often while cases pass (Surefire says nothing until the end). */
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
            if (System.nanoTime() - lastLine >= PROGRESS_EVERY_NANOS) {
                log.info("progress: " + (index + 1) + " of " + total + " cases run, " + passed + " passed");
                lastLine = System.nanoTime();
            }
            return;
        }
        lastLine = System.nanoTime();
        String line = "[" + (index + 1) + "/" + total + "] " + result.id() + " "
                + result.status().name().toLowerCase(Locale.ROOT) + (result.message() == null ? "" : ": " + result.message());
        switch (result.status()) {
            case FAILED -> details(result, line, log::warn);
            case ERRORED -> details(result, line, log::error);
            default -> log.info(line);
        }
    }

    /** The failure, its step's inputs, expected and actual, the reference's trace, and how to rerun it. */
    private static void details(CaseResult r, String line, java.util.function.Consumer<CharSequence> out) {
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
