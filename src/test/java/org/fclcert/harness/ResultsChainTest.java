package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The hash chain of results.jsonl: any line changed, removed or added breaks it where fclcert can name it. */
class ResultsChainTest {
    @TempDir
    Path dir;

    private List<String> written() throws Exception {
        Path file = dir.resolve("results.jsonl");
        try (ResultsWriter w = ResultsWriter.create(file)) {
            w.header(new RunHeader(new RunHeader.Iut("x", "1", "c", "reference", null, List.of(), null),
                    new RunHeader.Toolkit("0.1"), new RunHeader.CorpusInfo("conformance", 2, "ab", 1),
                    new RunHeader.Selection(List.of(), List.of(), List.of(), List.of()), "2026-01-01T00:00:00Z"));
            w.accept(CaseResult.skipped(new PlannedCase("B-FB-001", "t", "basic", List.of(), List.of()), "why"));
            w.accept(CaseResult.skipped(new PlannedCase("B-FB-002", "t", "basic", List.of(), List.of()), "why"));
            ResultsChain.Seal seal = w.finish("2026-01-01T00:01:00Z");
            assertEquals(3, seal.lines());
        }
        return new ArrayList<>(Files.readAllLines(file));
    }

    @Test
    void anUneditedFileIsIntactAndSealedWithTheDigestOfItsLastLine() throws Exception {
        List<String> lines = written();
        ResultsChain.Check check = ResultsChain.check("results.jsonl", lines);
        assertTrue(check.intact(), check.firstBreak());
        assertNotNull(check.seal());
        assertEquals(ResultsChain.sha256(lines.get(2)), check.seal().digest());
        assertEquals("2026-01-01T00:01:00Z", check.seal().endedAt());
    }

    @Test
    void aChangedLineBreaksTheChainAtTheLineAfterIt() throws Exception {
        List<String> lines = written();
        lines.set(1, lines.get(1).replace("\"skipped\"", "\"passed\""));
        assertEquals("results.jsonl:3: the chain breaks here: 'prev' is not the sha256 of the line before it"
                + " (a line before this one was changed, removed, added or moved)",
                ResultsChain.check("results.jsonl", lines).firstBreak());
    }

    @Test
    void aRemovedLineALineAfterTheEndAndAStrippedHashAreEachNamed() throws Exception {
        List<String> lines = written();
        List<String> removed = new ArrayList<>(lines);
        removed.remove(2);
        assertTrue(ResultsChain.check("r", removed).firstBreak().startsWith("r:3: the chain breaks here"));
        List<String> added = new ArrayList<>(lines);
        added.add(lines.get(1));
        assertTrue(ResultsChain.check("r", added).firstBreak().startsWith("r:5: a line after the run's end line"));
        List<String> stripped = new ArrayList<>(lines);
        stripped.set(0, stripped.get(0).replaceFirst(",\"prev\":\"0+\"", ""));
        assertTrue(ResultsChain.check("r", stripped).firstBreak().startsWith("r:1: the line carries no 'prev' hash"));
    }

    @Test
    void aRunCutShortIsIntactButNotSealed() throws Exception {
        List<String> lines = written();
        ResultsChain.Check check = ResultsChain.check("r", lines.subList(0, 3));
        assertTrue(check.intact());
        assertNull(check.seal());
    }
}
