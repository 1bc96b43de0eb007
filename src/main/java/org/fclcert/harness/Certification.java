package org.fclcert.harness;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import org.fclcert.corpus.Corpus;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.probe.Prober;
import org.fclcert.probe.Table11;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;
import org.fclcert.report.ReportFiles;

/**
 * One certification run from start to finish: select the cases, start the implementation, run the cases
 * streaming {@code results.jsonl}, measure the Table 11 data check list if asked, write the four reports.
 * The only orchestration of a run: the front ends (the command line, the Maven plugin) parse their own
 * options into a {@link Request}, follow the run through a {@link RunListener} and {@link Hooks}, and
 * present the outcome. Nothing here prints.
 */
public final class Certification {
    private Certification() {
    }

    /**
     * What to certify.
     *
     * @param iutSpec   {@code reference}, {@code java:CLASS} or {@code process:COMMAND}
     * @param options   timeouts, class path and the like for the implementation
     * @param classpath the class path as the user wrote it, for the report (null when none)
     * @param corpus    the loaded corpus
     * @param corpusName how the report names the corpus (its directory, or {@code bundled})
     * @param selection which cases run
     * @param outDir    where results and reports go; null for {@code <reportsRoot>/<iut-name>}
     * @param reportsRoot parent of the default output directory
     * @param probe     how to measure the Table 11 data check list after the cases; null: not measured
     * @param filters   the filters as the user gave them (levels, features, case globs), for the report;
     *                  null to describe {@code selection}
     */
    public record Request(String iutSpec, IutOptions options, String classpath, Corpus corpus, String corpusName,
            CaseSelection selection, Path outDir, Path reportsRoot, Prober.Options probe,
            List<List<String>> filters) {

        /** A run whose report describes the selection itself. */
        public Request(String iutSpec, IutOptions options, String classpath, Corpus corpus, String corpusName,
                CaseSelection selection, Path outDir, Path reportsRoot, Prober.Options probe) {
            this(iutSpec, options, classpath, corpus, corpusName, selection, outDir, reportsRoot, probe, null);
        }

        /** A run without the data check list. */
        public Request(String iutSpec, IutOptions options, String classpath, Corpus corpus, String corpusName,
                CaseSelection selection, Path outDir, Path reportsRoot) {
            this(iutSpec, options, classpath, corpus, corpusName, selection, outDir, reportsRoot, null);
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

    /** The finished run: its report and the directory holding the files. */
    public record Outcome(Report report, Path directory) {
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

        /** The cases are about to run on {@code iut}; their results stream to {@code resultsFile} in {@code directory}. */
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
    public static final String RESULTS = "results.jsonl";

    public static Outcome run(Request request, RunListener listener) throws CannotCertify {
        return run(request, listener, Hooks.NONE);
    }

    public static Outcome run(Request request, RunListener listener, Hooks hooks) throws CannotCertify {
        List<RunCase> all = RunCases.from(request.corpus().cases());
        List<RunCase> selected = request.selection().apply(all);
        if (selected.isEmpty()) {
            throw new NothingSelected(request.corpusName());
        }
        try (ImplementationUnderTest iut = open(request)) {
            IutInfo info = hello(iut, request.iutSpec());
            RunHeader header = RunHeaders.of(info, request.iutSpec(), request.classpath(), request.corpusName(),
                    request.corpus().sha256(), all, selected, request.filtersForReport());
            Path dir = request.outDir() != null ? request.outDir()
                    : request.reportsRoot().resolve(defaultDirectoryName(request.iutSpec(), info.name()));
            return new Outcome(runAndReport(request, iut, header, selected, dir, listener, hooks), dir);
        }
    }

    private static Report runAndReport(Request request, ImplementationUnderTest iut, RunHeader header,
            List<RunCase> selected, Path dir, RunListener listener, Hooks hooks) throws CannotCertify {
        Path resultsFile = dir.resolve(RESULTS);
        try (ResultsWriter results = ResultsWriter.create(resultsFile)) {
            hooks.started(iut, dir, resultsFile);
            List<CaseResult> done = new Runner(listener).run(iut, header, selected, results);
            hooks.casesFinished();
            List<DataCheckEntry> dataCheckList = List.of();
            if (request.probe() != null) {
                dataCheckList = dataCheckList(request, hooks::probing);
                results.dataCheckList(dataCheckList);
            }
            hooks.resultsComplete();
            Report report = ReportBuilder.build(header, done, List.of(), dataCheckList, Instant.now());
            ReportFiles.writeAll(report, dir);
            return report;
        } catch (IOException e) {
            throw new CannotCertify("cannot write the results or reports in " + dir + ": " + e.getMessage());
        }
    }

    /**
     * The Table 11 data check list of the request's implementation, measured on fresh sessions of it
     * (empty when the request asks for none). An implementation that cannot be probed gets every row
     * "not measured" with the reason, so that the certification itself still stands.
     */
    public static List<DataCheckEntry> dataCheckList(Request request, Prober.Listener listener) {
        if (request.probe() == null) {
            return List.of();
        }
        try {
            return Prober.probe(() -> Iuts.open(request.iutSpec(), request.options()), request.probe(), listener);
        } catch (IutException e) {
            return Prober.notMeasured("the implementation could not be probed: " + e.getMessage());
        }
    }

    /**
     * The name of the default output directory: {@code reference} for fclcert's own evaluator, else the
     * implementation's name in lower case with runs of anything but letters, digits, '.', '_' and '-'
     * turned into one '-' ({@code iut} when nothing is left).
     */
    public static String defaultDirectoryName(String spec, String name) {
        if (spec.strip().equals("reference")) {
            return "reference";
        }
        String cleaned = (name == null ? "" : name).toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9._-]+", "-")
                .replaceAll("^[-.]+|-+$", "");
        return cleaned.isEmpty() ? "iut" : cleaned;
    }

    private static ImplementationUnderTest open(Request request) throws CannotCertify {
        try {
            return Iuts.open(request.iutSpec(), request.options());
        } catch (IutException e) {
            throw new CannotCertify("cannot start the implementation '" + request.iutSpec() + "': " + e.getMessage()
                    + tail(e.stderrTail()));
        }
    }

    private static IutInfo hello(ImplementationUnderTest iut, String spec) throws CannotCertify {
        try {
            return iut.hello();
        } catch (IutException e) {
            throw new CannotCertify("the implementation '" + spec + "' did not answer hello: " + e.getMessage()
                    + tail(e.stderrTail()));
        }
    }

    private static String tail(String stderrTail) {
        return stderrTail == null || stderrTail.isBlank() ? "" : "\n--- its stderr ---\n" + stderrTail.strip();
    }
}
