package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ResultsFile;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 18 item 4 and the run budget (item 13): a certification or a probe stopped by SIGINT, SIGTERM, Ctrl-C
 * (SIGINT to the whole process group, the implementation included) or its budget ends in bounded time with every
 * output written and agreeing, every case exactly once, the cases not run reported as such with the reason —
 * never blamed on the implementation — and no process of the implementation left running.
 * {@code src/test/resources/iut/slow.py DELAY PIDFILE} answers each request after DELAY seconds and writes its
 * pid and its child's.
 */
class InterruptedRunTest {
    private static final String CORPUS = "src/test/resources/corpus-process";
    private static final List<String> IDS = List.of("B-FB-001", "B-FB-002", "B-FB-003", "B-FB-901");
    private static final String INTERRUPTED = "not run: the run was stopped: interrupted (SIGINT, SIGTERM or SIGHUP)";
    /** Far above what each run takes (a few seconds), far below what it would take unstopped. */
    private static final long BOUND_SECONDS = 30;

    @TempDir
    Path dir;

    /** Run with --no-sandbox: the test reads the host pids it writes (the sandbox's own cleanup: SandboxedRunTest). */
    private String slow(double delay) {
        return "process:python3 src/test/resources/iut/slow.py " + delay + " " + dir.resolve("pids");
    }

