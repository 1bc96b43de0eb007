package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.function.UnaryOperator;
import org.apache.maven.plugin.MojoFailureException;
import org.fclcert.maven.VerifyMojo;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 26: results that cannot be edited into a pass. A real run of an implementation that fails (the fake that
 * answers sums) is edited as a forger would — every case flipped to passed, a two-line results file, the version
 * string, {@code basicLevel.conformant} — and {@code report --from}, {@code report --verify}, {@code compare} and the
 * Maven {@code fclcert:verify} gate each refuse it or report it inconsistent. The forger recomputes the hash chain
 * (there is no key to stop that), so what catches the flips is the re-judging of the evidence.
 */
class EditedResultsTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    static Path root;
    static Path run;

    @BeforeAll
    static void aRealRunThatFails() {
        run = root.resolve("run");
        Cli c = Cli.run("certify", "--iut", "process:python3 src/test/resources/iut/well_behaved.py", "--no-probe",
                "--seed", "7", "--case", "B-ACCU-MAX-00*", "--case", "N-C002-001", "--out", run.toString());
        assertEquals(0, c.exitCode(), c.err());
    }

    /** A copy of the run with {@code results.jsonl}'s lines edited, the chain recomputed, the reports kept. */
    private static Path forged(String name, UnaryOperator<List<ObjectNode>> edit) throws Exception {
        Path dir = root.resolve(name);
        copy(run, dir);
        List<ObjectNode> lines = new ArrayList<>();
        for (String l : Files.readAllLines(dir.resolve("results.jsonl"))) {
            lines.add((ObjectNode) JSON.readTree(l));
        }
        Files.writeString(dir.resolve("results.jsonl"), rechained(edit.apply(lines)));
        return dir;
    }

    static String rechained(List<ObjectNode> lines) throws Exception {
        StringBuilder out = new StringBuilder();
        String prev = "0".repeat(64);
        for (ObjectNode n : lines) {
            n.put("prev", prev);
            if (n.path("type").asText().equals("end")) {
                n.put("digest", prev);
            }
            String text = JSON.writeValueAsString(n);
            out.append(text).append('\n');
            prev = HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
        }
        return out.toString();
    }

    private static void copy(Path from, Path to) throws Exception {
        Files.createDirectories(to);
        try (var files = Files.list(from)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                Files.copy(f, to.resolve(f.getFileName()));
            }
        }
    }

    private static List<ObjectNode> everyCasePassed(List<ObjectNode> lines) {
        for (ObjectNode n : lines) {
            if (n.path("type").asText().equals("case")) {
                n.put("status", "passed");
                n.put("message", "3 step(s) within tolerance");
                for (String f : List.of("step", "inputs", "expected", "actual", "error", "reference")) {
                    n.remove(f);
                }
            }
        }
        return lines;
    }

    private static void refusedByAll(Path dir, String because, boolean resultsEdited) throws Exception {
        if (resultsEdited) {
            Cli from = Cli.run("report", "--from", dir.resolve("results.jsonl").toString(), "--out",
                    dir.resolve("again").toString());
            assertEquals(1, from.exitCode(), from.out() + from.err());
            assertTrue(from.err().contains(because), from.err());
            assertTrue(Files.notExists(dir.resolve("again").resolve("report.md")), "no report is made of it");
        }
        Cli verify = Cli.run("report", "--verify", dir.toString());
        assertEquals(1, verify.exitCode(), verify.out() + verify.err());
        assertTrue(verify.err().contains(because), verify.err());
        Cli compare = Cli.run("compare", "--out", dir.resolve("page").toString(), run.toString(), dir.toString());
        assertEquals(1, compare.exitCode(), compare.out() + compare.err());
        assertTrue(compare.err().contains(because), compare.err());
        MojoFailureException gate = assertThrows(MojoFailureException.class, () -> gate(dir, "none").execute());
        assertTrue(gate.getMessage().contains(because), gate.getMessage());
    }

    static VerifyMojo gate(Path dir, String failOn) throws Exception {
        VerifyMojo mojo = new VerifyMojo();
        set(mojo, "reportsDirectory", dir.toFile());
        set(mojo, "failOn", failOn);
        set(mojo, "claims", List.of());
        return mojo;
    }

    private static void set(Object o, String field, Object value) throws Exception {
        var f = VerifyMojo.class.getDeclaredField(field);
        f.setAccessible(true);
        f.set(o, value);
    }

    @Test
    void theRunItselfHoldsUpEverywhere() throws Exception {
        assertEquals(0, Cli.run("report", "--verify", run.toString()).exitCode());
        assertEquals(0, Cli.run("compare", "--out", root.resolve("page0").toString(), run.toString()).exitCode());
        gate(run, "none").execute();
        assertThrows(MojoFailureException.class, () -> gate(run, "any").execute(), "the fake fails its cases");
        Cli from = Cli.run("report", "--from", run.resolve("results.jsonl").toString(), "--out",
                root.resolve("again0").toString());
        assertEquals(0, from.exitCode(), from.err());
    }

    @Test
    void everyCaseFlippedToPassedIsRefusedByTheEvidence() throws Exception {
        refusedByAll(forged("flipped", EditedResultsTest::everyCasePassed),
                "case B-ACCU-MAX-001: the line says passed, its evidence judged again gives failed", true);
    }

    @Test
    void everyCaseFlippedWithoutRecomputingTheChainBreaksIt() throws Exception {
        Path dir = root.resolve("unchained");
        copy(run, dir);
        List<String> lines = Files.readAllLines(dir.resolve("results.jsonl"));
        lines.set(1, lines.get(1).replace("\"status\":\"failed\"", "\"status\":\"passed\""));
        Files.write(dir.resolve("results.jsonl"), lines);
        refusedByAll(dir, "results.jsonl:3: the chain breaks here", true);
    }

    @Test
    void aTwoLineFileClaimingOneBasicCaseIsRefused() throws Exception {
        Path dir = forged("two-lines", lines -> {
            ObjectNode header = lines.get(0);
            ObjectNode corpus = (ObjectNode) header.path("corpus");
            corpus.put("basicCases", 1);
            ArrayNode planned = (ArrayNode) header.path("selection").path("planned");
            while (planned.size() > 1) {
                planned.remove(1);
            }
            ObjectNode only = everyCasePassed(new ArrayList<>(List.of(lines.get(1)))).get(0);
            only.remove("replies");
            return new ArrayList<>(List.of(header, only));
        });
        List<org.fclcert.corpus.CorpusCase> cases =
                org.fclcert.corpus.Corpus.load(java.nio.file.Path.of("conformance")).cases();
        int all = cases.size();
        // the Basic Level cases as Rejudge counts them: a case with an interpretation flag is not one
        long basic = cases.stream()
                .filter(c -> c.level() == org.fclcert.model.ConformanceLevel.BASIC && c.interpretation().isEmpty())
                .count();
        refusedByAll(dir, "the run header says the corpus has " + all + " cases, 1 of the Basic Level; it has " + all
                + " and " + basic, true);
    }

    @Test
    void aVersionStringEditIsRefused() throws Exception {
        Path dir = forged("version", lines -> {
            ((ObjectNode) lines.get(0).path("toolkit")).put("version", "9.9.9-CERTIFIED");
            return lines;
        });
        refusedByAll(dir, "the results say they were made by fclcert 9.9.9-CERTIFIED", true);
        Path reportOnly = root.resolve("version-in-report");
        copy(run, reportOnly);
        Path json = reportOnly.resolve("report.json");
        Files.writeString(json, Files.readString(json).replaceFirst("\"version\" : \"[^\"]*\"",
                "\"version\" : \"9.9.9-CERTIFIED\""));
        refusedByAll(reportOnly, "report.json:", false);
    }

    @Test
    void aFlippedBasicLevelVerdictInReportJsonIsRefused() throws Exception {
        Path dir = root.resolve("conformant");
        copy(run, dir);
        Path json = dir.resolve("report.json");
        String text = Files.readString(json);
        assertTrue(text.contains("\"conformant\" : false"));
        Files.writeString(json, text.replaceFirst("\"conformant\" : false", "\"conformant\" : true"));
        refusedByAll(dir, "report.json:", false);
        // the gate judges the rebuilt report: the run's cases still did not pass
        MojoFailureException basic = assertThrows(MojoFailureException.class, () -> gate(run, "basic").execute());
        assertTrue(basic.getMessage().contains("case(s) selected by fclcert.cases did not pass: B-ACCU-MAX-001 failed"),
                basic.getMessage());
    }

    @Test
    void anUneditedCopyOfAnotherRunsReportNextToTheseResultsIsRefused() throws Exception {
        Path dir = root.resolve("mixed");
        copy(run, dir);
        Files.writeString(dir.resolve("report.md"), Files.readString(dir.resolve("report.md")).replace("NOT conformant",
                "conformant"));
        refusedByAll(dir, "report.md:", false);
        assertTrue(new File(dir.toFile(), "results.jsonl").isFile());
    }
}
