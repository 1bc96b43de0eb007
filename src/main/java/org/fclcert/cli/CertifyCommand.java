package org.fclcert.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fclcert.corpus.BundledCorpus;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusException;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.Runner;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.StopSignal;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.orchestration.Certification;
import org.fclcert.orchestration.Defaults;
import org.fclcert.orchestration.PresentAs;
import org.fclcert.orchestration.RunControl;
import org.fclcert.probe.Prober;
import org.fclcert.probe.Table11;
import org.fclcert.report.FailOn;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.fclcert.report.ReportFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert certify}: runs the conformance corpus against an implementation and writes the reports. */
@Command(name = "certify", mixinStandardHelpOptions = true,
        description = {"Run the conformance corpus against an implementation under test and write the compliance "
                + "statement (report.json, report.md, report.html, junit.xml) and results.jsonl.",
            "Exit 0: the run completed and --fail-on holds; 1: it does not hold; 2: the run could not be done, or was"
                    + " stopped before its end by --budget (the reports of what was done are written)."})
final class CertifyCommand implements Callable<Integer> {
    static final int OK = ExitCodes.OK;
    static final int FAILED = ExitCodes.ERRORS;
    static final int CANNOT_RUN = ExitCodes.USAGE;

    @Spec
    CommandSpec spec;

    @Mixin
    IutMixin iut;

    @Option(names = "--corpus", paramLabel = "DIR",
            description = "Corpus directory (default: conformance/ when the current directory has one, else the"
                    + " corpus bundled in fclcert)")
    Path corpus;

    /** The corpus of a checkout of this repository, used when the command runs at its root. */
    private static final Path DEFAULT_CORPUS = Path.of("conformance");

    /** The corpus the run uses: the directory given, else conformance/ here, else none (the bundled one). */
    private Path corpusDirectory() {
        return corpus == null && Files.isDirectory(DEFAULT_CORPUS) ? DEFAULT_CORPUS : corpus;
    }

    /** The corpus as a reproduce command names it: null for the default (conformance/ here, or the bundled one). */
    private String corpusArgument() {
        return corpus == null || corpus.equals(DEFAULT_CORPUS) ? null : corpus.toString();
    }

    /** How the run names its corpus: its directory, or {@code bundled}. */
    private String corpusName() {
        Path dir = corpusDirectory();
        return dir != null ? dir.toString() : BundledCorpus.NAME;
    }

    @Option(names = "--out", paramLabel = "DIR",
            description = "Output directory (default: fclcert-reports/<iut-name>, which git ignores; with --case,"
                    + " fclcert-reports-<user>/<iut-name> of the system's temporary directory, so that reproducing a case"
                    + " writes nothing into the checkout)")
    Path out;

    @Option(names = "--level", paramLabel = "LEVEL", split = ",",
            description = "Only cases of these levels: basic, extension, open")
    List<ConformanceLevel> levels = new ArrayList<>();

    @Option(names = "--feature", paramLabel = "ID", arity = "1..*",
            description = "Only cases that are evidence for these feature ids (e.g. E-ACCU-NSUM)")
    List<String> features = new ArrayList<>();

    @Option(names = "--case", paramLabel = "GLOB", arity = "1..*",
            description = "Only cases whose id matches one of these globs (e.g. 'B-COGS-*')")
    List<String> cases = new ArrayList<>();

    @Option(names = "--fail-on", paramLabel = "WHAT", defaultValue = "none",
            description = "none | basic | claimed | any: exit 1 when this does not hold (default: ${DEFAULT-VALUE})")
    FailOn failOn;

    @Option(names = "--present-as", paramLabel = "LAYOUT", defaultValue = "auto",
            completionCandidates = PresentAsNames.class,
            description = "${COMPLETION-CANDIDATES}: also send each positive case the layout can"
                    + " express written in that library's layout, the semantic axis (default: ${DEFAULT-VALUE}: the"
                    + " built-in library adapters in their library's layout, none for reference, java: and process:)")
    PresentAs presentAs;

    @Option(names = "--budget", paramLabel = "DURATION", defaultValue = Defaults.RUN_BUDGET_TEXT,
            converter = DurationConverter.class,
            description = "Time the whole run may take, cases and probes, e.g. 30m, 2h (default: ${DEFAULT-VALUE});"
                    + " the cases not run by then are reported as skipped with the reason")
    Duration budget;

    @Option(names = "--seed", paramLabel = "N", description = "The run seed the fresh vectors and disguises are drawn"
            + " from (default: drawn anew; every report records it, and the same seed replays the run exactly)")
    Long seed;