    /** fclcert in a JVM of its own, the leader of a process group of its own (as a shell starts a command). */
    private Process start(String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of("setsid", Path.of(System.getProperty("java.home"), "bin",
                "java").toString(), "-cp", System.getProperty("java.class.path"), "org.fclcert.cli.Main"));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectOutput(dir.resolve("stdout").toFile())
                .redirectError(dir.resolve("stderr").toFile()).start();
    }

    private static void signal(String signal, String target) throws Exception {
        Process kill = new ProcessBuilder("kill", "-" + signal, "--", target).redirectErrorStream(true).start();
        assertEquals(0, kill.waitFor(), new String(kill.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
    }

    /** Waits until {@code file} has at least {@code lines} lines. */
    private static void awaitLines(Path file, int lines) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(BOUND_SECONDS);
        while (System.nanoTime() < end) {
            if (Files.exists(file) && Files.readAllLines(file).size() >= lines) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError(file + " never reached " + lines + " lines");
    }

    /**
     * The results file a run into {@code out} streams to: in its private sibling {@code .out.partial-…} until the
     * run ends and moves it into place.
     */
    private static Path streaming(Path out) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(BOUND_SECONDS);
        while (System.nanoTime() < end) {
            try (var siblings = Files.list(out.getParent())) {
                var partial = siblings.filter(p -> p.getFileName().toString().startsWith("." + out.getFileName()
                        + ".partial-")).findFirst();
                if (partial.isPresent()) {
                    return partial.get().resolve("results.jsonl");
                }
            }
            Thread.sleep(50);
        }
        throw new AssertionError("no run is writing into " + out);
    }

    private static int awaitExit(Process p) throws Exception {
        assertTrue(p.waitFor(BOUND_SECONDS, TimeUnit.SECONDS), "ended in bounded time");
        return p.exitValue();
    }

    private String text(String name) throws IOException {
        return Files.readString(dir.resolve(name));
    }

    /** Every process the implementation and its child ran as has ended. */
    private void noSurvivors() throws Exception {
        List<Long> pids = Files.readAllLines(dir.resolve("pids")).stream().map(Long::valueOf).toList();
        assertFalse(pids.isEmpty());
        for (long pid : pids) {
            var handle = ProcessHandle.of(pid);
            if (handle.isPresent()) {
                handle.get().onExit().get(5, TimeUnit.SECONDS);
            }
            assertTrue(ProcessHandle.of(pid).map(h -> !h.isAlive()).orElse(true), "process " + pid + " survives");
        }
    }

    /**
     * The five outputs of {@code out} agree, hold every case once, none blamed on the implementation, the cases
     * not run say why; {@code report --from} rebuilds the same report. Returns the report.
     */
    private Report agreeing(Path out, String notRun) throws Exception {
        for (String f : List.of("results.jsonl", "report.json", "report.md", "report.html", "junit.xml")) {
            assertTrue(Files.size(out.resolve(f)) > 0, f + " written");
        }
        ResultsFile results = ResultsFile.read(out.resolve("results.jsonl"));
        assertEquals(List.of(), results.problems(), "no torn line");
        assertEquals(IDS, results.results().stream().map(CaseResult::id).sorted().toList(), "each case once");
        Report report = JsonReport.read(out.resolve("report.json"));
        assertEquals(statuses(results.results()), statuses(report.cases()), "results.jsonl and report.json agree");
        assertFalse(report.run().complete(), "a stopped run is not complete");
        long stopped = 0;
        for (CaseResult c : report.cases()) {
            // the fakes accept every program: the negative case B-FB-901, when run, fails
            CaseStatus run = c.id().equals("B-FB-901") ? CaseStatus.FAILED : CaseStatus.PASSED;
            assertTrue(c.status() == run || c.status() == CaseStatus.SKIPPED,
                    c.id() + " is the implementation's fault? " + c.status() + ": " + c.message());
            if (c.status() == CaseStatus.SKIPPED) {
                assertEquals(notRun, c.message(), c.id());
                stopped++;
            }
        }
        assertTrue(stopped > 0, "some case was not run");
        String junit = Files.readString(out.resolve("junit.xml"));
        for (String id : IDS) {
            assertEquals(1, junit.split("name=\"" + id, -1).length - 1, id + " once in junit.xml");
        }
        Path again = dir.resolve("again");
        PrintWriter sink = new PrintWriter(new ByteArrayOutputStream());
        assertEquals(0, Main.run(sink, sink, "report", "--from", out.resolve("results.jsonl").toString(), "--out",
                again.toString()));
        Report rebuilt = JsonReport.read(again.resolve("report.json"));
        assertEquals(messages(report.cases()), messages(rebuilt.cases()), "report --from agrees, blames no one");
        return report;
    }

    private static Map<String, CaseStatus> statuses(List<CaseResult> results) {
        return results.stream().collect(Collectors.toMap(CaseResult::id, CaseResult::status, (a, b) -> a, TreeMap::new));
    }

    private static Map<String, String> messages(List<CaseResult> results) {
        return results.stream().collect(Collectors.toMap(CaseResult::id, c -> c.status() + ": " + c.message(),
                (a, b) -> a, TreeMap::new));
    }

    private void interruptCertify(String signal, boolean wholeGroup, int exitCode) throws Exception {
        Path out = dir.resolve("out");
        Process p = start("certify", "--iut", slow(0.25), "--no-sandbox", "--corpus", CORPUS, "--out", out.toString(), "--no-probe",
                "--no-fresh-evidence");
        awaitLines(streaming(out), 2);   // the header and the first case: the second is under way
        signal(signal, wholeGroup ? "-" + p.pid() : String.valueOf(p.pid()));
        assertEquals(exitCode, awaitExit(p), () -> "stderr: " + safeText("stderr"));
        agreeing(out, INTERRUPTED);
        String err = text("stderr");
        assertTrue(err.contains("fclcert certify: the run was stopped (interrupted (SIGINT, SIGTERM or SIGHUP)) after "), err);
        assertFalse(err.contains("Exception") || err.contains("internal error"), err);
        assertFalse(err.contains("SKIPPED B-FB-"), "one line for the stop, not one per case left: " + err);
        assertTrue(text("stdout").contains("slow 1.0: 4 cases, "), text("stdout"));
        noSurvivors();
    }

    private String safeText(String name) {
        try {
            return text(name);
        } catch (IOException e) {
            return e.toString();
        }
    }

    @Test
    void sigintStopsTheRunWithEveryCaseOnceAndTheReportsWritten() throws Exception {
        interruptCertify("INT", false, 130);
    }

    @Test
    void sigtermStopsTheRunTheSameWay() throws Exception {
        interruptCertify("TERM", false, 143);
    }

    @Test
    void sighupStopsTheRunTheSameWay() throws Exception {
        interruptCertify("HUP", false, 129);
    }

    @Test
    void ctrlCReachingTheImplementationTooIsNotItsFault() throws Exception {
        // Ctrl-C signals the terminal's whole process group: the implementation dies of it as well
        interruptCertify("INT", true, 130);
    }

    @Test
    void theRunBudgetStopsASlowButLegalImplementation() throws Exception {
        // 0.85 s per request under a 1 s timeout: 4 cases of up to 7 requests, some 20 s unstopped; the corpus's
        // thousands of requests would be hours
        Path out = dir.resolve("out");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintWriter errWriter = new PrintWriter(err, true, StandardCharsets.UTF_8);
        int exit = Main.run(new PrintWriter(new ByteArrayOutputStream()), errWriter, "certify", "--iut", slow(0.85), "--no-sandbox",
                "--timeout", "1s", "--budget", "2s", "--no-fresh-evidence", "--corpus", CORPUS, "--out", out.toString(), "--probe-cap", "4");
        assertEquals(2, exit, err.toString(StandardCharsets.UTF_8));
        Report r = agreeing(out, "not run: the run was stopped: the run budget of 2s ran out");
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("the run was stopped (the run budget of 2s ran out)"),
                err.toString(StandardCharsets.UTF_8));
        assertEquals(22, r.dataCheckList().size());
        for (DataCheckEntry e : r.dataCheckList()) {
            assertEquals(DataCheckEntry.NOT_MEASURED, e.bound(), e.id());
            assertEquals("not measured: the run was stopped: the run budget of 2s ran out", e.note(), e.id());
        }
        noSurvivors();
    }

    @Test
    void anInterruptedProbeStopsItsImplementationAndShowsWhatItMeasured() throws Exception {
        Path out = dir.resolve("probe");
        Process p = start("probe", "--iut", slow(0.02), "--no-sandbox", "--cap", "64", "--out", out.toString());
        awaitLines(dir.resolve("pids"), 2);
        Thread.sleep(3000);   // some rows measured, one under way
        signal("INT", String.valueOf(p.pid()));
        assertEquals(130, awaitExit(p), () -> "stderr: " + safeText("stderr"));
        String err = text("stderr");
        assertTrue(err.contains("fclcert probe: stopped (interrupted (SIGINT, SIGTERM or SIGHUP)) after "), err);
        List<String> rows = text("stdout").lines().toList();
        assertEquals(22, rows.size(), text("stdout"));
        assertTrue(rows.get(0).startsWith("data-types "), rows.get(0));
        assertTrue(rows.get(21).contains("not measured: the probe was stopped: interrupted (SIGINT, SIGTERM or SIGHUP)"),
                rows.get(21));
        List<DataCheckEntry> written = List.of(new com.fasterxml.jackson.databind.ObjectMapper()
                .readValue(out.resolve("data-check-list.json").toFile(), DataCheckEntry[].class));
        assertEquals(22, written.size());
        assertEquals(DataCheckEntry.NOT_MEASURED, written.get(21).bound());
        noSurvivors();
    }

    @Test
    void theProbeBudgetBoundsASlowImplementation() throws Exception {
        // the data-types row alone is 50 requests: 42 s at 0.85 s each, and the execution-time row's warm-up 425 s
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int exit = Main.run(new PrintWriter(out, true, StandardCharsets.UTF_8), new PrintWriter(new ByteArrayOutputStream()),
                "probe", "--iut", slow(0.85), "--no-sandbox", "--timeout", "1s", "--cap", "8", "--budget", "2s", "--format", "json");
        assertEquals(0, exit);
        List<DataCheckEntry> rows = List.of(new com.fasterxml.jackson.databind.ObjectMapper()
                .readValue(out.toByteArray(), DataCheckEntry[].class));
        assertEquals(22, rows.size());
        assertEquals("not measured: the probe was stopped: the probe budget of 2s ran out during this row",
                rows.get(0).note());
        for (DataCheckEntry e : rows.subList(1, 22)) {
            assertEquals("not measured: the probe was stopped: the probe budget of 2s ran out", e.note(), e.id());
        }
        noSurvivors();
    }

    /**
     * A fuzz run stopped by a signal writes what it found so far (the same "never lost results" as certify): the
     * fake answers every output with the sum of the inputs, so the first programs disagree and a shrink is under way
     * when the signal comes; it ends there, and the finding is written, with the run marked as stopped. Every process
     * of the implementation ends.
     */
    @Test
    void anInterruptedFuzzRunWritesTheFindingsSoFar() throws Exception {
        Path out = dir.resolve("fuzz");
        Process p = start("fuzz", "--iut", slow(0.01), "--no-sandbox", "--budget", "10m", "--seed", "5", "--out",
                out.toString());
        awaitLines(dir.resolve("pids"), 2);
        Thread.sleep(4000);   // a few programs, the first disagreement being shrunk
        signal("TERM", String.valueOf(p.pid()));
        assertEquals(143, awaitExit(p), () -> "stderr: " + safeText("stderr"));
        String err = text("stderr");
        assertTrue(err.contains("fclcert fuzz: the run was stopped (interrupted (SIGINT, SIGTERM or SIGHUP)) after "), err);
        assertFalse(err.contains("Exception") || err.contains("internal error"), err);
        var json = new com.fasterxml.jackson.databind.ObjectMapper().readTree(out.resolve("fuzz.json").toFile());
        assertEquals("interrupted (SIGINT, SIGTERM or SIGHUP)", json.path("run").path("stopped").asText());
        assertTrue(json.path("counts").path("findings").asInt() >= 1, json.toString());
        assertEquals(json.path("counts").path("findings").asInt(), json.path("findings").size());
        for (var f : json.path("findings")) {
            assertTrue(Files.exists(out.resolve(f.path("file").asText())), f.toString());
        }
        assertTrue(Files.readString(out.resolve("fuzz.md")).contains("**The run was stopped** (interrupted"));
        assertTrue(text("stdout").contains("finding(s)"), text("stdout"));
        noSurvivors();
    }
}
