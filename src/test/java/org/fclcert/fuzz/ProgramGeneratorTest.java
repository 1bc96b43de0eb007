package org.fclcert.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.EnumSet;
import java.util.Set;
import java.util.TreeSet;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.check.FeatureReport;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.junit.jupiter.api.Test;

class ProgramGeneratorTest {
    private static final CanonicalWriter WRITER = new CanonicalWriter();

    /** Reads the program back as the corpus language; any diagnostic that is an error is a generator bug. */
    static Program checked(Program p) {
        String text = WRITER.write(p);
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", text);
        if (a.program().isEmpty()) {
            fail("generated program is not valid: " + a.diagnostics().stream().filter(Diagnostic::isError).toList()
                    + "\n" + text);
        }
        assertEquals(p, a.program().get(), "the model reads back as written");
        return a.program().get();
    }

    @Test
    void everyProgramPassesTheStrictReaderAndTheChecks_andStaysWithinItsLevel() {
        for (ConformanceLevel level : ConformanceLevel.values()) {
            ProgramGenerator g = new ProgramGenerator(new FuzzSettings(level, Set.of()));
            for (long seed = 0; seed < 800; seed++) {
                Program p = checked(g.generate(seed));
                FeatureReport report = new FeatureDetector().detect(p);
                assertTrue(report.level().compareTo(level) <= 0, "seed " + seed + " at " + level + " uses " + report.features());
            }
        }
    }

    @Test
    void aSeedGivesTheSameProgram() {
        ProgramGenerator g = new ProgramGenerator(FuzzSettings.open());
        assertEquals(WRITER.write(g.generate(42)), WRITER.write(g.generate(42)));
        assertTrue(!WRITER.write(g.generate(42)).equals(WRITER.write(g.generate(43))));
    }

    @Test
    void coversEveryFeatureOfTables8And9AndTheOpenLevelFeaturesTheReferenceEvaluates() {
        ProgramGenerator g = new ProgramGenerator(FuzzSettings.open());
        Set<Feature> seen = EnumSet.noneOf(Feature.class);
        for (long seed = 0; seed < 3000; seed++) {
            seen.addAll(new FeatureDetector().detect(g.generate(seed)).features());
        }
        Set<String> missing = new TreeSet<>();
        for (Feature f : FuzzSettings.generatable()) {
            if (!seen.contains(f)) {
                missing.add(f.id());
            }
        }
        assertEquals(Set.of(), missing);
    }

    @Test
    void aFocusedFeatureIsInMostPrograms() {
        for (Feature f : FuzzSettings.generatable()) {
            ProgramGenerator g = new ProgramGenerator(new FuzzSettings(ConformanceLevel.OPEN, Set.of(f)));
            int with = 0;
            for (long seed = 0; seed < 200; seed++) {
                if (new FeatureDetector().detect(g.generate(seed)).features().contains(f)) {
                    with++;
                }
            }
            assertTrue(with >= 60, f.id() + " in only " + with + " of 200 focused programs");
        }
    }
}
