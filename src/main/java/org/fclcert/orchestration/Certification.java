package org.fclcert.orchestration;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import org.fclcert.corpus.BundledCorpus;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ReferenceExportCheck;
import org.fclcert.harness.Provenance;
import org.fclcert.harness.ResultSink;
import org.fclcert.harness.ResultsChain;
import org.fclcert.harness.RunSeed;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.ResultsWriter;
import org.fclcert.harness.RunCase;
import org.fclcert.harness.RunCases;
import org.fclcert.harness.RunHeader;
import org.fclcert.harness.RunHeaders;
import org.fclcert.harness.RunListener;
import org.fclcert.harness.Runner;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.RecordingIut;
import org.fclcert.iut.StopSignal;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.probe.Prober;
import org.fclcert.probe.Table11;
import org.fclcert.report.Origin;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;
import org.fclcert.report.ReportFiles;
import org.fclcert.syntax.dialect.Dialect;

/**
 * One certification run from start to finish: select the cases, start the implementation, run the cases
 * streaming {@code results.jsonl}, measure the Table 11 data check list if asked, write the four reports.
 * The only orchestration of a run: the front ends (the command line, the Maven plugin) parse their own
 * options into a {@link Request}, follow the run through a {@link RunListener} and {@link Hooks}, and
 * present the outcome. Nothing here prints.
 *
 * <p>It lives above {@code harness} (which runs the cases), {@code probe} (Table 11) and {@code report}
 * (verdicts and renderings), so that none of those three needs to know the others' flow
 * ({@code docs/architecture.md}).
 */
public final class Certification {
    private Certification() {
    }

    /**
     * What to certify. Build one with {@link #builder(String, Corpus)}: only the implementation and the
     * corpus are required, everything else has the default the command line uses.
     *
     * @param iutSpec     a spec of one of {@link org.fclcert.iut.Iuts#KINDS} ({@code reference}, {@code java:CLASS}, {@code fuzzylite[:PATH]}, ...)
     * @param options     timeouts, class path and the like for the implementation
     * @param classpath   the class path as the user wrote it, for the report (null when none)
     * @param corpus      the loaded corpus
     * @param corpusName  how the report names the corpus (its directory, or {@code bundled})
     * @param selection   which cases run
     * @param outDir      where results and reports go; null for {@code <reportsRoot>/<iut-name>}
     * @param reportsRoot parent of the default output directory ({@code fclcert-reports})
     * @param probe       how to measure the Table 11 data check list after the cases; null: not measured
     * @param filters     the filters as the user gave them (levels, features, case globs), for the report;
     *                    null to describe {@code selection}
     * @param presentAs   the semantic axis: in which library's layout positive cases are also sent (null: auto)
     * @param rerun       the front end's command that reruns one case, {@code {case}} for its id (null: the
     *                    command line's); the reports print it for every case that did not pass
     * @param budget      the time the whole run may take, the cases and the probes (null: {@link Defaults#RUN_BUDGET});
     *                    when it runs out the run is stopped, and the cases not run are reported as skipped with the
     *                    reason
     * @param seed        the run seed the fresh vectors and disguises are drawn from ({@code --seed}); null: drawn anew
     * @param freshEvidence false only to drive fclcert's own harness with fakes ({@code --no-fresh-evidence}): no seed,
     *                    no fresh vectors, no disguise, no check of a custom corpus; the results are unverifiable, their
     *                    Basic verdict "not determined", and report --verify, compare and fclcert:verify refuse them
     */
    public record Request(String iutSpec, IutOptions options, String classpath, Corpus corpus, String corpusName,
            CaseSelection selection, Path outDir, Path reportsRoot, Prober.Options probe,
            List<List<String>> filters, PresentAs presentAs, String rerun, Duration budget, Long seed,
            boolean freshEvidence) {

        public Request {
            budget = budget == null ? Defaults.RUN_BUDGET : budget;
            if (budget.isNegative() || budget.isZero()) {
                throw new IllegalArgumentException("the run budget must be positive: " + budget);
            }
            Objects.requireNonNull(iutSpec, "iutSpec");
            Objects.requireNonNull(options, "options");
            Objects.requireNonNull(corpus, "corpus");
            Objects.requireNonNull(corpusName, "corpusName");
            Objects.requireNonNull(selection, "selection");
            presentAs = presentAs == null ? PresentAs.AUTO : presentAs;
            if (outDir == null && reportsRoot == null) {
                throw new IllegalArgumentException("a request needs an output directory or a reports root");
            }
        }

        /** A request for {@code iutSpec} on {@code corpus}; the builder's setters change the defaults. */
        public static Builder builder(String iutSpec, Corpus corpus) {
            return new Builder(iutSpec, corpus);
        }

        private List<List<String>> filtersForReport() {
            if (filters != null) {
                return filters;
            }
            CaseSelection s = selection;
            return List.of(s.levels().stream().map(l -> l.word()).sorted().toList(),
                    s.features().stream().sorted().toList(), s.globs());
        }
    }

