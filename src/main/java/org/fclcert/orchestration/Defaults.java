package org.fclcert.orchestration;

import org.fclcert.iut.IutOptions;
import org.fclcert.probe.Prober;

/**
 * The defaults of a run, named once and shared by the command line and the Maven plugin. Annotation values
 * (picocli's {@code defaultValue}, the mojos' {@code @Parameter defaultValue}) must be constant strings, so
 * each default is also spelled as the text each front end takes; every text is derived from the number.
 */
public final class Defaults {
    private Defaults() {
    }

    /** Per-request timeout of the implementation, in seconds ({@link IutOptions#DEFAULT_TIMEOUT}). */
    public static final int TIMEOUT_SECONDS = IutOptions.DEFAULT_TIMEOUT_SECONDS;

    /** {@link #TIMEOUT_SECONDS} as the command line writes it: {@code 5s}. */
    public static final String TIMEOUT = TIMEOUT_SECONDS + "s";

    /** {@link #TIMEOUT_SECONDS} as the Maven plugin's {@code timeoutMillis} takes it: {@code 5000}. */
    public static final String TIMEOUT_MILLIS = "" + TIMEOUT_SECONDS * 1000;

    /**
     * Largest size the Table 11 probes of a certification try: every "maximum number" row the standard's
     * own examples need, many times over, and quick enough for a certification run.
     */
    public static final long CERTIFY_PROBE_CAP = 4096;

    /** {@link #CERTIFY_PROBE_CAP} as text: {@code 4096}. */
    public static final String CERTIFY_PROBE_CAP_TEXT = "" + CERTIFY_PROBE_CAP;

    /** Largest size {@code fclcert probe} tries on its own ({@link Prober#DEFAULT_CAP}), as text. */
    public static final String PROBE_CAP_TEXT = "" + Prober.DEFAULT_CAP;

    /** Time budget of the Table 11 probes, in minutes ({@link Prober#DEFAULT_BUDGET}). */
    public static final int PROBE_BUDGET_MINUTES = Prober.DEFAULT_BUDGET_MINUTES;

    /** {@link #PROBE_BUDGET_MINUTES} as the command line writes it: {@code 3m}. */
    public static final String PROBE_BUDGET = PROBE_BUDGET_MINUTES + "m";

    /** {@link #PROBE_BUDGET_MINUTES} as the Maven plugin's {@code probeBudgetSeconds} takes it: {@code 180}. */
    public static final String PROBE_BUDGET_SECONDS = "" + PROBE_BUDGET_MINUTES * 60;

    /**
     * The time a whole certification run may take, cases and probes, in minutes. The per-request timeout bounds a
     * hang, not a slow implementation: one answering each request just within it (0.85 s under 1 s) would stretch
     * a run over the corpus's thousands of requests to hours. The corpus runs in seconds on every implementation
     * fclcert knows, fuzzylite's launch per request included, and the probes take {@link #PROBE_BUDGET_MINUTES}.
     */
    public static final int RUN_BUDGET_MINUTES = 30;

    /** {@link #RUN_BUDGET_MINUTES} as a duration. */
    public static final java.time.Duration RUN_BUDGET = java.time.Duration.ofMinutes(RUN_BUDGET_MINUTES);

    /** {@link #RUN_BUDGET_MINUTES} as the command line writes it: {@code 30m}. */
    public static final String RUN_BUDGET_TEXT = RUN_BUDGET_MINUTES + "m";

    /** {@link #RUN_BUDGET_MINUTES} as the Maven plugin's {@code budgetSeconds} takes it: {@code 1800}. */
    public static final String RUN_BUDGET_SECONDS = "" + RUN_BUDGET_MINUTES * 60;

    /**
     * How long a shutdown hook (Ctrl-C, SIGTERM) waits for a stopped run to end on its own — the request under way
     * cut short, the reports written, the implementation closed — before it seals the outputs and kills the
     * implementation itself. A process IUT ends at once; this bounds an in-process one deaf to interruption.
     */
    public static final java.time.Duration STOP_GRACE = java.time.Duration.ofSeconds(10);
}
