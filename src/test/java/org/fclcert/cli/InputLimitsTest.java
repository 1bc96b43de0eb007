package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fclcert.model.Limits;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 18 item 12 and "every limit named once": every file fclcert reads — a program, a CSV table, a corpus
 * case, a results file — goes through {@link Limits#readFile}: a device, a FIFO or a file beyond
 * {@link Limits#MAX_SOURCE_BYTES} gets a plain error at once (no hang, no heap exhaustion, no exit 3).
 */
class InputLimitsTest {
    private static final String TOO_LARGE = "larger than fclcert's limit of 128 MiB (org.fclcert.model.Limits.MAX_SOURCE_BYTES)";
    private static final String NOT_A_FILE = "not a regular file (a device, pipe or socket); fclcert reads only files";

    @TempDir
    Path dir;

    /** A file beyond the limit, made sparse: it takes no disk space and no time to write. */
    private Path huge(String name) throws Exception {
        Path p = dir.resolve(name);
        try (RandomAccessFile f = new RandomAccessFile(p.toFile(), "rw")) {
            f.setLength(Limits.MAX_SOURCE_BYTES + 1);
        }
        return p;
    }

    private Path fifo() throws Exception {
        Path p = dir.resolve("fifo");
        assertEquals(0, new ProcessBuilder("mkfifo", p.toString()).start().waitFor());
        return p;
    }

    @Test
    void aResultsFileThatIsADeviceAFifoOrTooLargeIsAPlainError() throws Exception {
        for (Path from : List.of(Path.of("/dev/zero"), fifo(), huge("results.jsonl"))) {
            Cli c = Cli.run("report", "--from", from.toString(), "--out", dir.resolve("out").toString());
            assertEquals(2, c.exitCode(), from + ": " + c.err());
            assertTrue(c.err().equals("fclcert report: cannot read " + from + ": " + NOT_A_FILE + "\n")
                    || c.err().equals("fclcert report: cannot read " + from + ": " + TOO_LARGE + "\n"), c.err());
        }
    }

    @Test
    void aCsvTableOrProgramThatIsADeviceAFifoOrTooLargeIsAPlainError() throws Exception {
        Path fifo = fifo();
        Cli csv = Cli.run("eval", "--csv", fifo.toString(), "examples/valve.fcl");
        assertEquals(2, csv.exitCode(), csv.err());
        assertEquals("fclcert: cannot read " + fifo + ": " + NOT_A_FILE + "\n", csv.err());
        Path big = huge("big.csv");
        Cli large = Cli.run("eval", "--csv", big.toString(), "examples/valve.fcl");
        assertEquals(2, large.exitCode(), large.err());
        assertEquals("fclcert: cannot read " + big + ": " + TOO_LARGE + "\n", large.err());
        Cli program = Cli.run("check", huge("big.fcl").toString());
        assertEquals(2, program.exitCode(), program.err());
        assertTrue(program.err().contains(TOO_LARGE), program.err());
    }

    @Test
    void aCorpusCaseBeyondTheLimitIsACorpusProblem() throws Exception {
        Path corpus = dir.resolve("corpus");
        Files.createDirectories(corpus);
        Files.copy(Path.of("src/test/resources/corpus-process/B-FB-001.fcl"), corpus.resolve("B-FB-001.fcl"));
        Files.move(huge("B-FB-002.fcl"), corpus.resolve("B-FB-002.fcl"));
        Cli c = Cli.run("certify", "--corpus", corpus.toString(), "--out", dir.resolve("out").toString(), "--no-probe");
        assertEquals(2, c.exitCode(), c.err());
        assertTrue(c.err().contains(corpus.resolve("B-FB-002.fcl") + ": cannot read the file: " + TOO_LARGE), c.err());
    }

    @Test
    void aResultsFileWithBytesThatAreNotUtf8IsReadWithAWarning() throws Exception {
        Path run = dir.resolve("run");
        Cli certify = Cli.run("certify", "--corpus", "src/test/resources/corpus-process", "--out", run.toString(),
                "--no-probe", "--no-fresh-evidence");
        assertEquals(0, certify.exitCode(), certify.err());
        byte[] bytes = Files.readAllBytes(run.resolve("results.jsonl"));
        String text = new String(bytes, StandardCharsets.UTF_8);
        int at = text.indexOf("Process-path case 2", text.indexOf("{\"type\":\"case\",\"id\":\"B-FB-002\""));
        bytes[text.substring(0, at).getBytes(StandardCharsets.UTF_8).length] = (byte) 0xFF;   // 'P' becomes 0xFF
        Files.write(run.resolve("results.jsonl"), bytes);
        Cli c = Cli.run("report", "--from", run.resolve("results.jsonl").toString(), "--out", dir.resolve("out").toString());
        assertEquals(0, c.exitCode(), c.err());
        assertTrue(c.err().contains("results.jsonl: bytes that are not UTF-8 read as U+FFFD (the file is damaged)"),
                c.err());
        var kept = org.fclcert.report.JsonReport.read(dir.resolve("out/report.json")).cases().stream()
                .filter(r -> r.id().equals("B-FB-002")).findFirst().orElseThrow();
        assertTrue(kept.title().startsWith("\uFFFDrocess-path case 2"), "the case is kept, its title repaired: " + kept.title());
        assertFalse(c.err().contains("Exception"), c.err());
    }
}
