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
        assertTrue(c.out().contains("Basic Level: not determined (the custom corpus does not hold 91 of"
                + " the built-in Basic Level cases unchanged"), c.out());
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
}
