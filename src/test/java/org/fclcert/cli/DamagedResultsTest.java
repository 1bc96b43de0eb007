package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code report --from} on damaged results files: located, plain warnings or errors; never a crash (exit 3). */
class DamagedResultsTest {
    @TempDir
    Path dir;
    private List<String> lines;

    @BeforeEach
    void certify() throws Exception {
        Cli run = Cli.run("certify", "--iut", "process:python3 src/test/resources/iut/well_behaved.py",
                "--corpus", "src/test/resources/corpus-process", "--out", dir.toString(), "--no-probe", "--no-fresh-evidence");
        assertEquals(0, run.exitCode(), run.err());
        lines = Files.readAllLines(dir.resolve("results.jsonl"));
        assertTrue(lines.get(0).contains("\"type\":\"run\"") && lines.get(2).contains("\"type\":\"case\""));
    }

    private Cli reportFrom(List<String> damaged) throws Exception {
        Path file = Files.write(dir.resolve("damaged.jsonl"), damaged);
        return Cli.run("report", "--from", file.toString(), "--out", dir.resolve("again").toString());
    }

    private static void plain(Cli run) {
        String all = run.out() + run.err();
        assertFalse(all.contains("org.fclcert") || all.contains("java.") || all.contains("Exception")
                || all.contains("internal error"), all);
    }

    @Test
    void aCaseLineWithoutStatusOrIdIsAWarningAtItsLine() throws Exception {
        for (String field : List.of("status", "id")) {
            List<String> damaged = new ArrayList<>(lines);
            damaged.set(2, damaged.get(2).replaceFirst("\"" + field + "\":\"[^\"]*\",", ""));
            Cli run = reportFrom(damaged);
            assertEquals(0, run.exitCode(), run.err());
            assertTrue(run.err().contains("damaged.jsonl:3: case line without '" + field + "' ignored"), run.err());
            plain(run);
        }
    }

    @Test
    void aStatusOfTheWrongKindIsAPlainWarning() throws Exception {
        List<String> damaged = new ArrayList<>(lines);
        damaged.set(2, damaged.get(2).replaceFirst("\"status\":\"[^\"]*\"", "\"status\":\"splendid\""));
        Cli run = reportFrom(damaged);
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.err().contains("damaged.jsonl:3: line ignored: field 'status' has a value of the wrong kind"),
                run.err());
        plain(run);
    }

    @Test
    void aHeaderWithoutCorpusIsALocatedError() throws Exception {
        List<String> damaged = new ArrayList<>(lines);
        damaged.set(0, damaged.get(0).replaceFirst("\"corpus\":\\{[^{}]*(\\{[^}]*\\})?[^}]*\\},", ""));
        assertFalse(damaged.get(0).contains("\"corpus\""), damaged.get(0));
        Cli run = reportFrom(damaged);
        assertEquals(2, run.exitCode(), run.err());
        assertTrue(run.err().contains("damaged.jsonl:1: the run header has no 'corpus' object"), run.err());
        plain(run);
    }
}
