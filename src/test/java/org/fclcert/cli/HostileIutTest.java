package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.harness.ResultsFile;
import org.fclcert.iut.IutText;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fclcert certify} against hostile implementations ({@code src/test/resources/iut/hostile.py MODE}):
 * each run must end normally with all five outputs written and agreeing, every case exactly once, the attack
 * recorded as the implementation's fault (never a pass), and nothing of the implementation's raw on the terminal.
 */
class HostileIutTest {
    private static final String CORPUS = "src/test/resources/corpus-process";
    private static final String HOSTILE = "process:python3 src/test/resources/iut/hostile.py ";
    private static final List<String> IDS = List.of("B-FB-001", "B-FB-002", "B-FB-003", "B-FB-901");

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

    /** Certifies with the hostile mode, asserts the run ended normally and the five outputs agree; returns the report. */
    private Report certify(String mode, String... more) throws Exception {
        List<String> args = new ArrayList<>(List.of("certify", "--iut", HOSTILE + mode, "--corpus", CORPUS,
                "--out", dir.toString(), "--no-probe", "--no-fresh-evidence"));
        args.addAll(List.of(more));
        if (!args.contains("--timeout")) {
            args.addAll(List.of("--timeout", "5s"));
        }
        int exit = Main.run(args.toArray(String[]::new));
        assertEquals(0, exit, () -> "exit " + exit + "; stderr: " + err);
        for (String f : List.of("results.jsonl", "report.json", "report.md", "report.html", "junit.xml")) {
            assertTrue(Files.size(dir.resolve(f)) > 0, f + " written");
        }
        Report report = JsonReport.read(dir.resolve("report.json"));
        ResultsFile results = ResultsFile.read(dir.resolve("results.jsonl"));
        List<String> ids = args.contains("--case") ? List.of(args.get(args.indexOf("--case") + 1)) : IDS;
        assertEquals(ids, results.results().stream().map(CaseResult::id).sorted().toList(), "each case once");
        assertEquals(statuses(results.results()), statuses(report.cases()), "results.jsonl and report.json agree");
        String junit = Files.readString(dir.resolve("junit.xml"));
        String html = Files.readString(dir.resolve("report.html"));
        for (String id : ids) {
            assertEquals(1, count(junit, "name=\"" + id), id + " once in junit.xml");
            assertTrue(html.contains(id), id + " in report.html");
        }
        String terminal = out.toString(StandardCharsets.UTF_8) + err.toString(StandardCharsets.UTF_8);
        assertFalse(terminal.contains("\u001b]") || terminal.contains("\u0007") || terminal.contains("\u0000"),
                "no OSC, BEL or NUL of the implementation's on the terminal");
        assertFalse(terminal.contains("StackOverflowError") || terminal.contains("internal error"), terminal);
        return report;
    }

    private static Map<String, CaseStatus> statuses(List<CaseResult> results) {
        return results.stream().collect(Collectors.toMap(CaseResult::id, CaseResult::status, (a, b) -> a, TreeMap::new));
    }

    private static CaseResult result(Report r, String id) {
        return r.cases().stream().filter(c -> c.id().equals(id)).findFirst().orElseThrow();
    }

    private static int count(String text, String what) {
        int n = 0;
        for (int i = text.indexOf(what); i >= 0; i = text.indexOf(what, i + 1)) {
            n++;
        }
        return n;
    }

    @Test
    void noiseWithinToleranceAndAByteOrderMarkGetThePlainImplementationsVerdicts() throws Exception {
        // issue 27: outputs varying by 1e-12 relative between two evaluations were "state leaks" on every case, and a
        // byte-order mark before the hello reply made the run impossible
        Map<String, CaseStatus> plain = statuses(certify("name fake").cases());
        assertEquals(CaseStatus.PASSED, plain.get("B-FB-001"));
        Report jitter = certify("jitter");
        assertEquals(plain, statuses(jitter.cases()), "the same verdicts as without the noise");
        List<String> notes = result(jitter, "B-FB-001").verdict().notes();
        assertTrue(notes.stream().anyMatch(n -> n.startsWith("non-determinism within tolerance (not a state leak)")),
                notes.toString());
        assertEquals(plain, statuses(certify("bom").cases()), "the same verdicts with a byte-order mark");
    }

