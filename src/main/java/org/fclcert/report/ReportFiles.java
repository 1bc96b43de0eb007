package org.fclcert.report;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** Writes all four renderings of a report into an output directory. */
public final class ReportFiles {
    public static final String JSON = "report.json";
    public static final String MARKDOWN = "report.md";
    public static final String HTML = "report.html";
    public static final String JUNIT = "junit.xml";

    /**
     * The name the Maven plugin gives the JUnit results in {@code target/surefire-reports/}, where CI servers
     * and the surefire-report plugin look (only there: two copies in one directory would count every case twice).
     */
    public static final String SUREFIRE = "TEST-fclcert.xml";

    private ReportFiles() {
    }

    /** Returns the files written. */
    public static List<Path> writeAll(Report report, Path dir) throws IOException {
        Files.createDirectories(dir);
        Path json = dir.resolve(JSON);
        JsonReport.write(report, json);
        return List.of(json,
                write(dir.resolve(MARKDOWN), MarkdownReport.render(report)),
                write(dir.resolve(HTML), HtmlReport.render(report)),
                write(dir.resolve(JUNIT), JunitReport.render(report)));
    }

    private static Path write(Path file, String text) throws IOException {
        return Files.writeString(file, text, StandardCharsets.UTF_8);
    }
}