    @Option(names = "--no-fresh-evidence", description = "For testing fclcert's harness with fake implementations and"
            + " corpora: no seed, fresh vectors or disguise, no check of a custom corpus; the results are UNVERIFIED,"
            + " issue no Basic Level verdict, and report --verify, compare and fclcert:verify refuse them")
    boolean noFreshEvidence;

    @Option(names = "--no-probe", description = "Do not measure the Table 11 data check list")
    boolean noProbe;

    @Option(names = "--probe", description = "Measure the Table 11 data check list also when --case selects cases")
    boolean forceProbe;

    @Option(names = "--probe-cap", paramLabel = "N", defaultValue = Defaults.CERTIFY_PROBE_CAP_TEXT,
            description = "Largest size the Table 11 probes try (default: ${DEFAULT-VALUE}; fclcert probe uses "
                    + Defaults.PROBE_CAP_TEXT + ")")
    long probeCap;

    @Option(names = "--probe-budget", paramLabel = "DURATION", defaultValue = Defaults.PROBE_BUDGET,
            converter = DurationConverter.class,
            description = "Time budget of the Table 11 probes (default: ${DEFAULT-VALUE})")
    Duration probeBudget;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            return certify(spec.commandLine().getOut(), err);
        } catch (CannotRun e) {
            err.println("fclcert certify: " + TerminalText.visibleLines(e.getMessage()));
            err.flush();
            return CANNOT_RUN;
        } finally {
            // what the run printed is out: a shutdown hook waiting for it may let the JVM end
            printed.countDown();
            if (onSignal != null) {
                try {
                    Runtime.getRuntime().removeShutdownHook(onSignal);
                } catch (IllegalStateException shuttingDown) {
                    // the hook is running: it waited for 'printed'
                }
            }
        }
    }

    /** Counted down once everything the command prints is printed. */
    private final CountDownLatch printed = new CountDownLatch(1);
    /** The shutdown hook of a run under way (Ctrl-C, SIGTERM, SIGHUP), or null. */
    private Thread onSignal;
    /** Whether the run itself has begun (before it, a signal finds nothing written, and nothing to wait for). */
    private volatile boolean runStarted;

    private int certify(PrintWriter stdout, PrintWriter err) throws CannotRun {
        // SIGINT, SIGTERM and SIGHUP end the run the same way from the first moment (issue 27: a SIGTERM while the
        // corpus was read killed the JVM silently)
        boolean terminal = System.console() != null;
        ProgressLine progress = new ProgressLine(err, terminal, iut.spec, iut.classpath, corpusArgument());
        TerminalHooks hooks = new TerminalHooks(progress, err, terminal);
        RunControl control = new RunControl();
        onSignal = new Thread(() -> interrupted(control, printed, hooks, err), "fclcert-interrupted");
        Runtime.getRuntime().addShutdownHook(onSignal);
        EarlySignals.handledByCommand();
        Set<ConformanceLevel> levelSet = levels.isEmpty() ? Set.of() : EnumSet.copyOf(levels);
        CaseSelection selection = new CaseSelection(levelSet, parseFeatures(), cases);
        if (probeCap < 1) {
            throw new CannotRun("--probe-cap must be at least 1, not " + probeCap);
        }
        if (noProbe && forceProbe) {
            throw new CannotRun("--probe and --no-probe contradict each other");
        }
        // selecting cases is reproducing them: seconds, not the probes' minute, and nothing in the checkout
        boolean reproducing = !cases.isEmpty();
        boolean probing = forceProbe || !noProbe && !reproducing;
        Prober.Options probe = probing ? new Prober.Options(probeCap, probeBudget, Set.of()) : null;
        Corpus loaded = loadCorpus();
        java.nio.file.Path reportsRoot = Certification.DEFAULT_REPORTS_ROOT;
        if (reproducing && out == null) {
            try {
                reportsRoot = Certification.scratchReportsRoot();
            } catch (java.io.IOException e) {
                throw new CannotRun("cannot make a private directory for the reports in the temporary directory: "
                        + e.getMessage());
            }
        }
        Certification.Request request = Certification.Request.builder(iut.spec, loaded)
                .options(iut.options()).classpath(iut.classpath)
                .corpusName(corpusName()).selection(selection).outDir(out).probe(probe)
                .reportsRoot(reportsRoot)
                .filters(levels.stream().map(ConformanceLevel::word).toList(), features, cases)
                .presentAs(presentAs).budget(budget).seed(seed).freshEvidence(!noFreshEvidence).build();
        Certification.Outcome outcome;
        runStarted = true;
        try {
            outcome = Certification.run(request, progress, hooks, control);
        } catch (Certification.NothingSelected e) {
            throw new CannotRun("no case of " + corpusName() + " matches the selection");
        } catch (Certification.CannotCertify e) {
            throw new CannotRun(e.getMessage());
        } finally {
            progress.stop();
        }
        return finish(stdout, err, outcome);
    }

    private int finish(PrintWriter stdout, PrintWriter err, Certification.Outcome outcome) {
        Report report = outcome.report();
        print(stdout, report, outcome.directory());
        org.fclcert.sandbox.Isolation isolation = report.iut().isolation();
        if (isolation != null && (isolation.kind() == org.fclcert.sandbox.Isolation.Kind.UNAVAILABLE
                || isolation.kind() == org.fclcert.sandbox.Isolation.Kind.DISABLED)) {
            err.println("fclcert certify: warning: the implementation was not sandboxed: " + isolation.description());
            err.flush();
        }
        if (outcome.stopped() != null) {
            Report.Summary s = report.summary();
            long notRun = report.cases().stream().filter(c -> c.message() != null
                    && c.message().startsWith(Runner.STOPPED)).count();
            err.println("fclcert certify: the run was stopped (" + outcome.stopped() + ") after " + (s.cases() - notRun)
                    + " of " + s.cases() + " cases; the " + notRun + " not run are reported as skipped, the reports are"
                    + " in " + outcome.directory());
            err.flush();
            return CANNOT_RUN;
        }
        if (!failOn.holds(report)) {
            err.println("fclcert certify: --fail-on " + failOn.word() + ": " + failOn.explain(report));
            err.flush();
            return FAILED;
        }
        return OK;
    }

    /** How long the shutdown hook waits, once the run has ended, for its summary to be printed. */
    private static final Duration PRINT_GRACE = Duration.ofSeconds(5);

    /**
     * Ctrl-C or a kill during the run (a shutdown hook): the run is stopped and ends on its own thread — the case
     * under way and the later ones reported as not run, the reports written, the implementation closed, the summary
     * printed — and this waits for that, since the JVM ends when its hooks do. An implementation deaf to the stop
     * for {@link Defaults#STOP_GRACE} is killed, and the results of the cases that finished stay in results.jsonl.
     */
    private void interrupted(RunControl control, CountDownLatch printed, TerminalHooks hooks, PrintWriter err) {
        if (!runStarted) {
            err.println();
            err.println("fclcert certify: " + StopSignal.INTERRUPTED + " before the run started; nothing was written");
            err.flush();
            return;
        }
        if (control.stop(StopSignal.INTERRUPTED, Defaults.STOP_GRACE)) {
            try {
                printed.await(PRINT_GRACE.toMillis(), TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return;
        }
        Path results = hooks.resultsFile;
        err.println();
        err.println("fclcert certify: interrupted; the implementation did not stop within "
                + Defaults.STOP_GRACE.toSeconds() + " s and was killed" + (results == null ? ""
                        : "; the results of the cases that finished are in " + results + " ('fclcert report --from "
                                + results + "' makes the reports)"));
        err.flush();
    }

    /** The command line's side of a run: ends the progress line, shows the Table 11 probes on a terminal. */
    private static final class TerminalHooks implements Certification.Hooks {
        private final ProgressLine progress;
        private final PrintWriter err;
        private final boolean terminal;
        private volatile Path resultsFile;
        private boolean probed;

        TerminalHooks(ProgressLine progress, PrintWriter err, boolean terminal) {
            this.progress = progress;
            this.err = err;
            this.terminal = terminal;
        }

        @Override
        public void started(ImplementationUnderTest iut, Path directory, Path resultsFile) {
            progress.directory(directory);
            this.resultsFile = resultsFile;
        }

        @Override
        public void casesFinished() {
            progress.finish();
        }

        @Override
        public void probing(Table11 row, int index, int total) {
            if (terminal) {
                probed = true;
                err.print("\r\u001b[Kprobing Table 11, " + index + "/" + total + ": " + row.id());
                err.flush();
            } else {
                progress.probing(row.id(), index, total);
            }
        }

        @Override
        public void resultsComplete() {
            progress.stop();
            if (probed) {
                err.print("\r\u001b[K");
                err.flush();
            }
        }
    }

    /** How many causes the terminal summary lists; the reports list them all. */
    private static final int CAUSES_SHOWN = 8;

    private static void print(PrintWriter out, Report r, Path dir) {
        Report.Summary s = r.summary();
        out.println(TerminalText.visible(r.iut().name()) + " " + TerminalText.visible(r.iut().version()) + ": " + s.cases() + " cases, " + s.passed()
                + " passed, " + s.failed() + " failed, " + s.errored() + " errored, " + s.skipped() + " skipped");
        if (r.rejections().doubtful()) {
            out.println("Negative cases: " + r.rejections().sentence());
        }
        if (r.origin() != null) {
            r.origin().warnings().forEach(w -> out.println(TerminalText.visible(w)));
        }
        out.println("Basic Level: " + r.basicLevel().sentence());
        String axis = r.semantic() != null ? " (language axis)" : "";
        out.println("Standard Extensions realised (Table 9)" + axis + ": " + realised(r, 9));
        out.println("Open Level features realised (Table 10)" + axis + ": " + realised(r, 10));
        if (r.semantic() != null) {
            out.println(r.semantic().sentence());
            out.println("Basic Level rows realised (Table 8, semantic axis): " + semanticRealised(r, 8));
            out.println("Standard Extensions realised (Table 9, semantic axis): " + semanticRealised(r, 9));
            out.println("Open Level features realised (Table 10, semantic axis): " + semanticRealised(r, 10));
        }
        if (!r.causes().isEmpty()) {
            out.println("Failures by cause:");
            r.causes().stream().limit(CAUSES_SHOWN).forEach(c -> out.println("  " + TerminalText.visible(c.sentence())));
            if (r.causes().size() > CAUSES_SHOWN) {
                out.println("  … and " + (r.causes().size() - CAUSES_SHOWN) + " more causes (report.md, \"Failures by cause\")");
            }
        }
        if (!r.claims().notRealised().isEmpty()) {
            out.println("Claimed but not realised: " + TerminalText.visible(String.join(", ", r.claims().notRealised())));
        }
        if (!r.claims().notDetermined().isEmpty()) {
            out.println("Claimed, not determined: " + TerminalText.visible(String.join(", ", r.claims().notDetermined())));
        }
        out.println("Reports: " + dir.resolve(ReportFiles.MARKDOWN) + ", " + ReportFiles.HTML + ", "
                + ReportFiles.JSON + ", " + ReportFiles.JUNIT + ", " + Certification.RESULTS);
        out.flush();
    }

    /** {@code 3 of 25: E-NOT, E-COG, E-LM} or {@code 0 of 3} (the report has no rows for dialect-syntax features). */
    private static String realised(Report r, int table) {
        List<String> ids = r.features().stream().filter(f -> f.table() == table && f.status() == FeatureStatus.REALISED)
                .map(Report.FeatureRow::id).toList();
        long rows = r.features().stream().filter(f -> f.table() == table).count();
        return ids.size() + " of " + rows + (ids.isEmpty() ? "" : ": " + String.join(", ", ids));
    }

    /** As {@link #realised}, by the rows' semantic verdicts; {@code (n not presentable)} counts rows none of whose cases the layout can say. */
    private static String semanticRealised(Report r, int table) {
        List<Report.FeatureRow> rows = r.features().stream().filter(f -> f.table() == table && f.semantic() != null)
                .toList();
        List<String> ids = rows.stream().filter(f -> f.semantic().status() == FeatureStatus.REALISED)
                .map(Report.FeatureRow::id).toList();
        List<String> not = rows.stream().filter(f -> f.semantic().status() == FeatureStatus.NOT_REALISED
                || f.semantic().status() == FeatureStatus.PARTIAL).map(f -> f.id() + " " + f.semantic().passed()
                + "/" + f.semantic().total()).toList();
        return ids.size() + " of " + rows.size() + (table == 8 || ids.isEmpty() ? "" : ": " + String.join(", ", ids))
                + (not.isEmpty() ? "" : "; not realised: " + String.join(", ", not));
    }

    private Set<String> parseFeatures() throws CannotRun {
        for (String id : features) {
            if (Feature.byId(id.toUpperCase(Locale.ROOT)).isEmpty()) {
                throw new CannotRun("--feature: '" + id + "' is not a feature id (known ids: "
                        + Arrays.stream(Feature.values()).map(Feature::id).reduce((a, b) -> a + " " + b).orElse("")
                        + ")");
            }
        }
        return Set.copyOf(features);
    }

    private Corpus loadCorpus() throws CannotRun {
        Path dir = corpusDirectory();
        if (dir != null && !Files.isDirectory(dir)) {
            throw new CannotRun("corpus directory " + dir + " does not exist (use --corpus DIR)");
        }
        try {
            return dir != null ? Corpus.load(dir) : BundledCorpus.load();
        } catch (CorpusException e) {
            throw new CannotRun("the corpus cannot be used: " + e.getMessage());
        }
    }

    /** The run cannot be done; the message says why. */
    static final class CannotRun extends Exception {
        private static final long serialVersionUID = 1L;

        CannotRun(String message) {
            super(message);
        }
    }
}
