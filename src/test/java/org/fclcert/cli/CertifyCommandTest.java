package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fclcert certify} against real separate processes (the Python fakes of the iut tests, which answer
 * {@code sum = a + b}), and its exit codes.
 */
class CertifyCommandTest {
    static final String CORPUS = "src/test/resources/corpus-process";
    static final String FAKES = "src/test/resources/iut/";

    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private PrintStream oldOut;
    private PrintStream oldErr;

    @BeforeEach
    void capture() {
        oldOut = System.out;
        oldErr = System.err;
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    @AfterEach
    void restore() {
        System.setOut(oldOut);
        System.setErr(oldErr);
    }

    private int certify(String iut, String... more) {
        // the fakes answer sums, which no FCL gives: a harness test, run without fresh evidence (issue 26)
        List<String> args = new java.util.ArrayList<>(List.of("certify", "--iut", iut, "--corpus", CORPUS,
                "--out", dir.toString(), "--no-fresh-evidence"));
        if (!List.of(more).contains("--probe-cap")) {
            args.add("--no-probe");   // the probes have their own tests (ProberTest); keep these quick
        }
        args.addAll(List.of(more));
        return Main.run(args.toArray(String[]::new));
    }

    private Report report() throws Exception {
        return JsonReport.read(dir.resolve("report.json"));
    }

    private static Map<String, CaseStatus> statuses(Report r) {
        return r.cases().stream().collect(Collectors.toMap(CaseResult::id, CaseResult::status, (a, b) -> a,
                TreeMap::new));
    }

    private static CaseResult result(Report r, String id) {
        return r.cases().stream().filter(c -> c.id().equals(id)).findFirst().orElseThrow();
    }

    @Test
    void aCrashIsErroredWithItsStderrAndTheRunGoesOnAfterARestart() throws Exception {
        assertEquals(0, certify("process:python3 " + FAKES + "crash_on_fifth_eval.py"), err::toString);
        Report r = report();
        // B-FB-001 uses evaluations 1-4 (two steps, then two in reverse); the fifth is B-FB-002's first step
        assertEquals(Map.of("B-FB-001", CaseStatus.PASSED, "B-FB-002", CaseStatus.ERRORED,
                "B-FB-003", CaseStatus.PASSED, "B-FB-901", CaseStatus.FAILED), statuses(r));
        CaseResult crashed = result(r, "B-FB-002");
        assertTrue(crashed.message().startsWith("step 1 of 2: the implementation crashed"), crashed.message());
        assertTrue(crashed.evidence().error().contains("fatal: fifth evaluation, giving up"), crashed.evidence().error());
        assertEquals("accepted a program the standard rejects: FCL-S035 at line 15", result(r, "B-FB-901").message());
        assertEquals("fake", r.iut().name());
        assertEquals(List.of("B-FB"), r.claims().claimed());
        assertEquals(List.of("B-FB (partial)"), r.claims().notRealised());
        assertTrue(Files.readString(dir.resolve("report.md")).contains(
                "`./fclcert certify --iut 'process:python3 src/test/resources/iut/crash_on_fifth_eval.py' --corpus "
                        + CORPUS + " --case B-FB-002`"));
        assertEquals(6, Files.readAllLines(dir.resolve("results.jsonl")).size(), "a header, four cases, the end line");
        assertTrue(out.toString().contains("fake 1.0: 4 cases, 2 passed, 1 failed, 1 errored, 0 skipped"), out::toString);
        String md = Files.readString(dir.resolve("report.md"));
        assertTrue(md.contains("\n  - step 1, inputs: a = 2.0, b = 3.0\n"), md);
        assertTrue(md.contains("\n  - its last stderr line: `fatal: fifth evaluation, giving up`\n"), md);
        assertTrue(md.contains(" --case B-FB-002` (transcript: `requests/B-FB-002.requests.jsonl`)"), md);
        String stderr = err.toString();
        assertTrue(stderr.contains("ERRORED B-FB-002 (Process-path case 2"), stderr);
        assertTrue(stderr.contains(": step 1 of 2: the implementation crashed"), stderr);
        assertTrue(stderr.contains("\n  step 1, inputs: a = 2.0, b = 3.0\n"), stderr);
        assertTrue(stderr.contains("\n  its stderr: fatal: fifth evaluation, giving up\n"), stderr);
        assertTrue(stderr.contains("\n  reproduce: ./fclcert certify --iut 'process:python3 "
                + "src/test/resources/iut/crash_on_fifth_eval.py' --corpus " + CORPUS + " --case B-FB-002\n"), stderr);
        Path transcript = dir.resolve("requests").resolve("B-FB-002.requests.jsonl");
        assertTrue(stderr.contains("\n  transcript: " + transcript + "\n"), stderr);
        assertFalse(Files.exists(dir.resolve("requests").resolve("B-FB-001.requests.jsonl")), "only cases not passed");
        List<String> requests = Files.readAllLines(transcript);
        assertEquals("{\"op\":\"hello\",\"id\":1}", requests.get(0));
        assertTrue(requests.get(1).startsWith("{\"op\":\"load\",\"id\":2,\"fcl\":\"") && requests.get(1).contains("FUNCTION_BLOCK adder"), requests.get(1));
        assertTrue(requests.get(2).startsWith("{\"op\":\"eval\",\"id\":3,"), requests.get(2));
        assertTrue(requests.get(2).contains("\"inputs\":{\"a\":2.0,\"b\":3.0}"), requests.get(2));
        assertEquals("{\"op\":\"bye\",\"id\":" + requests.size() + "}", requests.get(requests.size() - 1));
    }

    @Test
    void aTranscriptPipedIntoTheImplementationReplaysTheCase() throws Exception {
        // the fake answers sum = a + b, so the transcript of the failing negative case replays its wrong accept
        assertEquals(0, certify("process:python3 src/test/resources/iut/well_behaved.py"));
        Path transcript = dir.resolve("requests").resolve("B-FB-901.requests.jsonl");
        Process p = new ProcessBuilder("python3", "src/test/resources/iut/well_behaved.py")
                .redirectInput(transcript.toFile()).start();
        List<String> replies = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).lines().toList();
        assertEquals(0, p.waitFor());
        assertEquals(Files.readAllLines(transcript).size(), replies.size(), "one reply per request: " + replies);
        assertTrue(replies.get(1).contains("\"ok\": true") || replies.get(1).contains("\"ok\":true"),
                "the program the standard rejects is accepted again: " + replies.get(1));
    }

