package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.fclcert.harness.ResultsFile;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two runs into one output directory (issue 27: both exited 0 and left one results file of both implementations
 * under one header): the second refuses at once, naming the first and its pid, and the first's outputs are its own.
 */
class SharedOutputDirectoryTest {
    private static final String CORPUS = "src/test/resources/corpus-process";

    @TempDir
    Path dir;

    @Test
    void aSecondRunIntoTheSameDirectoryRefusesAtOnceNamingTheFirst() throws Exception {
        Path out = dir.resolve("out");
        AtomicInteger firstExit = new AtomicInteger(-1);
        StringWriter firstErr = new StringWriter();
        Thread first = new Thread(() -> firstExit.set(Main.run(new PrintWriter(new StringWriter()),
                new PrintWriter(firstErr), "certify", "--iut", "process:python3 src/test/resources/iut/slow.py 0.3",
                "--corpus", CORPUS, "--out", out.toString(), "--no-probe", "--no-fresh-evidence")));
        first.start();
        Path lock = dir.resolve(".out.lock");
        long until = System.nanoTime() + 30_000_000_000L;
        while (!(Files.exists(lock) && Files.readString(lock).startsWith("pid ")) && System.nanoTime() < until) {
            Thread.sleep(20);
        }
        assertTrue(first.isAlive(), "the first run still runs: " + firstErr);

        StringWriter err = new StringWriter();
        long start = System.nanoTime();
        int exit = Main.run(new PrintWriter(new StringWriter()), new PrintWriter(err), "certify", "--iut",
                "process:python3 src/test/resources/iut/well_behaved.py", "--corpus", CORPUS, "--out", out.toString(),
                "--no-probe", "--no-fresh-evidence");
        long millis = (System.nanoTime() - start) / 1_000_000;
        assertEquals(2, exit, err.toString());
        assertTrue(err.toString().contains("is in use by another fclcert run (pid " + ProcessHandle.current().pid()
                + ", started "), err.toString());
        assertTrue(millis < 5000, "refused at once, not after a run: " + millis + " ms");

        first.join(120_000);
        assertEquals(0, firstExit.get(), firstErr.toString());
        Report report = JsonReport.read(out.resolve("report.json"));
        assertEquals("slow", report.iut().name());
        ResultsFile results = ResultsFile.read(out.resolve("results.jsonl"));
        assertEquals("slow", results.header().iut().name());
        assertEquals(List.of("B-FB-001", "B-FB-002", "B-FB-003", "B-FB-901"),
                results.results().stream().map(r -> r.id()).sorted().toList(), "each case once, of one run");
        try (var siblings = Files.list(dir)) {
            assertFalse(siblings.anyMatch(p -> p.getFileName().toString().contains(".partial-")),
                    "the private sibling is gone once its files are in place");
        }
    }
}