    /**
     * Builds a {@link Request}. Defaults: {@link IutOptions#defaults()}, no class path, the corpus named
     * {@code bundled}, every case, output to {@code fclcert-reports/<iut-name>}, no Table 11 probes, the filters
     * described from the selection.
     */
    public static final class Builder {
        private final String iutSpec;
        private final Corpus corpus;
        private IutOptions options = IutOptions.defaults();
        private String classpath;
        private String corpusName = BundledCorpus.NAME;
        private CaseSelection selection = CaseSelection.all();
        private Path outDir;
        private Path reportsRoot = DEFAULT_REPORTS_ROOT;
        private Prober.Options probe;
        private List<List<String>> filters;
        private PresentAs presentAs = PresentAs.AUTO;
        private String rerun;
        private Duration budget = Defaults.RUN_BUDGET;
        private Long seed;
        private boolean freshEvidence = true;

        private Builder(String iutSpec, Corpus corpus) {
            this.iutSpec = iutSpec;
            this.corpus = corpus;
        }

        /** Timeouts, class path and the like for opening the implementation. */
        public Builder options(IutOptions value) {
            options = value;
            return this;
        }

        /** The class path as the user wrote it, for the report. */
        public Builder classpath(String value) {
            classpath = value;
            return this;
        }

        /** How the report names the corpus: its directory, or {@code bundled}. */
        public Builder corpusName(String value) {
            corpusName = value;
            return this;
        }

        public Builder selection(CaseSelection value) {
            selection = value;
            return this;
        }

        /** The output directory itself (instead of {@code <reportsRoot>/<iut-name>}). */
        public Builder outDir(Path value) {
            outDir = value;
            return this;
        }

        /** The parent of the default output directory (default {@code fclcert-reports}). */
        public Builder reportsRoot(Path value) {
            reportsRoot = value;
            return this;
        }

        /** Measure the Table 11 data check list after the cases (null: do not). */
        public Builder probe(Prober.Options value) {
            probe = value;
            return this;
        }

        /** The filters as the user spelled them (levels, features, case globs), for the report. */
        public Builder filters(List<String> levels, List<String> features, List<String> cases) {
            filters = List.of(List.copyOf(levels), List.copyOf(features), List.copyOf(cases));
            return this;
        }

        /** The semantic axis ({@code --present-as}, default {@link PresentAs#AUTO}). */
        public Builder presentAs(PresentAs value) {
            presentAs = value;
            return this;
        }

        /** The front end's command that reruns one case, {@code {case}} standing for its id (default: the CLI's). */
        public Builder rerun(String value) {
            rerun = value;
            return this;
        }

        /** The time the whole run may take (default {@link Defaults#RUN_BUDGET}). */
        public Builder budget(Duration value) {
            budget = value;
            return this;
        }

        /** The run seed ({@code --seed}: replays a run's fresh vectors and disguises); null: drawn anew. */
        public Builder seed(Long value) {
            seed = value;
            return this;
        }

        /** False: run without fresh evidence (see {@link Request}); the results are unverifiable. */
        public Builder freshEvidence(boolean value) {
            freshEvidence = value;
            return this;
        }

        public Request build() {
            return new Request(iutSpec, options, classpath, corpus, corpusName, selection, outDir, reportsRoot,
                    probe, filters, presentAs, rerun, budget, seed, freshEvidence);
        }
    }

    /**
     * The parent of the default output directory: {@code fclcert-reports/} of the working directory, which
     * git ignores, so that a run never overwrites the committed {@code reports/} (scripts/regenerate-reports
     * writes those with an explicit output directory).
     */
    public static final Path DEFAULT_REPORTS_ROOT = Path.of("fclcert-reports");

