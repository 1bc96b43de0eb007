package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.ResultSink;
import org.fclcert.harness.RunCase;
import org.fclcert.harness.RunCases;
import org.fclcert.harness.RunHeader;
import org.fclcert.harness.RunHeaders;
import org.fclcert.harness.Runner;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;

/**
 * Coverage-guided fuzzing (Jazzer) of the corpus case reader: the bytes are one case file of a corpus given with
 * {@code --corpus}. Properties: the reader never throws; it returns a case or at least one problem, each located
 * in the file (line 0 for the whole file, else a line of it); a case keeps the program's line numbers (the
 * metadata comment becomes as many line breaks); and a case read runs on the reference through the harness
 * ({@link Runner}) to exactly one result for its id, whatever its metadata says. docs/fuzzing-readers.md says how
 * to fuzz for a budget.
 */
class CaseReaderFuzzTest {
    private static final int MAX_TEXT = 20_000;
    private static final Path FILE = Path.of("fuzz", "case.fcl");
    /** The runner returns the results; nothing is written. */
    private static final ResultSink NOWHERE = new ResultSink() {
        @Override
        public void header(RunHeader header) {
        }

        @Override
        public void accept(CaseResult result) {
        }
    };

    @FuzzTest(maxDuration = "10m")
    void caseReader(byte[] bytes) throws Exception {
        String text = new String(bytes, StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        List<CorpusProblem> problems = new ArrayList<>();
        Optional<CorpusCase> read = CaseFileReader.read(FILE, text, problems);
        assertTrue(read.isPresent() != !problems.isEmpty(), "a case, or problems: " + problems);
        long lines = text.chars().filter(c -> c == '\n').count() + 1;
        for (CorpusProblem p : problems) {
            assertEquals(FILE, p.file());
            assertTrue(p.line() >= 0 && p.line() <= lines + 1, () -> "line " + p.line() + " of " + lines + ": " + p);
            assertFalse(p.message().isBlank());
        }
        if (read.isEmpty()) {
            return;
        }
        CorpusCase c = read.get();
        assertEquals(text.chars().filter(ch -> ch == '\n').count(), c.programText().chars().filter(ch -> ch == '\n').count(),
                "the program keeps its line numbers");
        RunCase run = RunCases.from(c);
        List<CaseResult> results;
        try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
            RunHeader header = RunHeaders.of(reference.hello(), "reference", null, "fuzz", "", List.of(run),
                    List.of(run), List.of(List.of(), List.of(), List.of()));
            results = new Runner(org.fclcert.harness.RunListener.NONE).run(reference, header, List.of(run), NOWHERE);
        }
        assertEquals(1, results.size());
        assertEquals(c.id(), results.get(0).id());
    }
}
