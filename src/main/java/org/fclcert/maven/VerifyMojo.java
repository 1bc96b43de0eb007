package org.fclcert.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.fclcert.report.ReportVerifier;
import org.fclcert.report.Report;
import org.fclcert.report.ReportFiles;

/**
 * Reads the report {@code fclcert:certify} wrote and fails the build when it does not meet
 * {@code failOn}: {@code basic} (Basic Level not conformant), {@code claimed} (that, or a feature in
 * {@code claims} not realised), {@code any} (any case failed or errored) or {@code none}. A run narrowed by
 * {@code fclcert.cases} (the reproduce command) is judged by its cases alone: it fails when one of them did not pass.
 */
@Mojo(name = "verify", defaultPhase = LifecyclePhase.VERIFY, threadSafe = true)
public class VerifyMojo extends AbstractMojo {
    @Parameter(property = "fclcert.reportsDirectory", defaultValue = "${project.build.directory}/fclcert-reports")
    private File reportsDirectory;

    /** none, basic, claimed or any. */
    @Parameter(property = "fclcert.failOn", defaultValue = "basic")
    private String failOn;

    /** Feature ids (e.g. E-ACCU-NSUM) the project claims; when empty, the implementation's own claims. */
    @Parameter(property = "fclcert.claims")
    private List<String> claims;

    @Parameter(property = "fclcert.skip", defaultValue = "false")
    private boolean skip;

    @Parameter(property = "skipTests", defaultValue = "false")
    private boolean skipTests;

    @Parameter(property = "skipITs", defaultValue = "false")
    private boolean skipITs;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        if (skip || skipTests || skipITs) {
            getLog().info("fclcert:verify skipped");
            return;
        }
        ReportGate.FailOn condition;
        try {
            condition = ReportGate.FailOn.byWord(failOn);
        } catch (IllegalArgumentException e) {
            throw new MojoExecutionException("failOn must be none, basic, claimed or any, not '" + failOn + "'");
        }
        Path file = reportsDirectory.toPath().resolve(ReportFiles.JSON);
        if (!Files.isRegularFile(file)) {
            throw new MojoExecutionException("No certification report at " + file + ": run fclcert:certify first");
        }
        // the gate judges the evidence again, never the report's own verdict fields (ReportVerifier)
        Report report;
        try {
            ReportVerifier.Verified verified = ReportVerifier.check(reportsDirectory.toPath(), null);
            if (!verified.inconsistencies().isEmpty()) {
                throw new MojoFailureException("fclcert:verify: the certification in " + reportsDirectory
                        + " is inconsistent: " + verified.inconsistencies().get(0)
                        + (verified.inconsistencies().size() > 1 ? " (and " + (verified.inconsistencies().size() - 1)
                                + " more; fclcert report --verify lists them)" : ""));
            }
            report = verified.report();
        } catch (IOException e) {
            throw new MojoExecutionException("Cannot read " + file + ": " + e.getMessage(), e);
        }
        Optional<String> failure = ReportGate.failure(report, condition, claims == null ? List.of() : claims);
        if (failure.isPresent()) {
            throw new MojoFailureException("fclcert:verify (failOn=" + condition.name().toLowerCase(java.util.Locale.ROOT)
                    + ") failed for " + report.iut().name() + ":\n" + failure.get()
                    + "\nDetails: " + reportsDirectory.toPath().resolve(ReportFiles.MARKDOWN));
        }
        if (ReportGate.reproduction(report)) {
            getLog().info("fclcert:verify: the " + report.cases().size() + " case(s) selected by fclcert.cases passed on "
                    + report.iut().name() + " (failOn=" + failOn + " needs the whole corpus: run without fclcert.cases)");
        } else {
            getLog().info("fclcert:verify: " + report.iut().name() + " meets failOn=" + failOn);
        }
    }
}