    /**
     * The parent of the default output directory of a run of selected cases ({@code --case}): a directory
     * of the system's temporary directory, so that reproducing a failure writes nothing into a checkout; private to
     * the user ({@code fclcert-reports-<user>}, mode 700, never a link: {@link OutputDirectory#privateScratch}).
     */
    public static Path scratchReportsRoot() throws IOException {
        return OutputDirectory.privateScratch(Path.of(System.getProperty("java.io.tmpdir")),
                System.getProperty("user.name"));
    }

    /** Where a case that did not pass leaves its protocol transcript, relative to the output directory. */
    public static final String TRANSCRIPTS = "requests";

    /** The transcript file of case {@code id} in {@code directory}: {@code requests/<id>.requests.jsonl}. */
    public static Path transcriptFile(Path directory, String id) {
        return directory.resolve(TRANSCRIPTS).resolve(id.replaceAll("[^A-Za-z0-9._-]+", "-") + ".requests.jsonl");
    }

    /** The longest default directory name: well below every file system's 255-byte limit on a name. */
    public static final int MAX_DIRECTORY_NAME = 64;

    /**
     * The finished run: its report and the directory holding the files; {@code stopped} is why the run was stopped
     * before its end (Ctrl-C, the run budget), null when it ran to the end.
     */
    public record Outcome(Report report, Path directory, String stopped) {
    }

    /** The run could not be done (implementation would not start, nothing selected, files not writable). */
    public static class CannotCertify extends Exception {
        private static final long serialVersionUID = 1L;

        public CannotCertify(String message) {
            super(message);
        }
    }

    /** No case of the corpus matches the selection (front ends may word this their own way). */
    public static final class NothingSelected extends CannotCertify {
        private static final long serialVersionUID = 1L;

        NothingSelected(String corpusName) {
            super("no case of the corpus " + corpusName + " matches the selection");
        }
    }

    /**
     * What a front end may want to hear of a run besides the cases' progress; every method does nothing
     * by default. The command line uses them for its probe progress and to report a run cut short by Ctrl-C.
     */
    public interface Hooks {
        Hooks NONE = new Hooks() {
        };

        /**
         * The cases are about to run on {@code iut}; their outputs end up in {@code directory}, and until the run
         * ends its results stream to {@code resultsFile} in the run's private sibling of it (where they stay when the
         * run is cut off before its end).
         */
        default void started(ImplementationUnderTest iut, Path directory, Path resultsFile) {
        }

        /** The last selected case has run (the Table 11 probes, if any, come next). */
        default void casesFinished() {
        }

        /** The Table 11 probes reached {@code row}, the {@code index}th of {@code total}. */
        default void probing(Table11 row, int index, int total) {
        }

        /** The results file is complete; the reports are built and written next. */
        default void resultsComplete() {
        }
    }

    /** The name of the results file in the output directory. */
    public static final String RESULTS = ResultsWriter.FILE_NAME;

    public static Outcome run(Request request, RunListener listener) throws CannotCertify {
        return run(request, listener, Hooks.NONE);
    }

    public static Outcome run(Request request, RunListener listener, Hooks hooks) throws CannotCertify {
        return run(request, listener, hooks, new RunControl());
    }

    /**
     * As {@link #run(Request, RunListener, Hooks)}, stoppable from another thread through {@code control} (the
     * command line's Ctrl-C); the run budget stops it too. A stopped run records the case under way and every later
     * case as skipped ({@link Runner#STOPPED} and the reason), measures no more Table 11 rows, writes the reports
     * and closes the implementation, and its outcome says why it stopped.
     */
    public static Outcome run(Request request, RunListener listener, Hooks hooks, RunControl control)
            throws CannotCertify {
        StopSignal stop = control.signal;
        long deadline = System.nanoTime() + request.budget().toNanos();
        try (StopSignal.Timing budget = stop.stopAfter(request.budget(),
                StopSignal.budgetRanOut("run", request.budget()))) {
            List<RunCase> all = RunCases.from(request.corpus().cases());
            List<RunCase> selected = request.selection().apply(all);
            if (selected.isEmpty()) {
                throw new NothingSelected(request.corpusName());
            }
            Provenance.CorpusIdentity corpusIdentity = request.freshEvidence() ? CorpusCheck.identify(request.corpus()) : null;
            long seed = request.seed() != null ? request.seed() : RunSeed.fresh();
            // an explicit output directory is locked before the implementation starts: a second run refuses at once
            try (OutputDirectory claimed = request.outDir() != null ? OutputDirectory.claim(request.outDir()) : null;
                    ImplementationUnderTest iut = stop.guard(open(request))) {
                IutInfo info = hello(iut, request.iutSpec());
                RunHeader plain = RunHeaders.of(info, request.iutSpec(), request.classpath(), request.corpusName(),
                        request.corpus().sha256(), all, selected, request.filtersForReport(), request.rerun())
                        .withProvenance(request.freshEvidence() ? Provenance.of(seed, info, request.iutSpec(),
                                request.options().classpath(), corpusIdentity) : null);
                RunHeader header = request.presentAs().resolve(request.iutSpec())
                        .map(d -> plain.presentedAs(d.cliName())).orElse(plain).withIsolation(iut.isolation());
                Path dir = request.outDir() != null ? request.outDir()
                        : request.reportsRoot().resolve(defaultDirectoryName(request.iutSpec(), info.name()));
                try (OutputDirectory late = claimed == null ? OutputDirectory.claim(dir) : null) {
                    return runAndReport(request, iut, header, selected, claimed != null ? claimed : late, listener,
                            hooks, control, deadline);
                }
            }
        } finally {
            control.ended();
        }
    }

