package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.fclcert.model.Limits;
import org.fclcert.model.Program;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * The writer's contract: for every program the strict reader accepts, reading the canonical text
 * gives the same model (locations aside, SourceLocation equality being always true), and writing
 * that again gives the same text.
 */
class RoundTripTest {
    /** Where FCL programs live in this repository: examples, test resources and the corpus. */
    private static final List<Path> PROGRAM_DIRECTORIES =
            List.of(Path.of("examples"), Path.of("src/test/resources"), Path.of("conformance"));

    private final StrictReader reader = new StrictReader();
    private final CanonicalWriter writer = new CanonicalWriter();

    @TestFactory
    Stream<DynamicTest> everyProgramInTheRepositoryRoundTrips() {
        List<Path> files = programFiles();
        assertFalse(files.isEmpty(), "no .fcl files found; run from the repository root");
        return files.stream()
                .map(f -> DynamicTest.dynamicTest(f.toString(), () -> roundTripIfValid(f.toString(), read(f))));
    }

    @Test
    void generatedProgramsCoveringEveryConstructRoundTrip() {
        List<Program> programs = generated();
        assertEquals(new TreeSet<>(Constructs.ALL), Constructs.of(programs), "the generator misses a construct");
        programs.forEach(this::assertRoundTrip);
    }

    @Test
    void negativeZeroKeepsItsSign() {
        // record equality compares doubles bit-wise, so -0.0 and 0.0 differ and the sign must survive
        String text = """
                FUNCTION_BLOCK z
                VAR_INPUT a : REAL := -0; b : LREAL := -0.0; END_VAR
                FUZZIFY a TERM t := (-0.0, 0) (1, 1); END_FUZZIFY
                END_FUNCTION_BLOCK
                """;
        Program model = reader.read("z.fcl", text).program().orElseThrow();
        assertEquals(Double.doubleToRawLongBits(-0.0),
                Double.doubleToRawLongBits(model.functionBlocks().get(0).variables().get(0).initialValue().orElseThrow().value()));
        assertTrue(writer.write(model).contains("a : REAL := -0;\n    b : LREAL := -0.0;"), writer.write(model));
        assertRoundTrip(model);
    }

    @Test
    void nestingAtTheDocumentedLimitAndLongChainsRoundTrip() {
        int depth = Limits.MAX_NESTING_DEPTH;
        String nested = "(".repeat(depth) + "x IS low" + ")".repeat(depth);
        String chain = String.join(" AND ", Collections.nCopies(20_000, "x IS low"));
        String text = """
                FUNCTION_BLOCK deep
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM low := (0, 1) (1, 0); END_FUZZIFY
                DEFUZZIFY y TERM one := 1; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACCU : MAX;
                RULE 1 : IF %s THEN y IS one;
                RULE 2 : IF %s THEN y IS one;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """.formatted(nested, chain);
        ReadResult read = reader.read("deep.fcl", text);
        assertTrue(read.program().isPresent(), () -> read.diagnostics().toString());
        assertRoundTrip(read.program().get());
        assertTrue(writer.write(read.program().get()).contains("RULE 1 : IF " + nested + " THEN y IS one;\n"));
    }

    private static List<Program> generated() {
        RandomPrograms random = new RandomPrograms(61_131_7L);
        return java.util.stream.IntStream.range(0, 300).mapToObj(i -> random.program("generated-" + i + ".fcl")).toList();
    }

    private void roundTripIfValid(String name, String text) {
        ReadResult read = reader.read(name, text);
        // files that are meant to be rejected (negative corpus cases, broken examples) have no model to write
        read.program().ifPresent(this::assertRoundTrip);
    }

    private void assertRoundTrip(Program model) {
        String text = writer.write(model);
        ReadResult again = reader.read(model.sourceName(), text);
        assertTrue(again.program().isPresent(), () -> "canonical text not readable: " + again.diagnostics() + "\n" + text);
        assertEquals(model, again.program().get(), text);
        assertEquals(text, writer.write(again.program().get()), "write is not idempotent");
    }

    private static List<Path> programFiles() {
        return PROGRAM_DIRECTORIES.stream().filter(Files::isDirectory).flatMap(RoundTripTest::fclFilesUnder).sorted().toList();
    }

    private static Stream<Path> fclFilesUnder(Path dir) {
        try (Stream<Path> walk = Files.walk(dir)) {
            return walk.filter(p -> p.toString().endsWith(".fcl")).toList().stream();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String read(Path file) {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
