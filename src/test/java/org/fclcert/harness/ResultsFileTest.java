package org.fclcert.harness;

import org.fclcert.probe.DataCheckEntry;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ResultsFileTest {
    @TempDir
    Path dir;

    static RunHeader header() {
        return new RunHeader(
                new RunHeader.Iut("fake", "0.1", "python3 fake.py", "process:python3 fake.py", null,
                        List.of("E-NOT"), Map.of("max-rules-per-block", 10L)),
                new RunHeader.Toolkit("0.1.0"), new RunHeader.CorpusInfo("conformance", 3, "ab12", 2),
                new RunHeader.Selection(List.of(), List.of(), List.of(), List.of(
                        new PlannedCase("B-COGS-001", "t1", "basic", List.of("B-COGS"), List.of()),
                        new PlannedCase("B-COGS-002", "t2", "basic", List.of("B-COGS"), List.of()))),
                "2026-11-22T04:00:00Z");
    }

    static CaseResult failed() {
        return new CaseResult(new PlannedCase("B-COGS-001", "t1", "basic", List.of("B-COGS"), List.of()),
                new CaseResult.Verdict(CaseStatus.FAILED, "step 1 of 1: y = NaN where 2.0 is expected",
                        List.of("a note"), null),
                new CaseResult.Evidence(new CaseResult.Step(1, Map.of("x", 1.0)),
                        new CaseResult.Mismatch.Outputs(Map.of("y", 2.0), Map.of("y", Double.NaN)), null,
                        Double.POSITIVE_INFINITY),
                new CaseResult.Export(ExportStatus.UNSUPPORTED, null),
                new CaseResult.Setup(null, "exact", "FUNCTION_BLOCK fb\n", 12L));
    }

    @Test
    void whatIsWrittenIsReadBackIncludingNaNAndInfinity() throws Exception {
        Path file = dir.resolve("out/results.jsonl");
        try (ResultsWriter w = ResultsWriter.create(file)) {
            w.header(header());
            w.accept(failed());
        }
        List<String> lines = Files.readAllLines(file);
        assertEquals(2, lines.size());
        assertTrue(lines.get(0).startsWith("{\"type\":\"run\""), lines.get(0));
        assertTrue(lines.get(1).startsWith("{\"type\":\"case\""), lines.get(1));

        ResultsFile read = ResultsFile.read(file);
        assertEquals(header(), read.header());
        CaseResult back = read.results().get(0);
        assertEquals(failed().message(), back.message());
        assertEquals(Double.POSITIVE_INFINITY, back.evidence().maxError());
        assertEquals(Map.of("y", 2.0), back.mismatch().orElseThrow().expected());
        // JSON has no NaN: Jackson writes it as the string "NaN" (documented in docs/report-format.md),
        // which is read back as the number
        assertEquals(Map.of("y", Double.NaN), back.mismatch().orElseThrow().actual());
        assertTrue(lines.get(1).contains("\"actual\":{\"y\":\"NaN\"}"), lines.get(1));
        assertEquals(failed(), back, "every part survives the round trip");
        assertTrue(lines.get(1).contains("\"maxError\":\"Infinity\""), lines.get(1));
        assertEquals(List.of(), read.problems());
    }

    @Test
    void theDataCheckListTravelsInTheResultsFile() throws Exception {
        Path file = dir.resolve("results.jsonl");
        DataCheckEntry rules = new DataCheckEntry("max-rules-per-block", "max. number of rules per block", "100000",
                "at-least", "rules", "generated blocks of 1, 2, 4, ... rules", "cap reached");
        try (ResultsWriter w = ResultsWriter.create(file)) {
            w.header(header());
            w.accept(failed());
            w.dataCheckList(List.of(rules));
        }
        ResultsFile read = ResultsFile.read(file);
        assertEquals(List.of(rules), read.dataCheckList());
        assertTrue(Files.readAllLines(file).get(2).startsWith("{\"type\":\"dataCheckList\",\"entries\":[{\"id\":"));
    }

    @Test
    void aLineCutShortByAKilledRunIsReportedAndTheRestKept() throws Exception {
        Path file = dir.resolve("results.jsonl");
        try (ResultsWriter w = ResultsWriter.create(file)) {
            w.header(header());
            w.accept(failed());
        }
        Files.writeString(file, "{\"type\":\"case\",\"id\":\"B-CO", StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        ResultsFile read = ResultsFile.read(file);
        assertEquals(1, read.results().size());
        assertEquals(1, read.problems().size());
        assertTrue(read.problems().get(0).startsWith(file + ":3: unreadable line ignored"), read.problems().get(0));
    }

    @Test
    void aFileWithoutHeaderIsRefusedWithItsName() throws IOException {
        Path file = dir.resolve("other.jsonl");
        Files.writeString(file, "{\"type\":\"case\",\"id\":\"X\",\"status\":\"passed\"}\n");
        ResultsFile.InvalidResultsException e = assertThrows(ResultsFile.InvalidResultsException.class,
                () -> ResultsFile.read(file));
        assertTrue(e.getMessage().startsWith(file + ": no run header line"), e.getMessage());
    }
}
