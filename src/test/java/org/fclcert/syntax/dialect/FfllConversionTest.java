package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.model.Program;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;
import org.junit.jupiter.api.Test;

/**
 * Each FFLL sample converts to standard FCL; where the conversion claims exactness the converted text, read
 * by the strict reader, evaluates exactly like the FFLL program on a grid of inputs (both on the reference
 * evaluator); auto-detection; robustness of the reader on mutated FFLL text.
 */
class FfllConversionTest {
    private static final int STEPS = 23;

    private static Program ffll(String sample) {
        Analysis a = Analysis.analyze(new FfllReader(), sample, FfllSamples.text(sample));
        return a.program().orElseThrow(() -> new AssertionError(a.diagnostics().toString()));
    }

    private static Program standard(String sourceName, String text) {
        Analysis a = Analysis.analyze(new StrictReader(), sourceName, text);
        assertTrue(a.diagnostics().stream().noneMatch(d -> d.isError()), () -> a.diagnostics() + "\n" + text);
        return a.program().orElseThrow();
    }

    @Test
    void exactConversionsEvaluateAlikeOnAGrid() throws EvaluationException {
        for (String sample : List.of("guard.fcl", "mixer.fcl")) {
            Program original = ffll(sample);
            StandardConversion.Result r = new StandardConversion().convert(original);
            assertTrue(r.exact(), () -> sample + ": " + r.findings());
            assertEquals(original.dialectFeatures().size(), r.findings().size(), "one finding per construct");
            Program converted = standard(sample, new CanonicalWriter().write(r.program()));
            assertEquals(original, converted, sample + ": the same model, read back from standard text");
            int compared = compareOnGrid(original, converted);
            assertTrue(compared >= STEPS * STEPS, sample + ": " + compared);
        }
    }

    /** Evaluates both programs on a grid over [-1, 11]·(range/10) of every pair of inputs; returns the count. */
    private static int compareOnGrid(Program a, Program b) throws EvaluationException {
        double scale = a.functionBlocks().get(0).name().equals("guard") ? 10 : 1;
        return EvaluatesAlike.onGrid(a, b, STEPS, i -> (-1 + 12.0 * i / (STEPS - 1)) * scale,
                j -> -1 + 12.0 * j / (STEPS - 1));
    }

    @Test
    void momIsNotExpressibleAndSaidWhere() {
        StandardConversion.Result r = new StandardConversion().convert(ffll("heater.fcl"));
        assertFalse(r.exact());
        List<StandardConversion.Finding> lossy = r.findings().stream()
                .filter(f -> !(f.kind() instanceof StandardConversion.Kind.Exact)).toList();
        assertEquals(1, lossy.size(), r.findings().toString());
        assertEquals(22, lossy.get(0).location().line());
        assertEquals(5, lossy.get(0).location().column());
        assertInstanceOf(StandardConversion.Kind.NotExpressible.class, lossy.get(0).kind());
        String text = new CanonicalWriter().write(r.program());
        assertTrue(text.contains("METHOD : CoG;"), text);
        standard("heater.fcl", text);   // what --allow-lossy writes is standard FCL
    }

    @Test
    void autoPicksFfllForTheSamplesAndStrictForStandardPrograms() throws IOException {
        for (String sample : List.of("guard.fcl", "heater.fcl", "mixer.fcl", "broken-term.fcl", "broken-range.fcl",
                "broken-position.fcl")) {
            DialectReaders.Choice c = DialectReaders.auto(FfllSamples.text(sample));
            assertEquals(Dialect.FFLL, c.dialect(), sample);
            assertFalse(c.giveaways().isEmpty());
            assertTrue(c.explanation().startsWith("read as Free Fuzzy Logic Library (FFLL): "), c.explanation());
        }
        DialectReaders.Choice heater = DialectReaders.auto(FfllSamples.text("heater.fcl"));
        assertEquals("read as Free Fuzzy Logic Library (FFLL): RETAIN at line 4, RANGE comment at line 5,"
                + " RANGE comment at line 9, METHOD: MoM at line 22", heater.explanation());
        List<Path> standard = new ArrayList<>(List.of(Path.of("examples/valve.fcl")));
        try (Stream<Path> s = Files.list(Path.of("conformance/basic"))) {
            s.sorted().forEach(standard::add);
        }
        for (Path p : standard) {
            DialectReaders.Choice c = DialectReaders.auto(Files.readString(p));
            assertEquals(Dialect.STRICT, c.dialect(), p + ": " + c.explanation());
            assertEquals("read as standard FCL (strict)", c.explanation());
        }
    }

    /** The strict reader's mutation idea: no mutant of an FFLL sample makes the reader throw or hang. */
    @Test
    void mutantsNeverThrowOrHang() {
        List<String> insertions = List.of("ACCUM", ":", ";", "(*", "*)", "(* RANGE(0 .. 1) *)", "(* RANGE(", "REAL",
                "FUZZIFY", "END_FUZZIFY", "DEFUZZIFY", "MoM", "IF", "THEN", "AND", "OR", "NOT", "(", ")", ",",
                "RETAIN", "VAR_OUTPUT", "END_VAR", "x", "1.5", "WITH");
        Random random = new Random(61131);
        FfllReader reader = new FfllReader();
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            for (String sample : FfllSamples.VALID) {
                String text = FfllSamples.text(sample);
                for (int i = 0; i < 150; i++) {
                    StringBuilder m = new StringBuilder(text);
                    int at = random.nextInt(m.length());
                    switch (random.nextInt(3)) {
                        case 0 -> m.delete(at, Math.min(m.length(), at + 1 + random.nextInt(8)));
                        case 1 -> m.insert(at, " " + insertions.get(random.nextInt(insertions.size())) + " ");
                        default -> m.insert(at, m.substring(at, Math.min(m.length(), at + random.nextInt(30))));
                    }
                    String mutant = m.toString();
                    ReadResult r = reader.read("m.fcl", mutant);
                    assertEquals(r.program().isEmpty(), r.hasErrors(), mutant);
                    r.diagnostics().forEach(d -> assertTrue(d.location().line() >= 1
                            && d.code().matches("FCL-[SWD]\\d{3}"), d.toString()));
                    Analysis.analyze(reader, "m.fcl", mutant);
                    reader.giveaways(mutant);
                    DialectReaders.auto(mutant);
                }
            }
        });
    }
}
