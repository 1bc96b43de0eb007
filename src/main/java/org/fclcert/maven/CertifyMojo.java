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
import org.fclcert.probe.Prober;
import org.fclcert.iut.IutOptions;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.orchestration.Certification;
import org.fclcert.orchestration.Defaults;
import org.fclcert.report.Report;
import org.fclcert.report.ReportFiles;

/**
 * Runs the conformance corpus against an implementation under test and writes the reports to
 * {@code target/fclcert-reports}. Like Failsafe's integration-test goal it never fails the build on
 * results ({@code fclcert:verify} decides); only a run that cannot be done fails here.
 */
@Mojo(name = "certify", defaultPhase = LifecyclePhase.INTEGRATION_TEST, threadSafe = true,
        requiresDependencyResolution = ResolutionScope.TEST)
public class CertifyMojo extends AbstractMojo {
    /**
     * The implementation: {@code java:CLASS} (found on the project's test class path), {@code process:COMMAND},
     * {@code fuzzylite} or {@code fuzzylite:PATH} (the fuzzylite 6.0 command line), or {@code reference}.
     */
    @Parameter(property = "fclcert.iut", required = true)
    private String iut;

    /** A corpus directory; by default the corpus bundled with this plugin. */
    @Parameter(property = "fclcert.corpus")
    private File corpusDirectory;

    /** Where results.jsonl and the four reports go. */
    @Parameter(property = "fclcert.reportsDirectory", defaultValue = "${project.build.directory}/fclcert-reports")
    private File reportsDirectory;

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

    /** Also measure the Table 11 data check list by probing (off by default: it takes up to probeBudgetSeconds). */
    @Parameter(property = "fclcert.probe", defaultValue = "false")
    private boolean probe;

    /** Largest size the probes try. */
    @Parameter(property = "fclcert.probeCap", defaultValue = Defaults.CERTIFY_PROBE_CAP_TEXT)
    private long probeCap;

    /** Time budget of the probes, in seconds. */
    @Parameter(property = "fclcert.probeBudgetSeconds", defaultValue = Defaults.PROBE_BUDGET_SECONDS)
    private long probeBudgetSeconds;

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
        Corpus corpus = corpus();
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofMillis(timeoutMillis));
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
                .build();
        Certification.Outcome outcome;
        try {
            outcome = Certification.run(request, new ProgressLog(getLog()));
        } catch (Certification.CannotCertify e) {
            throw new MojoExecutionException("fclcert:certify could not run: " + e.getMessage(), e);
        }
        Report r = outcome.report();
        Report.Summary s = r.summary();
        getLog().info(r.iut().name() + " " + r.iut().version() + ": " + s.cases() + " cases, " + s.passed()
                + " passed, " + s.failed() + " failed, " + s.errored() + " errored, " + s.skipped() + " skipped");
        getLog().info("Basic Level: " + (r.basicLevel().conformant() ? "conformant" : "not conformant"));
        r.causes().stream().limit(5).forEach(c -> getLog().info("  " + c.sentence()));
        getLog().info("Reports: " + outcome.directory().resolve(ReportFiles.MARKDOWN));
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