    @Test
    void failOnDecidesTheExitCode() {
        String iut = "process:python3 " + FAKES + "crash_on_fifth_eval.py";
        assertEquals(1, certify(iut, "--fail-on", "any"));
        assertTrue(err.toString().contains("--fail-on any: 1 case(s) failed, 1 errored"), err::toString);
        assertEquals(1, certify(iut, "--fail-on", "claimed"));
        // alone, B-FB-001 needs four evaluations: no crash
        assertEquals(0, certify(iut, "--case", "B-FB-001", "--fail-on", "any"));
        assertEquals(1, certify(iut, "--case", "B-FB-001", "--fail-on", "basic"), "a partial run is not conformant");
    }

    @Test
    void aHangIsATimeoutNeverAPassNotEvenForANegativeCase() throws Exception {
        assertEquals(0, certify("process:python3 " + FAKES + "hang_on_load.py", "--timeout", "3s",
                "--case", "B-FB-901"), err::toString);
        Report r = report();
        assertEquals(0, r.summary().passed());
        CaseResult negative = result(r, "B-FB-901");
        assertEquals(CaseStatus.ERRORED, negative.status());
        assertEquals("load: the implementation timed out: no reply to 'load' within 3000 ms", negative.message());
    }

    @Test
    void garbageRepliesAreProtocolErrors() throws Exception {
        assertEquals(0, certify("process:python3 " + FAKES + "garbage.py text"), err::toString);
        Report r = report();
        assertEquals(0, r.summary().passed());
        assertTrue(result(r, "B-FB-001").message().startsWith("load: the implementation broke the protocol"),
                result(r, "B-FB-001").message());
        assertTrue(r.cases().stream().allMatch(c -> c.status() == CaseStatus.ERRORED
                || c.status() == CaseStatus.SKIPPED), r.cases()::toString);
    }

    @Test
    void aJavaImplementationOnAClasspath() throws Exception {
        // SummingFcl (the iut tests' vendor class) has an output 'y' = a + b and refuses to give 'sum'
        assertEquals(0, certify("java:org.fclcert.iut.SummingFcl", "--classpath", "target/test-classes"),
                err::toString);
        Report r = report();
        assertEquals("summing", r.iut().name());
        assertEquals(CaseStatus.FAILED, result(r, "B-FB-001").status());
        assertTrue(result(r, "B-FB-001").message().startsWith("step 1 of 2: the implementation reported an "
                + "evaluation error: "), result(r, "B-FB-001").message());
        assertEquals(CaseStatus.FAILED, result(r, "B-FB-901").status());
        assertEquals("target/test-classes", r.iut().classpath());
        assertTrue(Files.readString(dir.resolve("report.md")).contains("`./fclcert certify --iut "
                + "java:org.fclcert.iut.SummingFcl --classpath target/test-classes --corpus " + CORPUS
                + " --case B-FB-001`"));
    }

