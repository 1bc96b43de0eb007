package org.fclcert.maven;

import java.io.IOException;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.PathMatcher;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.check.SarifLog;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FeatureUse;

/**
 * Checks the project's own FCL files: every error fails the build with its location, and
 * {@code maxLevel} fails a file that needs a conformance level above the one the project allows.
 */
@Mojo(name = "check", defaultPhase = LifecyclePhase.VALIDATE, threadSafe = true)
public class CheckMojo extends AbstractMojo {
    /** Directory holding the FCL files. */
    @Parameter(property = "fclcert.fclDirectory", defaultValue = "${project.basedir}/src/main/fcl")
    private java.io.File fclDirectory;

    /** Glob patterns (relative to fclDirectory) of the files to check. */
    @Parameter(property = "fclcert.includes", defaultValue = "**/*.fcl")
    private List<String> includes;

    /** Glob patterns (relative to fclDirectory) of files to leave out. */
    @Parameter(property = "fclcert.excludes")
    private List<String> excludes;

    /** Highest conformance level a file may need: basic, extension or open. */
    @Parameter(property = "fclcert.maxLevel", defaultValue = "open")
    private String maxLevel;

    /** Treat warnings as errors. */
    @Parameter(property = "fclcert.failOnWarning", defaultValue = "false")
    private boolean failOnWarning;

    /**
     * Where the findings of all files are written as a SARIF 2.1.0 log (for code scanning in CI), beside the
     * build output; empty to write none.
     */
    @Parameter(property = "fclcert.sarifFile", defaultValue = "${project.build.directory}/fclcert/check.sarif")
    private java.io.File sarifFile;

    /** Skip this goal. */
    @Parameter(property = "fclcert.skip", defaultValue = "false")
    private boolean skip;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        if (skip) {
            getLog().info("fclcert:check skipped");
            return;
        }
        ConformanceLevel allowed = level(maxLevel);
        Path root = fclDirectory.toPath();
        if (!Files.isDirectory(root)) {
            getLog().info("No FCL directory " + root + ": nothing to check");
            return;
        }
        List<Path> files = select(root);
        FclFileGate gate = new FclFileGate(allowed);
        int failedFiles = 0;
        List<Diagnostic> all = new ArrayList<>();
        for (Path file : files) {
            FclFileGate.FileVerdict verdict;
            try {
                verdict = gate.examine(file);
            } catch (IOException e) {
                throw new MojoExecutionException("Cannot read " + file + ": " + e.getMessage(), e);
            }
            all.addAll(verdict.diagnostics());
            boolean warned = report(verdict, gate);
            if (verdict.failed() || (failOnWarning && warned)) {
                failedFiles++;
            }
        }
        writeSarif(sarifFile, all);
        String summary = files.size() + " FCL file(s) checked under " + root + ", maxLevel " + allowed.word();
        if (failedFiles > 0) {
            throw new MojoFailureException(failedFiles + " of " + summary + " failed (see the errors above)");
        }
        getLog().info(summary + ": all conform");
    }

    /** The SARIF log of the diagnostics (the level gate's findings are the build's, not the files'). */
    private void writeSarif(java.io.File to, List<Diagnostic> diagnostics) throws MojoExecutionException {
        if (to == null || to.getPath().isEmpty()) {
            return;
        }
        try {
            Path path = to.toPath();
            if (path.getParent() != null) {
                Files.createDirectories(path.getParent());
            }
            Files.writeString(path, SarifLog.render(diagnostics), java.nio.charset.StandardCharsets.UTF_8);
            getLog().info("SARIF log of the findings: " + path);
        } catch (IOException e) {
            throw new MojoExecutionException("Cannot write " + to + ": " + e.getMessage(), e);
        }
    }

    private boolean report(FclFileGate.FileVerdict verdict, FclFileGate gate) {
        boolean warned = false;
        for (Diagnostic d : verdict.diagnostics()) {
            String line = FclFileGate.mavenStyle(d.location(), d.severity().word() + " " + d.code() + ": " + d.message());
            if (d.isError()) {
                getLog().error(line);
            } else {
                getLog().warn(line);
                warned = true;
            }
        }
        for (FeatureUse use : verdict.beyondLevel()) {
            getLog().error(gate.describe(use));
        }
        return warned;
    }

    private List<Path> select(Path root) throws MojoExecutionException {
        FileSystem fs = FileSystems.getDefault();
        List<PathMatcher> in = matchers(fs, includes);
        List<PathMatcher> out = matchers(fs, excludes);
        try (Stream<Path> walk = Files.walk(root)) {
            List<Path> files = new ArrayList<>();
            walk.filter(Files::isRegularFile).sorted().forEach(p -> {
                Path rel = root.relativize(p);
                if (matchesAny(in, rel) && !matchesAny(out, rel)) {
                    files.add(p);
                }
            });
            return files;
        } catch (IOException e) {
            throw new MojoExecutionException("Cannot list " + root + ": " + e.getMessage(), e);
        }
    }

    private static List<PathMatcher> matchers(FileSystem fs, List<String> globs) {
        List<PathMatcher> m = new ArrayList<>();
        if (globs != null) {
            for (String g : globs) {
                m.add(fs.getPathMatcher("glob:" + g));
                if (g.startsWith("**/")) {
                    // '**/' in a glob needs at least one directory; files at the top level match too
                    m.add(fs.getPathMatcher("glob:" + g.substring(3)));
                }
            }
        }
        return m;
    }

    private static boolean matchesAny(List<PathMatcher> matchers, Path rel) {
        return matchers.stream().anyMatch(m -> m.matches(rel));
    }

    static ConformanceLevel level(String word) throws MojoExecutionException {
        try {
            return ConformanceLevel.byWord(word.trim().toLowerCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new MojoExecutionException("maxLevel must be basic, extension or open, not '" + word + "'");
        }
    }
}
