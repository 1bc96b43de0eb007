package org.fclcert.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fclcert.cli.Main;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FuzzCommandTest {
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    /**
     * Runs fclcert; a fuzz run of a java: fake calls it in process (--in-process): these tests are about the fuzzer,
     * whose every program and shrink trial would otherwise wait for a child JVM (that path: JavaChildJvmTest).
     */
    private int run(String... args) {
        boolean javaFake = args[0].equals("fuzz") && java.util.Arrays.stream(args).anyMatch(a -> a.startsWith("java:"));
        String[] all = javaFake ? java.util.stream.Stream.concat(java.util.Arrays.stream(args), java.util.stream.Stream.of(
                "--in-process")).toArray(String[]::new) : args;
        return Main.run(new PrintWriter(out), new PrintWriter(err), all);
    }

    private static JsonNode json(Path dir) throws Exception {
        return new ObjectMapper().readTree(Files.readString(dir.resolve("fuzz.json")));
    }

    @Test
    void theReferenceAgainstItselfFindsNothing_exit0(@TempDir Path dir) throws Exception {
        assertEquals(0, run("fuzz", "--iut", "reference", "--programs", "60", "--budget", "2m", "--out", dir.toString()), err.toString());
        JsonNode j = json(dir);
        assertEquals(60, j.at("/counts/programs").asLong());
        assertEquals(0, j.at("/counts/findings").asLong());
        assertEquals(0, j.at("/counts/generatorBugs").asLong());
        assertTrue(j.at("/counts/vectors").asLong() >= 60, j.toString());
        // where the time went: the reference side is most of a run against the reference in process
        assertTrue(j.at("/time/referenceSeconds").asDouble() > j.at("/time/implementationSeconds").asDouble(), j.toString());
        assertEquals(0.0, j.at("/time/shrinkSeconds").asDouble(), j.toString());
        assertTrue(Files.readString(dir.resolve("fuzz.md")).contains("**60 programs"), Files.readString(dir.resolve("fuzz.md")));
        // not a terminal: a progress line every few seconds at most, and the summary on stdout
        assertTrue(out.toString().contains("60 programs"), out.toString());
    }

    @Test
    void aDefectIsFoundShrunkAndWrittenAsACase_exit1(@TempDir Path dir) throws Exception {
        assertEquals(1, run("fuzz", "--iut", "java:org.fclcert.fuzz.SpiFakes$NsumAsBsum", "--feature", "E-ACCU-NSUM",
                "--max-findings", "1", "--budget", "60s", "--out", dir.toString()), err.toString());
        JsonNode f = json(dir).at("/findings/0");
        assertEquals("E-ACCU-NSUM", f.get("feature").asText());
        assertEquals("wrong-value", f.get("kind").asText());
        Path file = dir.resolve(f.get("file").asText());
        assertTrue(Files.readString(file).startsWith("(*---\nid: " + f.get("id").asText()), Files.readString(file));
        assertTrue(f.get("programLines").asInt() <= 25, f.toString());
        // and it can join a corpus: corpus add lints it and gives it the next free id
        Path corpus = dir.resolve("corpus");
        Files.createDirectories(corpus);
        assertEquals(0, run("corpus", "add", file.toString(), "--corpus", corpus.toString()), out + "" + err);
        assertTrue(Files.exists(corpus.resolve("extension").resolve("E-ACCU-NSUM-001.fcl")), out.toString());
        assertEquals(0, run("corpus", "add", file.toString(), "--corpus", corpus.toString()), out + "" + err);
        assertTrue(Files.exists(corpus.resolve("extension").resolve("E-ACCU-NSUM-002.fcl")), out.toString());
    }

    @Test
    void corpusAddRefusesACaseTheLintFaults_andSkipsRetiredIds(@TempDir Path dir) throws Exception {
        Path corpus = dir.resolve("corpus");
        Files.createDirectories(corpus);
        Files.writeString(corpus.resolve("RETIRED"), "B-COGS-001 wrong\n");
        String program = "FUNCTION_BLOCK f\nVAR_INPUT a : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
                + "FUZZIFY a TERM on := (0, 0) (1, 1); END_FUZZIFY\n"
                + "DEFUZZIFY y TERM hi := 10; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY\n"
                + "RULEBLOCK r AND : MIN; ACCU : MAX; RULE 1 : IF a IS on THEN y IS hi; END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
        String meta = "(*---\nid: B-COGS-007\ntitle: one rule\nlevel: basic\nfeatures: [%s]\ntests: [B-COGS]\n"
                + "tolerance: exact\nderivation: |\n  a = 0.5 gives on = 0.5, y = 10\nvectors:\n  - in: {a: 0.5}\n    out: {y: 10.0}\n---*)\n";
        Path good = dir.resolve("good.fcl");
        Files.writeString(good, String.format(meta, "B-FB, B-IN-TERM, B-OUT-SINGLETON, B-AND-MIN, B-ACCU-MAX, B-COGS, "
                + "B-DEFAULT-VALUE, B-ONE-RULEBLOCK, B-SUBCONDITIONS, B-ONE-SUBCONCLUSION") + program);
        Path bad = dir.resolve("bad.fcl");
        Files.writeString(bad, String.format(meta, "B-FB, B-COGS") + program);
        assertEquals(1, run("corpus", "add", bad.toString(), "--corpus", corpus.toString()), out.toString());
        assertTrue(out.toString().contains("not added"), out.toString());
        assertTrue(!Files.exists(corpus.resolve("basic").resolve("B-COGS-002.fcl")));
        assertEquals(0, run("corpus", "add", good.toString(), "--corpus", corpus.toString()), out.toString());
        assertTrue(Files.readString(corpus.resolve("basic").resolve("B-COGS-002.fcl")).contains("id: B-COGS-002\n"));
    }

    @Test
    void aSeedReproducesTheRun(@TempDir Path dir) throws Exception {
        Path a = dir.resolve("a");
        Path b = dir.resolve("b");
        String iut = "java:org.fclcert.fuzz.SpiFakes$NsumAsBsum";
        assertEquals(1, run("fuzz", "--iut", iut, "--seed", "99", "--programs", "80", "--budget", "2m", "--out", a.toString()));
        assertEquals(1, run("fuzz", "--iut", iut, "--seed", "99", "--programs", "80", "--budget", "2m", "--out", b.toString()));
        assertEquals(json(a).get("findings").toString().replaceAll("\"(shrink|foundAfter)Seconds\":[0-9.E-]+", ""),
                json(b).get("findings").toString().replaceAll("\"(shrink|foundAfter)Seconds\":[0-9.E-]+", ""));
        assertEquals(json(a).at("/counts/vectors"), json(b).at("/counts/vectors"));
        for (JsonNode f : json(a).get("findings")) {
            assertEquals(Files.readString(a.resolve(f.get("file").asText())), Files.readString(b.resolve(f.get("file").asText())));
        }
    }

    @Test
    void aCrashIsAFinding_andTheRunGoesOn(@TempDir Path dir) throws Exception {
        assertEquals(1, run("fuzz", "--iut", "java:org.fclcert.fuzz.SpiFakes$CrashesOnNot", "--feature", "E-NOT",
                "--programs", "40", "--budget", "2m", "--out", dir.toString()), err.toString());
        JsonNode j = json(dir);
        assertEquals(40, j.at("/counts/programs").asLong());
        assertEquals("crash", j.at("/findings/0/kind").asText(), j.toString());
        assertEquals("E-NOT", j.at("/findings/0/feature").asText(), j.toString());
        assertTrue(j.at("/findings/0/message").asText().contains("NOT is not implemented"), j.toString());
    }

    @Test
    void presentAsSendsEachProgramInTheLibrarysLayout_andCountsWhatItCannotSay(@TempDir Path dir) throws Exception {
        String iut = "java:org.fclcert.fuzz.SpiFakes$FuzzyliteLayoutOnly";
        assertEquals(1, run("fuzz", "--iut", iut, "--present-as", "fuzzylite", "--feature", "E-ACCU-NSUM", "--max-findings",
                "1", "--budget", "60s", "--out", dir.toString()), err.toString());
        JsonNode j = json(dir);
        assertEquals("fuzzylite", j.at("/run/presentAs").asText());
        JsonNode f = j.at("/findings/0");
        assertEquals("E-ACCU-NSUM", f.get("feature").asText(), j.toString());
        assertEquals("wrong-value", f.get("kind").asText());
        // the case is standard FCL for the corpus; the text as sent is beside it, in fuzzylite's layout
        String id = f.get("id").asText();
        assertTrue(Files.readString(dir.resolve(id + ".fcl")).contains("ACCU : NSUM;"));
        String sent = Files.readString(dir.resolve("as-fuzzylite").resolve(id + ".fcl"));
        assertTrue(sent.contains("  ACCU : NSUM;\n") && sent.contains("  METHOD : COG"), sent);
        assertTrue(Files.readString(dir.resolve(id + ".fcl")).contains("in fuzzylite's layout (as-fuzzylite/" + id + ".fcl)"));
        assertTrue(out.toString().contains("sent in fuzzylite's layout; "), out.toString());
        assertTrue(Files.readString(dir.resolve("fuzz.md")).contains("Programs were sent in fuzzylite's layout"));
    }

    @Test
    void theReferenceInALibrarysLayoutFindsNothing_whatTheWriterCannotSayIsSkippedWithItsReason(@TempDir Path dir)
            throws Exception {
        for (String layout : new String[] {"fuzzylite", "jfuzzylogic"}) {
            Path out = dir.resolve(layout);
            assertEquals(0, run("fuzz", "--iut", "reference", "--present-as", layout, "--programs", "150", "--budget", "2m",
                    "--out", out.toString()), err.toString());
            JsonNode j = json(out);
            assertEquals(layout, j.at("/run/presentAs").asText());
            assertEquals(0, j.at("/counts/findings").asLong());
            assertEquals(0, j.get("presentationFaults").size(), j.toString());
            long skipped = j.at("/counts/notPresentable").asLong();
            long sent = j.at("/counts/programs").asLong();
            assertTrue(sent > 20 && skipped > 0, j.toString());
            // every reason is a loss the writer names (FCL-X1nn), and they add up
            long sum = 0;
            for (var e : (Iterable<java.util.Map.Entry<String, JsonNode>>) () -> j.get("notPresentable").fields()) {
                assertTrue(e.getKey().matches("FCL-X1\\d\\d"), e.getKey());
                sum += e.getValue().asLong();
            }
            assertEquals(skipped, sum);
        }
        // standard FCL, the default for the reference, is the layout of no library
        assertEquals(0, run("fuzz", "--iut", "reference", "--programs", "5", "--out", dir.resolve("none").toString()));
        assertEquals("none", json(dir.resolve("none")).at("/run/presentAs").asText());
    }

    @Test
    void anImplementationThatReadsOnlyItsOwnLayoutRejectsStandardFcl(@TempDir Path dir) throws Exception {
        assertEquals(1, run("fuzz", "--iut", "java:org.fclcert.fuzz.SpiFakes$FuzzyliteLayoutOnly", "--present-as", "none",
                "--programs", "10", "--budget", "60s", "--out", dir.toString()), err.toString());
        assertEquals("rejected", json(dir).at("/findings/0/kind").asText());
    }

    @Test
    void badUsageAndAnImplementationThatCannotRun_exit2(@TempDir Path dir) {
        assertEquals(2, run("fuzz", "--iut", "nonsense", "--out", dir.toString()));
        assertTrue(err.toString().contains("unknown implementation under test"), err.toString());
        assertEquals(2, run("fuzz", "--iut", "reference", "--budget", "soon", "--out", dir.toString()));
        assertEquals(2, run("fuzz", "--iut", "reference", "--feature", "O-HEDGE-VERY", "--out", dir.toString()));
        assertEquals(2, run("fuzz", "--iut", "reference", "--level", "basic", "--feature", "E-ACCU-NSUM", "--out", dir.toString()));
        assertEquals(2, run("fuzz", "--iut", "reference", "--present-as", "fuzzy", "--out", dir.toString()));
        assertEquals(2, run("fuzz", "--iut", "process:/nonexistent/iut", "--budget", "5s", "--out", dir.toString()));
        assertTrue(err.toString().contains("cannot run process:/nonexistent/iut"), err.toString());
    }
}
