package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import org.fclcert.corpus.BundledCorpus;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusException;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.ResultsWriter;
import org.fclcert.harness.RunCase;
import org.fclcert.harness.RunCases;
import org.fclcert.harness.RunHeader;
import org.fclcert.harness.RunHeaders;
import org.fclcert.harness.Runner;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.probe.Prober;
import org.fclcert.report.FailOn;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;
import org.fclcert.report.ReportFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fclcert certify}: runs the conformance corpus against an implementation and writes the reports. */
@Command(name = "certify", mixinStandardHelpOptions = true,
        description = {"Run the conformance corpus against an implementation under test and write the compliance "
                + "statement (report.json, report.md, report.html, junit.xml) and results.jsonl.",
            "Exit 0: the run completed and --fail-on holds; 1: it does not hold; 2: the run could not be done."})
final class CertifyCommand implements Callable<Integer> {
    static final int OK = ExitCodes.OK;
    static final int FAILED = ExitCodes.ERRORS;
    static final int CANNOT_RUN = ExitCodes.USAGE;

    @Spec
    CommandSpec spec;

    @Option(names = "--iut", paramLabel = "SPEC", defaultValue = "reference",
            description = "reference | java:CLASS | process:COMMAND | fuzzylite[:PATH] (default: ${DEFAULT-VALUE})")
    String iut;

    @Option(names = "--classpath", paramLabel = "PATHS", description = "Where java:CLASS is found (jars or directories, separated as the platform's class path)")
    String classpath;

    @Option(names = "--corpus", paramLabel = "DIR",
            description = "Corpus directory (default: conformance/ when the current directory has one, else the"
                    + " corpus bundled in fclcert)")
    Path corpus;

    /** The corpus of a checkout of this repository, used when the command runs at its root. */
    private static final Path DEFAULT_CORPUS = Path.of("conformance");

    /** How the run names its corpus: the directory given or found, or {@code bundled}. */
    private String corpusName() {
        return corpus != null ? corpus.toString() : BundledCorpus.NAME;
    }

    @Option(names = "--out", paramLabel = "DIR",
            description = "Output directory (default: reports/reference for the reference, else reports/<iut-name>)")
    Path out;

    @Option(names = "--level", paramLabel = "LEVEL", split = ",",
            description = "Only cases of these levels: basic, extension, open")
    List<String> levels = new ArrayList<>();

    @Option(names = "--feature", paramLabel = "ID", arity = "1..*",
            description = "Only cases that are evidence for these feature ids (e.g. E-ACCU-NSUM)")
    List<String> features = new ArrayList<>();

    @Option(names = "--case", paramLabel = "GLOB", arity = "1..*",
            description = "Only cases whose id matches one of these globs (e.g. 'B-COGS-*')")
    List<String> cases = new ArrayList<>();

    @Option(names = "--timeout", paramLabel = "DURATION", defaultValue = "5s",
            description = "Per-request timeout for the implementation, e.g. 5s, 500ms (default: ${DEFAULT-VALUE})")
    String timeout;

    @Option(names = "--fail-on", paramLabel = "WHAT", defaultValue = "none",
            description = "none | basic | claimed | any: exit 1 when this does not hold (default: ${DEFAULT-VALUE})")
    String failOn;

    @Option(names = "--no-probe", description = "Do not measure the Table 11 data check list")
    boolean noProbe;

    @Option(names = "--probe-cap", paramLabel = "N", defaultValue = "4096",
            description = "Largest size the Table 11 probes try (default: ${DEFAULT-VALUE}; fclcert probe uses 100000)")
    long probeCap;