    @Test
    void anExportNestedAThousandDeepIsCheckedNotACrash() throws Exception {
        Report r = certify("deep-export", "--case", "B-FB-001");
        CaseResult c = result(r, "B-FB-001");
        assertEquals(CaseStatus.PASSED, c.status(), c.message());   // sum = a + b: the steps are right
        // the export reads back (1000 levels is within the limit) and is judged: the hostile condition changes
        // the rule, so it is not the original program's meaning
        assertEquals(ExportStatus.FAILED, c.export().status());
        assertTrue(c.export().message().startsWith("the exported FCL evaluates differently"), c.export().message());
    }

    @Test
    void aLoneSurrogateInTheNameOrAMessageIsKeptAsU_FFFD() throws Exception {
        Report r = certify("surrogate-name");
        assertEquals("sur\uFFFDrogate", r.iut().name());
        assertTrue(Files.readString(dir.resolve("report.md")).contains("sur\uFFFDrogate"));
        assertEquals(1 + IDS.size() + 1, Files.readAllLines(dir.resolve("results.jsonl")).size(),
                "a header, each case once, no torn or doubled line, the end line");

        Report m = certify("surrogate-msg");
        CaseResult c = result(m, "B-FB-001");
        assertEquals(CaseStatus.FAILED, c.status());
        assertTrue(c.message().endsWith("bad \uFFFD program"), c.message());
        assertEquals(CaseStatus.PASSED, result(m, "B-FB-901").status(), "a rejection of the negative case");
    }

    @Test
    void whatIsKeptOfAHugeMessageIsCappedAndMarked() throws Exception {
        Report r = certify("huge-msg");
        CaseResult c = result(r, "B-FB-001");
        assertEquals(CaseStatus.FAILED, c.status());
        assertTrue(c.message().endsWith("… (truncated, 1000000 bytes)"), c.message().substring(c.message().length() - 60));
        assertTrue(c.message().length() < IutText.MAX_KEPT_BYTES + 200, "length " + c.message().length());
        // four cases of a 1 MB message each: the files hold what is kept, not what was sent
        assertTrue(Files.size(dir.resolve("results.jsonl")) < 100_000, "results.jsonl " + Files.size(dir.resolve("results.jsonl")));
        assertTrue(Files.size(dir.resolve("report.json")) < 200_000, "report.json " + Files.size(dir.resolve("report.json")));
    }

    @Test
    void aKeyGivenTwiceOrTwiceButForCaseIsAProtocolFaultNeverAPass() throws Exception {
        for (String mode : List.of("dup-key", "case-key")) {
            Report r = certify(mode);
            assertEquals(0, r.summary().passed() - (int) r.cases().stream()
                    .filter(c -> c.id().equals("B-FB-901") && c.status() == CaseStatus.PASSED).count(), mode);
            CaseResult c = result(r, "B-FB-001");
            assertEquals(CaseStatus.ERRORED, c.status(), mode);
            assertTrue(c.message().contains("the reply to 'eval' is ambiguous"), mode + ": " + c.message());
            assertFalse(r.basicLevel().conformant(), mode);
        }
    }

    @Test
    void injectionsReachNeitherTheTerminalNorReportMdRaw() throws Exception {
        Report r = certify("inject");
        String terminal = out.toString(StandardCharsets.UTF_8) + err.toString(StandardCharsets.UTF_8);
        assertFalse(terminal.contains("\u001b"), "no ESC of the implementation's: " + terminal);
        assertFalse(terminal.contains("\rFAILED") || terminal.contains("\r\u001b"), terminal);
        assertTrue(terminal.contains("evil\\r\\e[2K\\e]0;pwned\\aFAILED\\n# forged heading"), terminal);
        String md = Files.readString(dir.resolve("report.md"));
        assertFalse(md.contains("\n# forged heading"), () -> "no forged heading: " + md.lines()
                .filter(l -> l.startsWith("# forged")).findFirst().orElse("") + " in\n" + md);
        assertFalse(md.contains("\n**Basic Level: conformant**"), "no forged verdict line");
        assertFalse(md.contains("<script>") || java.util.regex.Pattern.compile("(?<!\\\\)\\]\\(javascript:").matcher(md).find()
                || md.contains("\u0000")
                || md.contains("\u001b"), md);
        assertTrue(md.contains("\\<script\\>"), "shown, escaped");
        String html = Files.readString(dir.resolve("report.html"));
        assertFalse(html.contains("<script>alert"), "report.html escapes it");
        assertEquals(CaseStatus.FAILED, result(r, "B-FB-001").status());
    }

