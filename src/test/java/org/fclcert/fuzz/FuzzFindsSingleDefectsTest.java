package org.fclcert.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.fclcert.corpus.CorpusLint;
import org.fclcert.corpus.LintReport;
import org.fclcert.harness.fakes.Fakes;
import org.fclcert.model.Feature;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The acceptance test: against each single-defect implementation, an unfocused fuzz run (no corpus)
 * finds the defect within a minute and shrinks it to a case of at most 25 program lines named by the feature
 * it isolates, which lints as a corpus case. Each run stops at its first finding, so the test takes seconds
 * per defect.
 */
class FuzzFindsSingleDefectsTest {
    static Stream<Arguments> defects() {
        return Stream.of(
                Arguments.of("NSUM computed as BSUM", (IutSession.Factory) Fakes.NsumAsBsum::new, Set.of(Feature.E_ACCU_NSUM), 1),
                Arguments.of("CoGS summed per rule", (IutSession.Factory) Fakes.PerRuleCogs::new, Set.of(Feature.B_COGS), 1),
                Arguments.of("WITH applied before activation", (IutSession.Factory) Fakes.WeightBeforeActivation::new,
                        Set.of(Feature.E_WITH_CONST, Feature.E_WITH_VAR), 1),
                Arguments.of("LM and RM swapped", (IutSession.Factory) SingleDefects.LeftRightSwapped::new,
                        Set.of(Feature.E_LM, Feature.E_RM), 1),
                Arguments.of("AND and OR of equal precedence", (IutSession.Factory) Fakes.EqualPrecedence::new,
                        Set.of(Feature.E_OR_MAX, Feature.E_OR_ASUM, Feature.E_OR_BSUM), 1),
                Arguments.of("degrees outside the points taken as 0", (IutSession.Factory) SingleDefects.ZeroOutsideThePoints::new,
                        Set.of(Feature.B_IN_TERM, Feature.E_RANGE), 1),
                Arguments.of("ACT PROD evaluated as MIN", (IutSession.Factory) SingleDefects.ProdActivationAsMin::new,
                        Set.of(Feature.E_ACT_PROD), 1),
                Arguments.of("NC as 0", (IutSession.Factory) Fakes.NcAsZero::new, Set.of(Feature.B_DEFAULT_NC), 1),
                Arguments.of("defuzzification sampled at 100 points", (IutSession.Factory) Fakes.SampledDefuzzification::new,
                        Set.of(Feature.E_COG, Feature.E_COA, Feature.E_LM, Feature.E_RM, Feature.O_MOM), 3));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("defects")
    void findsAndShrinksTheDefect(String defect, IutSession.Factory fake, Set<Feature> isolates, int findings,
            @TempDir Path dir) throws Exception {
        Fuzzer.Options options = Fuzzer.Options.of(7, Duration.ofSeconds(60), FuzzSettings.open(), 1).withMaxFindings(findings);
        Fuzzer.Result result = new Fuzzer().run(fake, options, Duration.ofSeconds(10), p -> { });
        assertFalse(result.findings().isEmpty(), defect + ": nothing found in " + result.progress());
        List<FuzzReport.Written> written = FuzzReport.write(result, dir);
        FuzzReport.Written w = written.stream().filter(x -> isolates.contains(x.finding().feature())).findFirst()
                .orElseThrow(() -> new AssertionError(defect + ": no case isolates " + isolates + ": "
                        + result.findings().stream().map(Finding::key).toList()));
        Finding f = w.finding();
        assertTrue(f.foundAfterMillis() < 60_000, defect + ": found only after " + f.foundAfterMillis() + " ms");
        assertTrue(w.programLines() <= 25, defect + ": " + w.programLines() + " lines:\n" + Files.readString(w.file()));
        System.out.printf("%s: found after %.1f s (program %d), shrunk in %.1f s (%d trials) from %d to %d lines: %s%n",
                defect, f.foundAfterMillis() / 1000.0, f.programIndex(), f.shrinkMillis() / 1000.0, f.shrinkTrials(),
                f.originalLines(), w.programLines(), w.id());
        if (System.getenv("FUZZ_CASES") != null) {
            Files.copy(w.file(), Path.of(System.getenv("FUZZ_CASES")).resolve(w.file().getFileName()),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        assertCaseLints(w, dir);
    }

    /** The case file is a valid corpus case: placed in a corpus directory of its level, it lints clean. */
    static void assertCaseLints(FuzzReport.Written w, Path dir) throws Exception {
        Path corpus = dir.resolve("corpus");
        String level = switch (w.id().charAt(0)) {
            case 'B' -> "basic";
            case 'E' -> "extension";
            default -> "open";
        };
        Files.createDirectories(corpus.resolve(level));
        Files.copy(w.file(), corpus.resolve(level).resolve(w.file().getFileName()));
        LintReport report = new CorpusLint().lint(corpus);
        assertEquals(List.of(), report.caseFindings(), Files.readString(w.file()));
        assertEquals(1, report.positive());
    }
}
