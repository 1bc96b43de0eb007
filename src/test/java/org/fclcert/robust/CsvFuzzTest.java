package org.fclcert.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fclcert.cli.Main;

/**
 * Coverage-guided fuzzing (Jazzer) of {@code fclcert eval --csv TABLE examples/valve.fcl}: the bytes are the CSV
 * table. Properties: the command exits 0, 1 or 2, never 3 (an internal error), and never shows a stack trace; a
 * refusal is a sentence on stderr naming the table; a table it evaluates gives the header
 * {@code temp,pressure,valve} and, for each data row, one line of three decimal numbers; no control character of
 * the table reaches the terminal raw. docs/fuzzing-readers.md
 * says how to fuzz for a budget.
 */
class CsvFuzzTest {
    private static final int MAX_BYTES = 20_000;
    private static final Path TABLE = tempTable();

    private static Path tempTable() {
        try {
            Path p = Files.createTempFile("fclcert-fuzz-", ".csv");
            p.toFile().deleteOnExit();
            return p;
        } catch (java.io.IOException e) {
            throw new IllegalStateException(e);
        }
    }

    @FuzzTest(maxDuration = "10m")
    void evalCsv(byte[] bytes) throws Exception {
        if (bytes.length > MAX_BYTES) {
            return;
        }
        Files.write(TABLE, bytes);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int exit = Main.run(new PrintWriter(out), new PrintWriter(err), "eval", "--csv", TABLE.toString(),
                "examples/valve.fcl");
        String e = err.toString();
        assertTrue(exit == 0 || exit == 1 || exit == 2, () -> "exit " + exit + ": " + e);
        // the table's text may say anything (even "internal error"): only fclcert's own lines count
        assertFalse(e.lines().anyMatch(l -> l.startsWith("fclcert: internal error") || l.startsWith("\tat ")
                || l.startsWith("Exception in thread") || l.startsWith("java.")), e);
        assertTrue(e.chars().noneMatch(c -> c < 0x20 && c != '\n' || c == 0x7f),
                () -> "a control character of the table reached the terminal raw: " + e);
        if (exit != 0) {
            assertTrue(e.startsWith("fclcert: ") && e.contains(TABLE.toString()), e);
            return;
        }
        List<String> lines = out.toString().lines().toList();
        assertEquals("temp,pressure,valve", lines.get(0));
        for (String line : lines.subList(1, lines.size())) {
            String[] cells = line.split(",", -1);
            assertEquals(3, cells.length, line);
            for (String cell : cells) {
                Double.parseDouble(cell);
            }
        }
        long rows = new String(bytes, java.nio.charset.StandardCharsets.UTF_8).replaceFirst("^\uFEFF", "").lines()
                .map(String::strip)
                .filter(l -> !l.isEmpty() && !l.startsWith("#")).count() - 1;
        assertEquals(rows, lines.size() - 1, "one line per data row");
    }
}