    @Test
    void anExportWithoutFclIsAFailedExport() throws Exception {
        // that it costs no restart: HostileProcessIutTest, with a restart budget of 0
        Report r = certify("no-fcl-export");
        for (String id : List.of("B-FB-001", "B-FB-002", "B-FB-003")) {
            CaseResult c = result(r, id);
            assertEquals(CaseStatus.PASSED, c.status(), id + ": " + c.message());
            assertEquals(ExportStatus.FAILED, c.export().status(), id);
            assertTrue(c.export().message().contains("no text field 'fcl'"), c.export().message());
        }
    }

    /** Every process listed in {@code pids} (one pid a line) has ended. */
    private static void noSurvivors(Path pids) throws Exception {
        List<Long> all = Files.readAllLines(pids).stream().map(Long::valueOf).toList();
        assertFalse(all.isEmpty());
        for (long pid : all) {
            var handle = ProcessHandle.of(pid);
            if (handle.isPresent()) {
                handle.get().onExit().get(5, java.util.concurrent.TimeUnit.SECONDS);
            }
            assertTrue(ProcessHandle.of(pid).map(h -> !h.isAlive()).orElse(true), "process " + pid + " survives");
        }
    }

    @Test
    void childrenOutlivingTheImplementationSurviveNeitherCertifyNorProbe() throws Exception {
        // issue 18 item 5: the IUT exits at each eval, its child keeps stdout open; one survivor per restart was
        // left (6 after a certify, 34 after a probe)
        // --no-sandbox: the test reads the host pids the children write (in the sandbox its PID namespace ends them
        // all, SandboxedRunTest); this is the kill path of an unsandboxed run
        Path pids = dir.resolve("pids");
        Report r = certify("orphan " + pids, "--timeout", "1s", "--no-sandbox");
        assertEquals(CaseStatus.ERRORED, result(r, "B-FB-001").status());
        assertTrue(Files.readAllLines(pids).size() >= 2, "restarted, a child each time");
        noSurvivors(pids);
        Path probed = dir.resolve("probe-pids");
        int exit = Main.run("probe", "--iut", HOSTILE + "orphan " + probed, "--no-sandbox", "--timeout", "1s", "--cap", "4",
                "--budget", "6s");
        assertEquals(0, exit, err.toString(StandardCharsets.UTF_8));
        assertTrue(Files.readAllLines(probed).size() >= 2, "restarted, a child each time");
        noSurvivors(probed);
    }

    @Test
    void anImplementationNamingItselfLikeACommittedReportNeverWritesThere(@TempDir Path checkout) throws Exception {
        // issue 18 item 7: without --out, 'reference' and 'fuzzylite 6.0' wrote over reports/<name>/; a 300-character
        // name failed with "File name too long"
        Path committed = checkout.resolve("reports/reference/report.md");
        Files.createDirectories(committed.getParent());
        Files.writeString(committed, "committed\n");
        String script = Path.of("src/test/resources/iut/hostile.py").toAbsolutePath().toString();
        String corpus = Path.of(CORPUS).toAbsolutePath().toString();
        Map<String, String> expected = Map.of("reference", "reference", "fuzzylite 6.0", "fuzzylite-6.0",
                "n".repeat(300), "n".repeat(64));
        for (Map.Entry<String, String> e : expected.entrySet()) {
            Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                    System.getProperty("java.class.path"), "org.fclcert.cli.Main", "certify", "--no-probe", "--no-fresh-evidence", "--corpus",
                    corpus, "--iut", "process:python3 " + script + " name '" + e.getKey() + "'")
                    .directory(checkout.toFile()).redirectErrorStream(true).start();
            String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertEquals(0, p.waitFor(), text);
            Path written = checkout.resolve("fclcert-reports").resolve(e.getValue());
            assertTrue(Files.exists(written.resolve("report.md")), e.getValue() + ": " + text);
            assertTrue(text.contains("Reports: fclcert-reports/" + e.getValue() + "/report.md"), text);
        }
        assertEquals("committed\n", Files.readString(committed), "the committed report is untouched");
    }

    @Test
    void aReplyWrittenBeforeTheQuestionIsNotTakenAsTheAnswer() throws Exception {
        Report r = certify("unasked", "--case", "B-FB-001");
        CaseResult c = result(r, "B-FB-001");
        assertEquals(CaseStatus.ERRORED, c.status());
        assertTrue(c.message().contains("before 'eval' was sent, unasked"), c.message());
    }
}