    @Test
    void aRunThatCannotBeDoneExitsWith2AndSaysWhy() {
        assertEquals(2, Main.run("certify", "--corpus", "no/such/dir", "--out", dir.toString()));
        assertTrue(err.toString().contains("corpus directory no/such/dir does not exist"), err::toString);
        assertEquals(2, certify("process:/no/such/program"));
        assertTrue(err.toString().contains("fclcert certify: the implementation 'process:/no/such/program' did not "
                + "answer hello"), err::toString);
        assertEquals(2, certify("nonsense"));
        assertEquals(2, certify("reference", "--fail-on", "sometimes"));
        assertEquals(2, certify("reference", "--feature", "E-HEDGES"));
        assertEquals(2, certify("reference", "--level", "expert"));
        assertEquals(2, certify("reference", "--timeout", "soon"));
        assertTrue(err.toString().contains("Invalid value for option '--timeout': 'soon' is not a duration"),
                err::toString);
        assertTrue(err.toString().contains("Invalid value for option '--fail-on': expected one of [NONE, BASIC, CLAIMED,"
                + " ANY] (case-insensitive) but was 'sometimes'"), err::toString);
        assertTrue(err.toString().contains("Invalid value for option '--level' (LEVEL): expected one of [BASIC,"
                + " EXTENSION, OPEN] (case-insensitive) but was 'expert'"), err::toString);
        assertEquals(2, certify("reference", "--case", "Z-*"));
        assertTrue(err.toString().contains("no case of " + CORPUS + " matches the selection"), err::toString);
    }

    @Test
    void reportRebuildsEverythingFromAResultsFileCutShort() throws Exception {
        certify("process:python3 " + FAKES + "crash_on_fifth_eval.py");
        Path results = dir.resolve("results.jsonl");
        List<String> lines = Files.readAllLines(results);
        Path cut = dir.resolve("cut/results.jsonl");
        Files.createDirectories(cut.getParent());
        // the header, the first case, and half of the second line as a killed run leaves it
        Files.writeString(cut, lines.get(0) + "\n" + lines.get(1) + "\n" + lines.get(2).substring(0, 40));
        assertEquals(0, Main.run("report", "--from", cut.toString()), err::toString);
        Report r = JsonReport.read(dir.resolve("cut/report.json"));
        assertEquals(Map.of("B-FB-001", CaseStatus.PASSED, "B-FB-002", CaseStatus.SKIPPED,
                "B-FB-003", CaseStatus.SKIPPED, "B-FB-901", CaseStatus.SKIPPED), statuses(r));
        assertEquals(false, r.run().complete());
        assertEquals(1, r.run().problems().size());
        assertTrue(err.toString().contains("unreadable line ignored"), err::toString);
        for (String f : List.of("report.md", "report.html", "junit.xml")) {
            assertTrue(Files.size(dir.resolve("cut").resolve(f)) > 0, f);
        }
        assertEquals(2, Main.run("report", "--from", dir.resolve("missing.jsonl").toString()));
    }

    @Test
    void certifyFillsTheDataCheckListOfResultsAndReports() throws Exception {
        assertEquals(0, certify("reference", "--probe-cap", "8"));
        List<String> lines = java.nio.file.Files.readAllLines(dir.resolve("results.jsonl"));
        assertTrue(lines.get(lines.size() - 2).startsWith("{\"type\":\"dataCheckList\",\"entries\":[{\"id\":\"data-types\""),
                lines.get(lines.size() - 2));
        assertTrue(lines.get(lines.size() - 1).startsWith("{\"type\":\"end\",\"digest\":"), "the chain's end line last");
        org.fclcert.report.Report r = org.fclcert.report.JsonReport.read(dir.resolve("report.json"));
        assertEquals(22, r.dataCheckList().size());
        assertEquals("8", r.dataCheckList().get(17).value());
        String md = java.nio.file.Files.readString(dir.resolve("report.md"));
        assertTrue(md.contains("| max. number of rules per block | ≥ 8 rules |  | reached the cap of 8 (--probe-cap) |"), md);
        String html = java.nio.file.Files.readString(dir.resolve("report.html"));
        assertTrue(html.contains("<h2>Data check list (Table 11)</h2>"), "a Table 11 section");
        assertTrue(html.contains("<td>max. number of rules per block</td><td><b>≥ 8 rules</b></td>"), "readable rows");
    }

    @Test
    void aBadProbeBudgetIsAUsageError() {
        assertEquals(2, certify("reference", "--probe-cap", "8", "--probe-budget", "later"));
    }

    @Test
    void outsideACheckoutTheBundledCorpusIsUsed() throws Exception {
        // a separate JVM whose working directory has no conformance/: certify falls back to the bundled corpus
        Path reports = dir.resolve("reports");
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), "org.fclcert.cli.Main", "certify", "--no-probe", "--case",
                "B-COGS-001", "--out", reports.toString())
                .directory(dir.toFile()).redirectErrorStream(true).start();
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), text);   // --fail-on none: a completed run exits 0
        assertTrue(text.contains("1 cases, 1 passed, 0 failed"), text);
        Report r = new com.fasterxml.jackson.databind.ObjectMapper().readValue(reports.resolve("report.json").toFile(),
                Report.class);
        assertEquals("bundled", r.corpus().dir());
    }
}
