package org.fclcert.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.fclcert.report.ComparisonPage;
import org.fclcert.report.ReportVerifier;
import org.fclcert.report.Report;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert compare DIR...}: one page with several certifications side by side. */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = {"Put certifications side by side: reads DIR/report.json of each report directory written by"
                + " 'fclcert certify' and writes index.md and index.html (implementations side by side, the verdicts"
                + " of every Table 8/9/10 row, the telling deviations with cases and values, the causes of failure,"
                + " Table 11). Prints the summary table.",
            "Each directory is checked as 'fclcert report --verify' does (its results chain, its corpus, every verdict"
                + " judged again from the recorded evidence, the reports what the results give); the page is made"
                + " from the verdicts so recomputed.",
            "Exit 0 when the page was written, 1 when a directory is inconsistent (the first inconsistency is named),"
                + " 2 when a report cannot be read or the page cannot be written."})
final class CompareCommand implements Callable<Integer> {
    static final String MARKDOWN = "index.md";
    static final String HTML = "index.html";

    @Spec
    CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "DIR", description = "Report directories, in the order of the columns")
    List<Path> dirs;

    @Option(names = "--out", paramLabel = "DIR", description = "Where index.md and index.html go (default: reports)")
    Path out = Path.of("reports");

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        List<ComparisonPage.Entry> entries = new ArrayList<>();
        List<ComparisonPage.Entry> printed = new ArrayList<>();
        for (Path dir : dirs) {
            Path json = dir.resolve("report.json");
            if (!Files.isRegularFile(json)) {
                err.println("fclcert compare: " + json + ": no such file (give directories written by 'fclcert certify')");
                err.flush();
                return CertifyCommand.CANNOT_RUN;
            }
            Report report;
            try {
                ReportVerifier.Verified verified = ReportVerifier.check(dir, null);
                if (!verified.inconsistencies().isEmpty()) {
                    err.println("fclcert compare: " + TerminalText.visible(dir.toString()) + " is inconsistent: "
                            + TerminalText.visible(verified.inconsistencies().get(0)));
                    err.flush();
                    return CertifyCommand.FAILED;
                }
                report = verified.report();
            } catch (IOException e) {
                err.println("fclcert compare: " + json + " cannot be read as a report: " + firstLine(e.getMessage()));
                err.flush();
                return CertifyCommand.CANNOT_RUN;
            }
            entries.add(new ComparisonPage.Entry(report, link(dir)));
            // what is printed is read from here: its links are relative to the working directory
            printed.add(new ComparisonPage.Entry(report, dir.normalize().resolve("report.md").toString().replace('\\', '/')));
        }
        try {
            Files.createDirectories(out);
            Files.writeString(out.resolve(MARKDOWN), ComparisonPage.markdown(entries), StandardCharsets.UTF_8);
            Files.writeString(out.resolve(HTML), ComparisonPage.html(entries), StandardCharsets.UTF_8);
        } catch (IOException e) {
            err.println("fclcert compare: cannot write " + out + ": " + e.getMessage());
            err.flush();
            return CertifyCommand.CANNOT_RUN;
        }
        PrintWriter o = spec.commandLine().getOut();
        o.print(ComparisonPage.summaryMarkdown(printed));
        o.println("Wrote " + out.resolve(MARKDOWN) + " and " + HTML);
        o.flush();
        return CertifyCommand.OK;
    }

    /** The report.md of a directory, relative to the page, with forward slashes. */
    private String link(Path dir) {
        Path base = out.toAbsolutePath().normalize();
        Path target = dir.toAbsolutePath().normalize().resolve("report.md");
        return base.relativize(target).toString().replace('\\', '/');
    }

    private static String firstLine(String s) {
        return s == null ? "" : s.lines().findFirst().orElse("");
    }
}
