package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Coverage-guided fuzzing (Jazzer) of the strict reader's fast path against its full pipeline: on any text, the
 * reader with the {@link DirectParser} gives what the reader without it gives (program with every location,
 * diagnostics, repaired program), under the standard's and the corpus's reader options, and what the direct
 * parser reads has no error. {@code mvn verify} replays the committed inputs under
 * {@code src/test/resources/org/fclcert/syntax/DirectParserFuzzTestInputs/}; docs/fuzzing-readers.md says how to
 * fuzz for a budget. {@link DirectParserTest} does the same on chosen texts and their mutations.
 */
class DirectParserFuzzTest {
    private static final int MAX_TEXT = 20_000;

    @FuzzTest(maxDuration = "10m")
    void sameResultAsTheFullPipeline(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        for (ReaderOptions options : List.of(ReaderOptions.STRICT, ReaderOptions.OPEN_LEVEL)) {
            ReadResult full = new StrictReader(options, false).read("f.fcl", text);
            ReadResult fast = new StrictReader(options, true).read("f.fcl", text);
            assertNull(DirectParserTest.difference(full, fast, "result"), text);
            boolean direct = DirectParser.program("f.fcl", text.startsWith("\uFEFF") ? text.substring(1) : text,
                    options, new ReaderDiagnostics("f.fcl")).isPresent();
            assertFalse(direct && full.hasErrors(), () -> "read directly, but " + full.diagnostics());
        }
    }
}
