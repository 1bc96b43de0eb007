package org.fclcert.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.Runner;
import org.fclcert.harness.RunCase;
import org.fclcert.harness.RunListener;
import org.fclcert.orchestration.Certification;

/**
 * The progress of {@code certify}: on a terminal one line rewritten in place; elsewhere (a pipe, a CI log)
 * a plain progress line every {@link #TICK_SECONDS} seconds, the Table 11 probes included. Every case that
 * does not pass gets a few lines of its own in both: what went wrong, the step's inputs, the
 * implementation's last stderr line, the command that reruns just that case and its protocol transcript.
 */
final class ProgressLine implements RunListener {
    /** How often the progress line is printed when stderr is not a terminal. */
    static final int TICK_SECONDS = 5;

    private final PrintWriter err;
    private final boolean terminal;
    private final String iutSpec;
    private final String classpath;
    private final String corpus;
    private Path directory;
    private int passed;
    private int notPassed;
    private volatile String state = "starting";
    private ScheduledExecutorService ticker;

    /**
     * @param corpus the corpus as the reproduce command must name it, or null when the default is right
     */
    ProgressLine(PrintWriter err, boolean terminal, String iutSpec, String classpath, String corpus) {
        this.err = err;
        this.terminal = terminal;
        this.iutSpec = iutSpec;
        this.classpath = classpath;
        this.corpus = corpus;
    }

    /** The run's output directory is known: transcripts are named in it; off a terminal the ticks begin. */
    void directory(Path dir) {
        directory = dir;
        if (!terminal && ticker == null) {
            ticker = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "fclcert-progress");
                t.setDaemon(true);
                return t;
            });
            ticker.scheduleAtFixedRate(this::tick, TICK_SECONDS, TICK_SECONDS, TimeUnit.SECONDS);
        }
    }

    private void tick() {
        synchronized (err) {
            err.println("progress: " + state);
            err.flush();
        }
    }

    @Override
    public void caseStarted(RunCase c, int index, int total) {
        state = "[" + (index + 1) + "/" + total + "] " + passed + " passed, " + notPassed + " not passed · " + c.id();
        if (terminal) {
            err.print("\r\033[K" + state);
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
        if (result.message() != null && result.message().startsWith(Runner.STOPPED)) {
            return;   // a stopped run: one line at its end says so, not one per case left
        }
        synchronized (err) {
            err.print(terminal ? "\r\033[K" : "");
            err.println(result.status().word().toUpperCase(Locale.ROOT) + " " + result.id()
                    + (result.title() == null ? "" : " (" + TerminalText.visible(result.title()) + ")") + ": " + TerminalText.visible(firstLine(result.message())));
            if (result.status() != CaseStatus.SKIPPED) {
                details(result);
            }
            err.flush();
        }
    }

    private void details(CaseResult r) {
        CaseResult.Step step = r.evidence().step();
        if (step != null && !step.inputs().isEmpty()) {
            err.println("  step " + step.number() + ", inputs: " + TerminalText.visible(values(step.inputs())));
        }
        r.mismatch().ifPresent(m -> {
            err.println("  expected: " + TerminalText.visible(describe(m.expected())));
            err.println("  actual:   " + TerminalText.visible(describe(m.actual())));
        });
        if (r.evidence().reference() != null) {
            r.evidence().reference().lines().forEach(l -> err.println("  reference: " + TerminalText.visible(l)));
        }
        negativeCase(r);
        String stderr = lastStderrLine(r.evidence().error());
        if (stderr != null) {
            err.println("  its stderr: " + TerminalText.visible(stderr));
        }
        err.println("  reproduce: " + reproduce(r.id()));
        if (directory != null && r.status() != CaseStatus.SKIPPED) {
            err.println("  transcript: " + Certification.transcriptFile(directory, r.id()));
        }
    }

    /** For a negative case: what its code means, and the line of the program that holds the error. */
    private void negativeCase(CaseResult r) {
        r.expectedRejection().ifPresent(want -> {
            DiagnosticCatalogue.find(want.code()).ifPresent(code ->
                    err.println("  " + code.code() + " (" + code.clause() + "): " + code.meaning()));
            r.programLine(want.line()).ifPresent(text -> err.println("  line " + want.line() + ": "
                    + TerminalText.visible(text)));
        });
    }

    /** The command that reruns just this case: no probes, reports in the temporary directory. */
    String reproduce(String caseId) {
        StringBuilder b = new StringBuilder("./fclcert certify --iut ").append(shellQuote(iutSpec));
        if (classpath != null) {
            b.append(" --classpath ").append(shellQuote(classpath));
        }
        if (corpus != null) {
            b.append(" --corpus ").append(shellQuote(corpus));
        }
        return b.append(" --case ").append(shellQuote(caseId)).toString();
    }

    /** The Table 11 probes reached row {@code id} (off a terminal only: the ticks show it). */
    void probing(String id, int index, int total) {
        state = "probing Table 11, " + index + "/" + total + ": " + id;
    }

    /** The cases are done; the progress line is cleared (the ticks go on through the probes). */
    void finish() {
        state = "cases done: " + passed + " passed, " + notPassed + " not passed";
        if (terminal) {
            err.print("\r\033[K");
            err.flush();
        }
    }

    /** The run is over: no more ticks. */
    void stop() {
        if (ticker != null) {
            ticker.shutdownNow();
        }
    }

    private static String values(Map<String, Double> values) {
        return values.entrySet().stream().map(e -> e.getKey() + " = " + e.getValue()).collect(Collectors.joining(", "));
    }

    private static String describe(Object value) {
        if (value instanceof Map<?, ?> map) {
            return map.entrySet().stream().map(e -> e.getKey() + " = " + e.getValue())
                    .collect(Collectors.joining(", "));
        }
        return String.valueOf(value);
    }

    /** The last non-blank line of the stderr tail the harness appended to an implementation's error, if any. */
    static String lastStderrLine(String error) {
        if (error == null) {
            return null;
        }
        int marker = error.indexOf("--- stderr");
        if (marker < 0) {
            return null;
        }
        String[] lines = error.substring(marker).split("\n");
        for (int i = lines.length - 1; i > 0; i--) {
            if (!lines[i].isBlank()) {
                return lines[i].strip();
            }
        }
        return null;
    }

    private static String shellQuote(String s) {
        return s.matches("[A-Za-z0-9_./:=@%+,-]+") ? s : "'" + s.replace("'", "'\\''") + "'";
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
