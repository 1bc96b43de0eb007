package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 26: a custom corpus says so in the headline and earns no Basic Level verdict unless it holds every built-in
 * Basic Level case unchanged; a corpus with an expected value the exact reference does not reproduce is refused,
 * naming the case, before any implementation is started.
 */
class CustomCorpusTest {
    @TempDir
    Path dir;

    private Path corpusOf(String id, String from, String to) throws Exception {
        Path corpus = dir.resolve("corpus");
        Files.createDirectories(corpus.resolve("basic"));
        String text = Files.readString(Path.of("conformance/basic/" + id + ".fcl"));
        assertTrue(text.contains(from), from);
        Files.writeString(corpus.resolve("basic/" + id + ".fcl"), text.replace(from, to));
        return corpus;
    }

    @Test
    void aOneCaseCorpusNeverYieldsBasicLevelConformant() throws Exception {
        Path corpus = corpusOf("B-ACCU-MAX-001", "", "");
        Cli c = Cli.run("certify", "--iut", "reference", "--corpus", corpus.toString(), "--no-probe", "--seed", "3",
                "--out", dir.resolve("out").toString());
        assertEquals(0, c.exitCode(), c.err());
        assertTrue(c.out().contains("1 cases, 1 passed"), c.out());
        // the built-in Basic Level cases it lacks are named (how many grows with the corpus)
        assertTrue(c.out().matches("(?s).*Basic Level: not determined \\(the custom corpus does not hold [1-9][0-9]* of"
                + " the built-in Basic Level cases unchanged \\(B-ACCU-MAX-002, .*"), c.out());
        assertTrue(c.out().contains("a custom corpus (1 cases, sha256 "), c.out());
        String md = Files.readString(dir.resolve("out/report.md"));
        assertTrue(md.contains("not the fclcert conformance corpus built into this fclcert"), md);
        assertFalse(md.contains("**Basic Level: conformant**"), md);
        assertEquals(0, Cli.run("report", "--verify", dir.resolve("out").toString()).exitCode());
    }

    @Test
    void aCorpusWithAWrongExpectedValueIsRefusedBeforeAnyImplementationStarts() throws Exception {
        Path corpus = corpusOf("B-ACCU-MAX-001", "out: {y: 90}", "out: {y: 91}");
        Path marker = dir.resolve("started");
        Cli c = Cli.run("certify", "--iut", "process:touch " + marker, "--corpus", corpus.toString(), "--no-probe",
                "--out", dir.resolve("out").toString());
        assertEquals(2, c.exitCode(), c.out() + c.err());
        assertTrue(c.err().contains("is refused: the exact reference does not reproduce what 1 of its case(s) expect"),
                c.err());
        assertTrue(c.err().contains("case B-ACCU-MAX-001: the reference does not reproduce its expected values:"
                + " vector 2: 'y' expected 91.0, the reference evaluator gives 90.0"), c.err());
        assertFalse(Files.exists(marker), "the implementation was started");
    }

    @Test
    void aCorpusWithEveryBasicCaseButOneExtensionCaseGetsItsBasicVerdictAndNoExtensionVerdict() throws Exception {
        Path corpus = dir.resolve("corpus");
        for (String level : new String[] {"basic", "negative"}) {
            Files.createDirectories(corpus.resolve(level));
            try (var files = Files.list(Path.of("conformance", level))) {
                for (Path f : files.toList()) {
                    Files.copy(f, corpus.resolve(level).resolve(f.getFileName()));
                }
            }
        }
        Files.createDirectories(corpus.resolve("extension"));
        Files.copy(Path.of("conformance/extension/E-ACCU-BSUM-001.fcl"), corpus.resolve("extension/E-ACCU-BSUM-001.fcl"));
        long extension = org.fclcert.corpus.Corpus.load(Path.of("conformance")).cases().stream()
                .filter(k -> k.level() == org.fclcert.model.ConformanceLevel.EXTENSION && k.interpretation().isEmpty())
                .filter(k -> !k.expectReject())   // the negative ones of the Extension Level were copied with negative/
                .count();
        Cli c = Cli.run("certify", "--iut", "reference", "--corpus", corpus.toString(), "--no-probe", "--seed", "5",
                "--out", dir.resolve("out").toString());
        assertEquals(0, c.exitCode(), c.err());
        // the Basic verdict is issued (every built-in Basic case is there), the Extension one is not, with its reason
        assertTrue(c.out().contains("Basic Level: conformant"), c.out());
        String md = Files.readString(dir.resolve("out/report.md"));
        assertTrue(md.contains("Extension Level (Table 9): not determined: the custom corpus does not hold "
                + (extension - 1) + " of the built-in Extension Level cases unchanged"), md);
        var report = new com.fasterxml.jackson.databind.ObjectMapper().readTree(dir.resolve("out/report.json").toFile());
        int table9 = 0;
        for (var row : report.path("features")) {
            if (row.path("table").asInt() == 9) {
                table9++;
                assertTrue(row.path("status").asText().matches("not-determined|not-tested|NOT_DETERMINED|NOT_TESTED"),
                        row.toString());
            }
        }
        assertEquals(25, table9, "Table 9 rows");
        assertEquals(0, Cli.run("report", "--verify", dir.resolve("out").toString()).exitCode());
    }
}
