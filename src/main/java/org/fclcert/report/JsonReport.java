package org.fclcert.report;

import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.Path;
import org.fclcert.harness.Json;

/** {@code report.json}: the {@link Report} record as indented JSON (schema in docs/report-format.md). */
public final class JsonReport {
    private JsonReport() {
    }

    public static void write(Report report, Path file) throws IOException {
        Json.mapper().writer().with(SerializationFeature.INDENT_OUTPUT).writeValue(file.toFile(), report);
    }

    /** The text {@link #write} writes. */
    public static String text(Report report) throws IOException {
        return Json.mapper().writer().with(SerializationFeature.INDENT_OUTPUT).writeValueAsString(report);
    }

    public static Report read(Path file) throws IOException {
        return Json.mapper().readValue(org.fclcert.model.Limits.readFile(file), Report.class);
    }
}