    private static Outcome runAndReport(Request request, ImplementationUnderTest iut, RunHeader header,
            List<RunCase> selected, OutputDirectory out, RunListener listener, Hooks hooks, RunControl control,
            long deadline) throws CannotCertify {
        // everything is written into the run's private sibling and moved into place at the end
        Path dir = out.staging();
        Path resultsFile = dir.resolve(RESULTS);
        StopSignal stop = control.signal;
        try (ResultsWriter results = ResultsWriter.create(resultsFile)) {
            ResultSink sink = control.guard(results);
            hooks.started(iut, out.target(), resultsFile);
            Dialect layout = request.presentAs().resolve(request.iutSpec()).orElse(null);
            RecordingIut recording = new RecordingIut(iut);
            Runner runner = new Runner(new ReferenceExportCheck(), new Transcripts(recording, dir, listener), layout);
            if (header.provenance() != null) {
                runner.withSeed(RunSeed.parse(header.provenance().seed()));
            }
            List<CaseResult> done = runner.run(recording, header, selected, sink, stop);
            hooks.casesFinished();
            List<DataCheckEntry> dataCheckList = List.of();
            if (request.probe() != null) {
                long left = deadline - System.nanoTime();
                dataCheckList = stop.stopped() || left < 1_000_000
                        ? Prober.notMeasured("not measured: the run was stopped: " + (stop.stopped() ? stop.reason()
                                : StopSignal.budgetRanOut("run", request.budget())))
                        : dataCheckList(request, hooks::probing, stop, Duration.ofNanos(left));
                sink.dataCheckList(dataCheckList);
            }
            // a stop from here on finds every case run: it waits for the reports, and the run is complete
            String stopped = stop.reason();
            ResultsChain.Seal[] seal = {null};
            control.write(() -> seal[0] = results.finish(Instant.now().toString()));
            hooks.resultsComplete();
            Report report = Origin.apply(ReportBuilder.build(header, done, List.of(), dataCheckList, Instant.now()),
                    header.provenance(), seal[0], Origin.JUDGED_LIVE, List.of());
            control.write(() -> {
                ReportFiles.writeAll(report, dir);
                out.publish(EARLIER_OUTPUTS, TRANSCRIPTS);
            });
            return new Outcome(report, out.target(), stopped);
        } catch (IOException e) {
            throw new CannotCertify("cannot write the results or reports in " + dir + ": " + e.getMessage());
        }
    }

    /**
     * The outputs of an earlier run in the output directory that a run replaces (with the transcripts): none of them
     * may stay beside the new run's results.
     */
    private static final List<String> EARLIER_OUTPUTS = List.of(RESULTS, ReportFiles.JSON, ReportFiles.MARKDOWN,
            ReportFiles.HTML, ReportFiles.JUNIT);

    /**
     * Writes, for each case that does not pass, the protocol requests it made ({@link #transcriptFile}), so
     * that the case can be replayed by hand: {@code python3 my_iut.py < requests/ID.requests.jsonl}.
     */
    private static final class Transcripts implements RunListener {
        private final RecordingIut recording;
        private final Path dir;
        private final RunListener next;

        Transcripts(RecordingIut recording, Path dir, RunListener next) {
            this.recording = recording;
            this.dir = dir;
            this.next = next;
        }

