package org.fclcert.maven;

import java.io.File;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.apache.maven.artifact.DependencyResolutionRequiredException;
import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.apache.maven.plugins.annotations.ResolutionScope;
import org.apache.maven.project.MavenProject;
import org.fclcert.corpus.BundledCorpus;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusException;
import org.fclcert.harness.CaseSelection;
import org.fclcert.harness.RunHeader;
import org.fclcert.probe.Prober;
import org.fclcert.iut.IutOptions;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.orchestration.Certification;
import org.fclcert.orchestration.Defaults;
import org.fclcert.orchestration.PresentAs;
import org.fclcert.report.JunitReport;
import org.fclcert.report.Report;
import org.fclcert.report.ReportFiles;
import org.fclcert.report.Tally;

/**
 * Runs the conformance corpus against an implementation under test and writes the reports to
 * {@code target/fclcert-reports}. Like Failsafe's integration-test goal it never fails the build on
 * results ({@code fclcert:verify} decides); only a run that cannot be done fails here.
 */
@Mojo(name = "certify", defaultPhase = LifecyclePhase.INTEGRATION_TEST, threadSafe = true,
        requiresDependencyResolution = ResolutionScope.TEST)
public class CertifyMojo extends AbstractMojo {
    /**
     * The implementation: any spec {@code fclcert certify --iut} takes (the list is {@code org.fclcert.iut.Iuts.KINDS};
     * an unknown spec is refused with that list): {@code reference}, {@code java:CLASS} (found on the project's test
     * class path), {@code process:COMMAND}, or a built-in library adapter such as {@code fuzzylite[:PATH]}.
     */
    @Parameter(property = "fclcert.iut", required = true)
    private String iut;

    /** A corpus directory; by default the corpus bundled with this plugin. */
    @Parameter(property = "fclcert.corpus")
    private File corpusDirectory;

    /** Where results.jsonl and the four reports go. */
    @Parameter(property = "fclcert.reportsDirectory", defaultValue = "${project.build.directory}/fclcert-reports")
    private File reportsDirectory;

    /**
     * Where the JUnit results also go as {@code TEST-fclcert.xml}, one testcase per case, class per feature row:
     * Surefire's directory by default, so that CI servers and the surefire-report plugin find them as they are.
     */
    @Parameter(property = "fclcert.junitDirectory", defaultValue = "${project.build.directory}/surefire-reports")
    private File junitDirectory;

    /** Only cases of these levels (basic, extension, open); all when empty. */
    @Parameter(property = "fclcert.levels")
    private List<String> levels;

    /** Only cases that are evidence for these feature ids; all when empty. */
    @Parameter(property = "fclcert.features")
    private List<String> features;

    /** Only cases whose id matches one of these globs; all when empty. */
    @Parameter(property = "fclcert.cases")
    private List<String> cases;

    /** Per-request timeout for the implementation, in milliseconds. */
    @Parameter(property = "fclcert.timeoutMillis", defaultValue = Defaults.TIMEOUT_MILLIS)
    private long timeoutMillis;

    /**
     * Run a process implementation as a plain process of the build's user instead of in the bubblewrap sandbox
     * (docs/iut-protocol.md, "The sandbox"); the reports say so.
     */
    @Parameter(property = "fclcert.noSandbox", defaultValue = "false")
    private boolean noSandbox;

    /**
     * Call a {@code java:} implementation inside the build's JVM instead of in a child JVM in the sandbox (faster,
     * not isolated; the reports say so), as {@code certify --in-process}.
     */
    @Parameter(property = "fclcert.inProcess", defaultValue = "false")
    private boolean inProcess;

    /**
     * Time the whole run may take, cases and probes, in seconds; the cases not run by then are reported as skipped
     * with the reason, and the goal fails.
     */
    /** The run seed the fresh vectors and disguises are drawn from; unset: drawn anew (the reports record it). */
    @Parameter(property = "fclcert.seed")
    private Long seed;

    @Parameter(property = "fclcert.budgetSeconds", defaultValue = Defaults.RUN_BUDGET_SECONDS)
    private long budgetSeconds;

    /** Also measure the Table 11 data check list by probing (off by default: it takes up to probeBudgetSeconds). */
    @Parameter(property = "fclcert.probe", defaultValue = "false")
    private boolean probe;

    /** Largest size the probes try. */
    @Parameter(property = "fclcert.probeCap", defaultValue = Defaults.CERTIFY_PROBE_CAP_TEXT)
    private long probeCap;

    /** Time budget of the probes, in seconds. */
    @Parameter(property = "fclcert.probeBudgetSeconds", defaultValue = Defaults.PROBE_BUDGET_SECONDS)
    private long probeBudgetSeconds;

    /**
     * The semantic axis: auto, none, or a format fclcert writes ({@code org.fclcert.orchestration.PresentAs.words()};
     * an unknown word is refused with that list). Each positive case the layout can express is also sent written in
     * that library's layout (auto: the built-in library adapters in their library's layout, none for reference,
     * java: and process:).
     */
    @Parameter(property = "fclcert.presentAs", defaultValue = "auto")
    private String presentAs;

    /** Skip this goal (also skipped with -DskipTests or -DskipITs). */
    @Parameter(property = "fclcert.skip", defaultValue = "false")
    private boolean skip;

    @Parameter(property = "skipTests", defaultValue = "false")
    private boolean skipTests;

    @Parameter(property = "skipITs", defaultValue = "false")
    private boolean skipITs;

    @Parameter(defaultValue = "${project}", readonly = true, required = true)
    private MavenProject project;

