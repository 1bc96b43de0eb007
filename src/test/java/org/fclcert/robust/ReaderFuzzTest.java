package org.fclcert.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;

/**
 * Coverage-guided fuzzing (Jazzer) of the readers of untrusted FCL text, with properties beyond "no
 * exception": a reader returns diagnostics and never throws nor reports an internal error (FCL-S999);
 * what the strict reader and the checks accept is written by fmt as text that reads back clean to the
 * same model (so it evaluates identically) and is a fixed point; what a dialect reader accepts converts
 * to a program that reads back strictly without errors. {@code mvn verify} replays the committed inputs
 * under {@code src/test/resources/org/fclcert/robust/ReaderFuzzTestInputs/<method>/}; how to fuzz for a
 * budget is in docs/fuzzing-readers.md.
 */
class ReaderFuzzTest {
    private static final int MAX_TEXT = 20_000;

    @FuzzTest(maxDuration = "10m")
    void strictReaderChecksAndFmt(byte[] bytes) {
        String text = new String(bytes, java.nio.charset.StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        Analysis a = Analysis.analyze(new StrictReader(), "fuzz.fcl", text);
        assertNoInternalError(a.diagnostics());
        if (a.program().isEmpty() || a.hasErrors()) {
            return;
        }
        String written = new CanonicalWriter().write(a.program().get());
        Analysis back = Analysis.analyze(new StrictReader(), "fmt.fcl", written);
        assertFalse(back.hasErrors(), () -> "fmt output does not check clean: " + back.diagnostics() + "\n" + written);
        assertEquals(a.program().get().functionBlocks(), back.program().orElseThrow().functionBlocks(),
                "fmt changed the model");
        assertEquals(written, new CanonicalWriter().write(back.program().get()), "fmt is not a fixed point");
    }

    @FuzzTest(maxDuration = "10m")
    void dialectReadersAndConvert(byte[] bytes) {
        if (bytes.length == 0) {
            return;
        }
        Dialect[] dialects = {Dialect.FFLL, Dialect.JFUZZYLOGIC, Dialect.FUZZYLITE};
        Dialect dialect = dialects[Math.floorMod(bytes[0], dialects.length)];
        String text = new String(bytes, 1, bytes.length - 1, java.nio.charset.StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        DialectReaders.Choice auto = DialectReaders.auto(text);
        assertTrue(auto.problem().stream().noneMatch(d -> d.code().equals("FCL-S999")), () -> "auto: " + auto.problem());
        FclReader reader = DialectReaders.reader(dialect);
        Analysis a = Analysis.analyze(reader, "fuzz.fcl", text);
        assertNoInternalError(a.diagnostics());
        if (a.program().isEmpty() || a.hasErrors()) {
            return;
        }
        Program converted = new StandardConversion().convert(a.program().get()).program();
        String standard = new CanonicalWriter().write(converted);
        Analysis back = Analysis.analyze(new StrictReader(), "converted.fcl", standard);
        assertFalse(back.hasErrors(), () -> dialect + ": converted program is not valid standard FCL: "
                + back.diagnostics() + "\n" + standard);
    }

    private static void assertNoInternalError(List<Diagnostic> diagnostics) {
        for (Diagnostic d : diagnostics) {
            assertFalse(d.code().equals("FCL-S999"), () -> "internal error: " + d);
        }
    }
}