        @Override
        public void caseStarted(RunCase c, int index, int total) {
            recording.clear();
            next.caseStarted(c, index, total);
        }

        @Override
        public void caseFinished(CaseResult result, int index, int total) {
            if (result.status() == CaseStatus.FAILED || result.status() == CaseStatus.ERRORED) {
                Path file = transcriptFile(dir, result.id());
                try {
                    Files.createDirectories(file.getParent());
                    Files.writeString(file, recording.transcript());
                } catch (IOException e) {
                    // a transcript is a convenience: the case's result is in results.jsonl either way
                }
            }
            next.caseFinished(result, index, total);
        }
    }

    /**
     * Builds and writes the four reports from a results file read back: {@code fclcert report --from}, and
     * a run cut short (the cases it planned but did not finish are reported as skipped).
     */
    public static Report rebuildReports(ResultsFile results, Path dir) throws IOException {
        Report report = ReportBuilder.build(results, Instant.now());
        ReportFiles.writeAll(report, dir);
        return report;
    }

    /**
     * The Table 11 data check list of the request's implementation, measured on fresh sessions of it
     * (empty when the request asks for none). An implementation that cannot be probed gets every row
     * "not measured" with the reason, so that the certification itself still stands.
     */
    public static List<DataCheckEntry> dataCheckList(Request request, Prober.Listener listener) {
        return dataCheckList(request, listener, null, request.budget());
    }

    /** As {@link #dataCheckList(Request, Prober.Listener)}, stopped by {@code stop}, within at most {@code left}. */
    private static List<DataCheckEntry> dataCheckList(Request request, Prober.Listener listener, StopSignal stop,
            Duration left) {
        if (request.probe() == null) {
            return List.of();
        }
        Prober.Options options = request.probe().budget().compareTo(left) <= 0 ? request.probe()
                : request.probe().withBudget(left);
        try {
            return Prober.probe(() -> Iuts.open(request.iutSpec(), request.options()), options, listener, stop);
        } catch (IutException e) {
            return Prober.notMeasured("the implementation could not be probed: " + e.getMessage());
        }
    }

    /**
     * The name of the default output directory: {@code reference} for fclcert's own evaluator, else the
     * implementation's name in lower case with runs of anything but letters, digits, '.', '_' and '-'
     * turned into one '-', cut to {@link #MAX_DIRECTORY_NAME} characters ({@code iut} when nothing is left).
     */
    public static String defaultDirectoryName(String spec, String name) {
        if (spec.strip().equals("reference")) {
            return "reference";
        }
        String cleaned = (name == null ? "" : name).toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9._-]+", "-")
                .replaceAll("^[-.]+|-+$", "");
        if (cleaned.length() > MAX_DIRECTORY_NAME) {
            cleaned = cleaned.substring(0, MAX_DIRECTORY_NAME).replaceAll("[-.]+$", "");
        }
        return cleaned.isEmpty() ? "iut" : cleaned;
    }

    private static ImplementationUnderTest open(Request request) throws CannotCertify {
        try {
            // the outputs and the corpus stay hidden from a sandboxed implementation, even where its command names
            // them or they lie inside the bound system
            Path corpusDir = request.corpusName().equals(BundledCorpus.NAME) ? null : Path.of(request.corpusName());
            List<Path> outputs = java.util.stream.Stream.of(request.outDir(), request.reportsRoot(), corpusDir)
                    .filter(java.util.Objects::nonNull).toList();
            return Iuts.open(request.iutSpec(), request.options()
                    .withSandbox(request.options().sandbox().hiding(outputs)));
        } catch (IutException e) {
            throw new CannotCertify("cannot start the implementation '" + request.iutSpec() + "': " + e.getMessage()
                    + tail(e.stderrTail()));
        }
    }

    private static IutInfo hello(ImplementationUnderTest iut, String spec) throws CannotCertify {
        try {
            return iut.hello();
        } catch (IutException e) {
            if (e.kind() == IutException.Kind.STOPPED) {
                throw new CannotCertify("the run was stopped before the implementation '" + spec + "' answered hello: "
                        + e.getMessage());
            }
            throw new CannotCertify("the implementation '" + spec + "' did not answer hello: " + e.getMessage()
                    + tail(e.stderrTail()));
        }
    }

    private static String tail(String stderrTail) {
        return stderrTail == null || stderrTail.isBlank() ? "" : "\n--- its stderr ---\n" + stderrTail.strip();
    }
}
