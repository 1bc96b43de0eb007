package org.fclcert.harness;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import org.fclcert.corpus.Corpus;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.probe.Prober;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;
import org.fclcert.report.ReportFiles;

/**
 * One certification run from start to finish: start the implementation, run the selected cases,
 * stream {@code results.jsonl}, write the four reports. Front ends (the command line, the Maven
 * plugin) parse their own options into a {@link Request} and present the outcome.
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
     */
    public record Request(String iutSpec, IutOptions options, String classpath, Corpus corpus, String corpusName,
            CaseSelection selection, Path outDir, Path reportsRoot, Prober.Options probe) {

        /** A run without the data check list. */
        public Request(String iutSpec, IutOptions options, String classpath, Corpus corpus, String corpusName,
                CaseSelection selection, Path outDir, Path reportsRoot) {
            this(iutSpec, options, classpath, corpus, corpusName, selection, outDir, reportsRoot, null);
        }
    }

    /** The finished run: its report and the directory holding the files. */
    public record Outcome(Report report, Path directory) {
    }

    /** The run could not be done (implementation would not start, nothing selected, files not writable). */
    public static final class CannotCertify extends Exception {
        private static final long serialVersionUID = 1L;

        public CannotCertify(String message) {
            super(message);
        }
    }

    public static Outcome run(Request request, RunListener listener) throws CannotCertify {
        List<RunCase> all = RunCases.from(request.corpus().cases());
        List<RunCase> selected = request.selection().apply(all);
        if (selected.isEmpty()) {
            throw new CannotCertify("no case of the corpus " + request.corpusName() + " matches the selection");
        }
        try (ImplementationUnderTest iut = open(request)) {
            IutInfo info = hello(iut, request.iutSpec());
            CaseSelection s = request.selection();
            RunHeader header = RunHeaders.of(info, request.iutSpec(), request.classpath(), request.corpusName(),
                    request.corpus().sha256(), all, selected,
                    List.of(s.levels().stream().map(l -> l.word()).sorted().toList(),
                            s.features().stream().sorted().toList(), s.globs()));
            Path dir = request.outDir() != null ? request.outDir()
                    : request.reportsRoot().resolve(defaultDirectoryName(request.iutSpec(), info.name()));
            return new Outcome(runAndReport(iut, header, selected, dir, listener,
                    () -> dataCheckList(request, Prober.Listener.NONE)), dir);
        }
    }

    private static Report runAndReport(ImplementationUnderTest iut, RunHeader header, List<RunCase> selected,
            Path dir, RunListener listener, Supplier<List<DataCheckEntry>> probe) throws CannotCertify {
        try (ResultsWriter results = ResultsWriter.create(dir.resolve("results.jsonl"))) {
            List<CaseResult> done = new Runner(listener).run(iut, header, selected, results);
            List<DataCheckEntry> dataCheckList = probe.get();
            if (!dataCheckList.isEmpty()) {
                results.dataCheckList(dataCheckList);
            }
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

    /** {@code reference} for fclcert's own evaluator, else the implementation's name made file-safe. */
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