    @Option(names = "--probe-budget", paramLabel = "DURATION", defaultValue = "3m",
            description = "Time budget of the Table 11 probes (default: ${DEFAULT-VALUE})")
    String probeBudget;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            return certify(spec.commandLine().getOut(), err);
        } catch (CannotRun e) {
            err.println("fclcert certify: " + e.getMessage());
            err.flush();
            return CANNOT_RUN;
        }
    }

    private int certify(PrintWriter stdout, PrintWriter err) throws CannotRun {
        FailOn condition = parseFailOn();
        CaseSelection selection = new CaseSelection(parseLevels(), parseFeatures(), cases);
        Duration requestTimeout = Durations.parse(timeout).orElseThrow(() -> new CannotRun(
                "--timeout: '" + timeout + "' is not a duration (write e.g. 5s, 500ms or 2m)"));
        Duration budget = Durations.parse(probeBudget).filter(d -> !d.isZero()).orElseThrow(() -> new CannotRun(
                "--probe-budget: '" + probeBudget + "' is not a duration (write e.g. 3m, 90s)"));
        if (probeCap < 1) {
            throw new CannotRun("--probe-cap must be at least 1, not " + probeCap);
        }
        Prober.Options probe = noProbe ? null : new Prober.Options(probeCap, budget, Set.of());
        Corpus loaded = loadCorpus();
        List<RunCase> all = RunCases.from(loaded.cases());
        List<RunCase> selected = selection.apply(all);
        if (selected.isEmpty()) {
            throw new CannotRun("no case of " + corpusName() + " matches the selection");
        }
        IutOptions options = IutArguments.options(requestTimeout, classpath);
        try (ImplementationUnderTest impl = open(options)) {
            IutInfo info = hello(impl);
            RunHeader header = RunHeaders.of(info, iut, classpath, corpusName(), loaded.sha256(), all, selected,
                    List.of(levels, features, cases));
            Path dir = out != null ? out : Path.of("reports", OutDirs.forIut(iut, info.name()));
            Report report = run(impl, header, selected, dir, err, probe, options);
            print(stdout, report, dir);
            if (!condition.holds(report)) {
                err.println("fclcert certify: --fail-on " + failOn + ": " + condition.explain(report));
                err.flush();
                return FAILED;
            }
            return OK;
        }
    }

    private Report run(ImplementationUnderTest impl, RunHeader header, List<RunCase> selected, Path dir,
            PrintWriter err, Prober.Options probe, IutOptions options) throws CannotRun {
        Path resultsFile = dir.resolve("results.jsonl");
        Thread onInterrupt = new Thread(() -> reportInterruptedRun(impl, resultsFile, dir, err));
        try (ResultsWriter results = ResultsWriter.create(resultsFile)) {
            ProgressLine progress = new ProgressLine(err, System.console() != null);
            Runtime.getRuntime().addShutdownHook(onInterrupt);
            List<CaseResult> done = new Runner(progress).run(impl, header, selected, results);
            progress.finish();
            List<DataCheckEntry> dataCheckList = List.of();
            if (probe != null) {
                dataCheckList = dataCheckList(probe, options, err);
                results.dataCheckList(dataCheckList);
            }
            Runtime.getRuntime().removeShutdownHook(onInterrupt);
            Report report = ReportBuilder.build(header, done, List.of(), dataCheckList, Instant.now());
            ReportFiles.writeAll(report, dir);
            return report;
        } catch (IOException e) {
            throw new CannotRun("cannot write the results or reports in " + dir + ": " + e.getMessage());
        }
    }

    /**
     * Ctrl-C or a kill during the run: the results of the finished cases are on disk already; make the
     * reports from them (the cases not run show as skipped) and stop the implementation.
     */
    private static void reportInterruptedRun(ImplementationUnderTest impl, Path resultsFile, Path dir,
            PrintWriter err) {
        try {
            Report report = ReportBuilder.build(ResultsFile.read(resultsFile), Instant.now());
            ReportFiles.writeAll(report, dir);
            err.println();
            err.println("fclcert certify: interrupted after " + (report.summary().cases() - report.summary().skipped())
                    + " of " + report.summary().cases() + " cases; reports of what was done are in " + dir);
        } catch (IOException | ResultsFile.InvalidResultsException | RuntimeException e) {
            err.println("fclcert certify: interrupted; the results so far are in " + resultsFile
                    + " ('fclcert report --from " + resultsFile + "' makes the reports)");
        } finally {
            err.flush();
            impl.close();
        }
    }

    private static void print(PrintWriter out, Report r, Path dir) {
        Report.Summary s = r.summary();
        out.println(r.iut().name() + " " + r.iut().version() + ": " + s.cases() + " cases, " + s.passed()
                + " passed, " + s.failed() + " failed, " + s.errored() + " errored, " + s.skipped() + " skipped");
        if (r.rejections().doubtful()) {
            out.println("Negative cases: " + r.rejections().sentence());
        }
        out.println("Basic Level: " + (r.basicLevel().conformant() ? "conformant" : "not conformant") + " ("
                + r.basicLevel().reason() + ")");
        out.println("Standard Extensions realised (Table 9): " + realised(r, 9));
        out.println("Open Level features realised (Table 10): " + realised(r, 10));
        if (!r.claims().notRealised().isEmpty()) {
            out.println("Claimed but not realised: " + String.join(", ", r.claims().notRealised()));
        }
        out.println("Reports: " + dir.resolve(ReportFiles.MARKDOWN) + ", " + ReportFiles.HTML + ", "
                + ReportFiles.JSON + ", " + ReportFiles.JUNIT + ", results.jsonl");
        out.flush();
    }

    /** {@code 3 of 25: E-NOT, E-COG, E-LM} or {@code 0 of 3} (the report has no rows for dialect-syntax features). */
    private static String realised(Report r, int table) {
        List<String> ids = r.features().stream().filter(f -> f.table() == table && f.status() == FeatureStatus.REALISED)
                .map(Report.FeatureRow::id).toList();
        long rows = r.features().stream().filter(f -> f.table() == table).count();
        return ids.size() + " of " + rows + (ids.isEmpty() ? "" : ": " + String.join(", ", ids));
    }

    private FailOn parseFailOn() throws CannotRun {
        try {
            return FailOn.byWord(failOn);
        } catch (IllegalArgumentException e) {
            throw new CannotRun("--fail-on: '" + failOn + "' is not one of none, basic, claimed, any");
        }
    }

    private Set<ConformanceLevel> parseLevels() throws CannotRun {
        Set<ConformanceLevel> set = EnumSet.noneOf(ConformanceLevel.class);
        for (String level : levels) {
            try {
                set.add(ConformanceLevel.byWord(level.trim()));
            } catch (IllegalArgumentException e) {
                throw new CannotRun("--level: '" + level + "' is not one of basic, extension, open");
            }
        }
        return set;
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
        if (corpus == null && Files.isDirectory(DEFAULT_CORPUS)) {
            corpus = DEFAULT_CORPUS;
        }
        if (corpus != null && !Files.isDirectory(corpus)) {
            throw new CannotRun("corpus directory " + corpus + " does not exist (use --corpus DIR)");
        }
        try {
            return corpus != null ? Corpus.load(corpus) : BundledCorpus.load();
        } catch (CorpusException e) {
            throw new CannotRun("the corpus cannot be used: " + e.getMessage());
        }
    }

    /** The Table 11 probes on fresh sessions of the implementation, after the cases. */
    private List<DataCheckEntry> dataCheckList(Prober.Options probe, IutOptions options, PrintWriter err) {
        boolean terminal = System.console() != null;
        try {
            List<DataCheckEntry> list = Prober.probe(() -> Iuts.open(iut, options), probe, (row, index, count) -> {
                if (terminal) {
                    err.print("\r\u001b[Kprobing Table 11, " + index + "/" + count + ": " + row.id());
                    err.flush();
                }
            });
            if (terminal) {
                err.print("\r\u001b[K");
                err.flush();
            }
            return list;
        } catch (IutException e) {
            return Prober.notMeasured("the implementation could not be probed: " + e.getMessage());
        }
    }

    private ImplementationUnderTest open(IutOptions options) throws CannotRun {
        try {
            return Iuts.open(iut, options);
        } catch (IutException e) {
            throw new CannotRun("cannot start the implementation '" + iut + "': " + e.getMessage()
                    + IutArguments.stderrTail(e));
        }
    }

    private IutInfo hello(ImplementationUnderTest impl) throws CannotRun {
        try {
            return impl.hello();
        } catch (IutException e) {
            throw new CannotRun("the implementation '" + iut + "' did not answer hello: " + e.getMessage()
                    + IutArguments.stderrTail(e));
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
