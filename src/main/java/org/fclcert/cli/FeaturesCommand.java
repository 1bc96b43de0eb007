package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.check.FeatureReport;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.SourceLocation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert features}: the conformance features (Tables 8-10) a program uses and the lowest level that runs it. */
@Command(name = "features", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "List the conformance features (clause 6, Tables 8, 9 and 10) a valid FCL program uses, "
                + "where it uses them, and the lowest conformance level that can run it. "
                + "A program with errors gets its diagnostics instead.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {ExitCodes.OK_LINE, ExitCodes.ERRORS_LINE, ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE})
final class FeaturesCommand implements Callable<Integer> {
    /** How many locations of one feature the text table shows before summarising the rest. */
    private static final int SHOWN_LOCATIONS = 4;

    @Spec
    CommandSpec spec;

    @Option(names = "--format", defaultValue = "text", paramLabel = "FORMAT",
            description = "text or json (default: ${DEFAULT-VALUE})")
    OutputFormat format;

    @Option(names = "--dialect", defaultValue = "strict", paramLabel = "DIALECT",
            completionCandidates = DialectName.Names.class, description = DialectName.DESCRIPTION)
    DialectName dialect;

    @Parameters(paramLabel = "FILE", description = "an FCL source file, or - for standard input")
    String file;

    record JsonFeature(String id, int line, int column, int table, String description) {
    }


    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Analysis analysis;
        try {
            String text = SourceFiles.read(file);
            String name = SourceFiles.name(file);
            analysis = Analysis.analyze(dialect.reader(name, text, err), name, text);
        } catch (FileProblem e) {
            err.println("fclcert: " + e.getMessage());
            return ExitCodes.USAGE;
        }
        if (analysis.program().isEmpty()) {
            printDiagnostics(out, analysis);
            err.println("fclcert: " + SourceFiles.name(file) + " has errors; features are listed only for a valid program");
            return ExitCodes.ERRORS;
        }
        DiagnosticPrinter.text(err, analysis.diagnostics()); // warnings only; stdout stays the report
        FeatureReport report = new FeatureDetector().detect(analysis.program().get());
        if (format == OutputFormat.json) {
            out.println(json(report));
        } else {
            text(out, report);
        }
        return ExitCodes.OK;
    }

    private void printDiagnostics(PrintWriter out, Analysis analysis) {
        if (format == OutputFormat.json) {
            DiagnosticPrinter.json(out, analysis.diagnostics());
        } else {
            DiagnosticPrinter.text(out, analysis.diagnostics());
        }
    }

    /** {@code {"level": ..., "features": [...]}} with one feature use per line. */
    static String json(FeatureReport report) {
        List<JsonFeature> features = report.uses().stream()
                .map(u -> new JsonFeature(u.feature().id(), u.location().line(), u.location().column(),
                        u.feature().table(), u.feature().description()))
                .toList();
        return "{\"level\": " + DiagnosticPrinter.toJson(report.level().word()) + ", \"features\": "
                + DiagnosticPrinter.jsonLines(features) + "}";
    }

    /** A table per level (Table 8, 9, 10), one row per feature with where the program uses it. */
    private void text(PrintWriter out, FeatureReport report) {
        out.println(SourceFiles.name(file) + ": lowest conformance level that can run it: " + report.level().word());
        Map<Feature, List<SourceLocation>> byFeature = report.uses().stream().collect(Collectors.groupingBy(
                FeatureUse::feature, LinkedHashMap::new, Collectors.mapping(FeatureUse::location, Collectors.toList())));
        int idWidth = byFeature.keySet().stream().mapToInt(f -> f.id().length()).max().orElse(0);
        int descriptionWidth = byFeature.keySet().stream().mapToInt(f -> f.description().length()).max().orElse(0);
        for (ConformanceLevel level : ConformanceLevel.values()) {
            List<Feature> features = byFeature.keySet().stream().filter(f -> f.level() == level).sorted().toList();
            if (features.isEmpty()) {
                continue;
            }
            out.println();
            out.println(heading(level));
            for (Feature f : features) {
                out.println("  " + pad(f.id(), idWidth) + "  " + pad(f.description(), descriptionWidth)
                        + "  at " + locations(byFeature.get(f)));
            }
        }
    }

    private static String heading(ConformanceLevel level) {
        return switch (level) {
            case BASIC -> "Basic level (Table 8)";
            case EXTENSION -> "Extension level (Table 9)";
            case OPEN -> "Open level (Table 10)";
        };
    }

    private static String locations(List<SourceLocation> at) {
        List<String> shown = new ArrayList<>();
        at.stream().limit(SHOWN_LOCATIONS).forEach(l -> shown.add(l.line() + ":" + l.column()));
        String more = at.size() > SHOWN_LOCATIONS ? " and " + (at.size() - SHOWN_LOCATIONS) + " more" : "";
        return String.join(", ", shown) + more;
    }

    private static String pad(String s, int width) {
        return s + " ".repeat(Math.max(0, width - s.length()));
    }
}
