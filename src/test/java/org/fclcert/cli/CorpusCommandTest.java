package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CorpusCommandTest {
    @TempDir
    Path dir;

    private String out;
    private String err;

    private int run(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            return Main.run(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out = o.toString(StandardCharsets.UTF_8);
            err = e.toString(StandardCharsets.UTF_8);
        }
    }

    @Test
    void lintReportsFindingsWithExitStatusOne() throws Exception {
        Files.createDirectories(dir.resolve("basic"));
        Files.writeString(dir.resolve("basic/B-FB-001.fcl"), "FUNCTION_BLOCK f END_FUNCTION_BLOCK\n");
        assertEquals(1, run("corpus", "lint", dir.toString()));
        assertTrue(out.contains("B-FB-001.fcl:1: a case file must start with the metadata comment"), out);
        assertTrue(out.contains("coverage: 0 negative case(s); at least 40 needed"), out);
        assertTrue(out.contains("0 cases (0 positive, 0 negative): "), out);
    }

    @Test
    void aMissingDirectoryIsAUsageError() {
        assertEquals(2, run("corpus", "lint", dir.resolve("nope").toString()));
        assertTrue(err.contains("is not a directory"), err);
    }

    @Test
    void theRealCorpusLintsCleanWithExitStatusZero() {
        assertEquals(0, run("corpus", "lint", "conformance"), out);
        assertTrue(out.strip().endsWith("negative): clean"), out);
    }
}