    @Override
    public void execute() throws MojoExecutionException {
        if (skip || skipTests || skipITs) {
            getLog().info("fclcert:certify skipped");
            return;
        }
        PresentAs layout;
        try {
            layout = PresentAs.byWord(presentAs == null ? "auto" : presentAs);
        } catch (IllegalArgumentException e) {
            throw new MojoExecutionException("fclcert:certify: presentAs " + e.getMessage());
        }
        if (budgetSeconds < 1) {
            throw new MojoExecutionException("fclcert:certify: budgetSeconds must be at least 1, not " + budgetSeconds);
        }
        Corpus corpus = corpus();
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofMillis(timeoutMillis))
                .withSandbox(noSandbox ? org.fclcert.sandbox.SandboxSettings.none()
                        : org.fclcert.sandbox.SandboxSettings.defaults()).withInProcess(inProcess);
        List<Path> classpath = iut.startsWith("java:") ? testClasspath() : List.of();
        if (!classpath.isEmpty()) {
            options = options.withClasspath(classpath);
        }
        Certification.Request request = Certification.Request.builder(iut, corpus).options(options)
                .classpath(classpath.isEmpty() ? null : "project test class path")
                .corpusName(corpusDirectory == null ? BundledCorpus.NAME : corpusDirectory.toString())
                .selection(new CaseSelection(levels(), Set.copyOf(orEmpty(features)), orEmpty(cases)))
                .outDir(reportsDirectory.toPath())
                .probe(probe ? new Prober.Options(probeCap, Duration.ofSeconds(probeBudgetSeconds), Set.of()) : null)
                .presentAs(layout).rerun(ProgressLog.reproduce(RunHeader.Toolkit.CASE))
                .budget(Duration.ofSeconds(budgetSeconds)).seed(seed).build();
        Certification.Outcome outcome;
        try {
            outcome = Certification.run(request, new ProgressLog(getLog()));
        } catch (Certification.CannotCertify e) {
            throw new MojoExecutionException("fclcert:certify could not run: " + e.getMessage(), e);
        }
        Report r = outcome.report();
        Path surefire = junitDirectory.toPath().resolve(ReportFiles.SUREFIRE);
        try {
            java.nio.file.Files.createDirectories(surefire.getParent());
            java.nio.file.Files.writeString(surefire, JunitReport.render(r));
        } catch (java.io.IOException e) {
            throw new MojoExecutionException("cannot write " + surefire + ": " + e.getMessage(), e);
        }
        // the failures, then Surefire's summary: the blocks above and the counts below are one tally (Tally)
        ProgressLog.failures(r, getLog());
        JunitReport.Counts counts = JunitReport.counts(r);
        String summary = counts.surefireLine() + " - " + r.iut().name() + " " + r.iut().version();
        if (counts.failures() + counts.errors() > 0) {
            getLog().warn(summary);
        } else {
            getLog().info(summary);
        }
        getLog().info(Tally.of(r).skippedSentence());
        getLog().info("Basic Level: " + r.basicLevel().sentence());
        if (!r.claims().notRealised().isEmpty()) {
            getLog().info("Claimed but not realised: " + String.join(", ", r.claims().notRealised()));
        }
        if (!r.claims().notDetermined().isEmpty()) {
            getLog().info("Claimed, not determined: " + String.join(", ", r.claims().notDetermined()));
        }
        if (r.semantic() != null) {
            getLog().info(r.semantic().sentence());
        }
        if (!r.causes().isEmpty()) {
            getLog().info("Failures by cause:");
        }
        r.causes().stream().limit(5).forEach(c -> getLog().info("  " + c.sentence()));
        if (r.causes().size() > 5) {
            getLog().info("  … and " + (r.causes().size() - 5) + " more causes (report.md, \"Failures by cause\")");
        }
        getLog().info(r.dataCheckList().isEmpty()
                ? "Table 11 (data check list): not measured (-Dfclcert.probe=true or <probe>true</probe> measures it,"
                        + " within probeBudgetSeconds)"
                : "Table 11 (data check list): measured, " + r.dataCheckList().size() + " rows (report.md)");
        getLog().info("Reports: " + outcome.directory().resolve(ReportFiles.MARKDOWN) + ", "
                + surefire);
        if (outcome.stopped() != null) {
            throw new MojoExecutionException("fclcert:certify: the run was stopped (" + outcome.stopped()
                    + "); the cases not run are reported as skipped (budgetSeconds)");
        }
    }

    private Corpus corpus() throws MojoExecutionException {
        try {
            return corpusDirectory == null ? BundledCorpus.load() : Corpus.load(corpusDirectory.toPath());
        } catch (CorpusException e) {
            throw new MojoExecutionException("the conformance corpus cannot be used: " + e.getMessage(), e);
        }
    }

    private List<Path> testClasspath() throws MojoExecutionException {
        try {
            List<Path> paths = new ArrayList<>();
            for (String element : project.getTestClasspathElements()) {
                paths.add(Path.of(element));
            }
            return paths;
        } catch (DependencyResolutionRequiredException e) {
            throw new MojoExecutionException("cannot resolve the project's test class path: " + e.getMessage(), e);
        }
    }

    private Set<ConformanceLevel> levels() throws MojoExecutionException {
        Set<ConformanceLevel> set = EnumSet.noneOf(ConformanceLevel.class);
        for (String word : orEmpty(levels)) {
            set.add(CheckMojo.level(word));
        }
        return set;
    }

    private static List<String> orEmpty(List<String> list) {
        return list == null ? List.of() : list;
    }
}
