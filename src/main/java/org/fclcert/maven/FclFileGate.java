package org.fclcert.maven;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.check.FeatureReport;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.StrictReader;

/**
 * The portability gate behind {@code fclcert:check}: a project's own FCL files must be valid and
 * must not need a conformance level above the one the project allows (a PLC team that targets
 * Basic Level controllers sets {@code maxLevel=basic}).
 */
final class FclFileGate {
    /** What the gate found in one file: its diagnostics and the features above the allowed level. */
    record FileVerdict(Path file, List<Diagnostic> diagnostics, ConformanceLevel level, List<FeatureUse> beyondLevel) {
        boolean failed() {
            return !beyondLevel.isEmpty() || diagnostics.stream().anyMatch(Diagnostic::isError);
        }
    }

    private final ConformanceLevel maxLevel;

    FclFileGate(ConformanceLevel maxLevel) {
        this.maxLevel = maxLevel;
    }

    FileVerdict examine(Path file) throws IOException {
        String text = new String(org.fclcert.model.Limits.readFile(file), StandardCharsets.UTF_8);
        Analysis analysis = Analysis.analyze(new StrictReader(), file.toString(), text);
        if (analysis.program().isEmpty()) {
            return new FileVerdict(file, analysis.diagnostics(), ConformanceLevel.BASIC, List.of());
        }
        FeatureReport features = new FeatureDetector().detect(analysis.program().get());
        List<FeatureUse> beyond = new ArrayList<>();
        for (FeatureUse use : features.uses()) {
            if (use.feature().level().compareTo(maxLevel) > 0) {
                beyond.add(use);
            }
        }
        return new FileVerdict(file, analysis.diagnostics(), features.level(), beyond);
    }

    /** Maven's usual form for a located problem: {@code /path/file.fcl:[line,col] text}. */
    static String mavenStyle(SourceLocation at, String text) {
        return at.file() + ":[" + at.line() + "," + at.column() + "] " + text;
    }

    String describe(FeatureUse use) {
        return mavenStyle(use.location(), "needs " + use.feature().level().word() + " level feature "
                + use.feature().id() + " (Table " + use.feature().table() + ": " + use.feature().description()
                + "), but maxLevel is " + maxLevel.word());
    }
}
