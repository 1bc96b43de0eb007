package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CorpusLoadTest {
    @TempDir
    Path dir;

    private static final String PROGRAM = """
            FUNCTION_BLOCK f
            VAR_INPUT x : REAL; END_VAR
            END_FUNCTION_BLOCK
            """;

    private static final String POSITIVE = """
            (*---
            id: B-COGS-002
            title: two steps
            level: basic
            features: [B-FB, B-COGS]
            tests: [B-COGS]
            tolerance: exact
            flags: [stateful, "interpretation:6"]
            derivation: |
              1/3 + 1/3
            vectors:
              - in: {temp: 5, pressure: 60}
                out: {valve: 74.80314960629921}
              - in: {temp: -1.5e+2, Pressure: 1e-3}
                out: {valve: 0}
            ---*)
            """ + PROGRAM;

    private static final String NEGATIVE = """
            (*---
            id: N-C002-001
            title: undefined term
            level: basic
            features: [B-FB]
            tests: []
            expect: reject
            error: {code: FCL-C002, line: 12}
            ---*)
            """ + PROGRAM;

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
        return p;
    }

    @Test
    void loadsEveryFieldOfAPositiveCase() throws Exception {
        write("basic/B-COGS-002.fcl", POSITIVE);
        CorpusCase c = Corpus.load(dir).cases().get(0);
        assertEquals("B-COGS-002", c.id());
        assertEquals("two steps", c.title());
        assertEquals(ConformanceLevel.BASIC, c.level());
        assertEquals(List.of(Feature.B_FB, Feature.B_COGS), c.features());
        assertEquals(List.of(Feature.B_COGS), c.tests());
        assertEquals(Tolerance.EXACT, c.tolerance());
        assertTrue(c.stateful());
        assertEquals(Optional.of("6"), c.interpretation());
        assertEquals(Optional.of("1/3 + 1/3"), c.derivation());
        assertEquals(Optional.empty(), c.block());
        assertFalse(c.expectReject());
        assertEquals(2, c.vectors().size());
        assertEquals(Map.of("temp", 5.0, "pressure", 60.0), c.vectors().get(0).in());
        assertEquals(List.of("temp", "pressure"), List.copyOf(c.vectors().get(0).in().keySet()));
        assertEquals(74.80314960629921, c.vectors().get(0).out().get("valve"));
        // 1e-3 without a dot is text in YAML 1.1; the loader still reads it as a number
        assertEquals(-150.0, c.vectors().get(1).in().get("temp"));
        assertEquals(0.001, c.vectors().get(1).in().get("Pressure"));
    }

    @Test
    void programTextKeepsLineNumbersOfTheFile() throws Exception {
        write("basic/B-COGS-002.fcl", POSITIVE);
        CorpusCase c = Corpus.load(dir).cases().get(0);
        List<String> fileLines = Files.readAllLines(c.path());
        List<String> programLines = c.programText().lines().toList();
        // the metadata spans lines 1..16; FUNCTION_BLOCK is on line 17 of both
        assertEquals("FUNCTION_BLOCK f", fileLines.get(16));
        assertEquals("FUNCTION_BLOCK f", programLines.get(16));
        assertEquals(fileLines.size(), programLines.size());
        assertFalse(c.programText().contains("(*"));
        assertTrue(programLines.subList(0, 16).stream().allMatch(String::isEmpty));
    }

    @Test
    void loadsANegativeCase() throws Exception {
        write("negative/N-C002-001.fcl", NEGATIVE);
        CorpusCase c = Corpus.load(dir).cases().get(0);
        assertTrue(c.expectReject());
        assertEquals(Optional.of(new ExpectedError("FCL-C002", 12)), c.expectedError());
        assertTrue(c.vectors().isEmpty());
        assertEquals(Tolerance.EXACT, c.tolerance());
    }

    @Test
    void casesAreSortedByIdWhateverTheirDirectory() throws Exception {
        write("negative/N-C002-001.fcl", NEGATIVE);
        write("basic/B-COGS-002.fcl", POSITIVE);
        write("basic/B-COGS-001.fcl", POSITIVE.replace("B-COGS-002", "B-COGS-001"));
        assertEquals(List.of("B-COGS-001", "B-COGS-002", "N-C002-001"),
                Corpus.load(dir).cases().stream().map(CorpusCase::id).toList());
    }

    @Test
    void collectsEveryProblemWithItsLineInsteadOfStoppingAtTheFirst() throws Exception {
        write("basic/B-COGS-002.fcl", POSITIVE
                .replace("level: basic", "level: expert")            // line 4
                .replace("tests: [B-COGS]", "tests: [B-COGZ]")       // line 6
                .replace("tolerance: exact", "tolerance: loose")     // line 7
                .replace("valve: 0}", "valve: nine}"));              // vectors at line 11
        write("basic/B-X-001.fcl", "FUNCTION_BLOCK f END_FUNCTION_BLOCK\n");
        CorpusException e = assertThrows(CorpusException.class, () -> Corpus.load(dir));
        List<String> lines = e.problems().stream().map(CorpusProblem::toString).toList();
        assertEquals(5, lines.size(), lines.toString());
        Path a = dir.resolve("basic/B-COGS-002.fcl");
        assertTrue(lines.get(0).startsWith(a + ":4: level 'expert'"), lines.get(0));
        assertTrue(lines.get(1).startsWith(a + ":6: 'B-COGZ' in 'tests'"), lines.get(1));
        assertTrue(lines.get(2).startsWith(a + ":7: tolerance 'loose'"), lines.get(2));
        assertTrue(lines.get(3).startsWith(a + ":11: vector 2 'out': 'valve' must be a finite number"), lines.get(3));
        assertTrue(lines.get(4).startsWith(dir.resolve("basic/B-X-001.fcl") + ":1: a case file must start"),
                lines.get(4));
    }

    @Test
    void reportsYamlSyntaxErrorsAtTheirLine() throws Exception {
        write("basic/B-COGS-002.fcl", POSITIVE.replace("tests: [B-COGS]", "tests: [B-COGS"));
        CorpusException e = assertThrows(CorpusException.class, () -> Corpus.load(dir));
        CorpusProblem p = e.problems().get(0);
        assertTrue(p.message().startsWith("the metadata is not valid YAML"), p.message());
        assertTrue(p.line() >= 6 && p.line() <= 7, "line " + p.line());
    }

    @Test
    void reportsUnclosedMetadataUnknownAndDuplicateFields() throws Exception {
        write("a/B-COGS-001.fcl", POSITIVE.replace("---*)", "--*)"));
        write("b/B-COGS-002.fcl", POSITIVE.replace("title: two steps", "title: two steps\ntitel: typo"));
        write("c/B-COGS-003.fcl", POSITIVE.replace("tolerance: exact", "tolerance: exact\ntolerance: exact"));
        List<String> messages = Corpus.scan(dir).problems().stream().map(CorpusProblem::toString).toList();
        assertEquals(3, messages.size(), messages.toString());
        assertTrue(messages.get(0).contains("B-COGS-001.fcl:1: the metadata comment is never closed"), messages.get(0));
        assertTrue(messages.get(1).contains("B-COGS-002.fcl:4: unknown metadata field 'titel'"), messages.get(1));
        assertTrue(messages.get(2).contains("B-COGS-003.fcl:") && messages.get(2).contains("Duplicate field"),
                messages.get(2));
    }

    @Test
    void rejectsDuplicateIdsAndMixedPositiveNegativeFields() throws Exception {
        write("basic/B-COGS-002.fcl", POSITIVE);
        write("other/B-COGS-002.fcl", POSITIVE);
        write("negative/N-C002-001.fcl", NEGATIVE.replace("expect: reject", "expect: reject\nvectors: []"));
        write("negative/N-C002-002.fcl", NEGATIVE.replace("N-C002-001", "N-C002-002")
                .replace("error: {code: FCL-C002, line: 12}", "error: {code: C002, line: 0}"));
        Corpus.Scan scan = Corpus.scan(dir);
        List<String> messages = scan.problems().stream().map(CorpusProblem::message).toList();
        assertTrue(messages.contains("id B-COGS-002 is already used by " + dir.resolve("basic/B-COGS-002.fcl")),
                messages.toString());
        assertTrue(messages.contains("a negative case ('expect: reject') has no vectors"), messages.toString());
        assertTrue(messages.contains("error code must look like FCL-S001 or FCL-C002"), messages.toString());
        assertTrue(messages.contains("error line must be a positive whole number (the line in the case file)"),
                messages.toString());
        assertEquals(4, messages.size(), messages.toString());
    }

    @Test
    void aMissingDirectoryIsAProblemNotACrash() {
        CorpusException e = assertThrows(CorpusException.class, () -> Corpus.load(dir.resolve("nope")));
        assertEquals(1, e.problems().size());
    }

    @Test
    void digestChangesWhenAnyCaseChanges() throws Exception {
        write("basic/B-COGS-002.fcl", POSITIVE);
        String before = Corpus.load(dir).sha256();
        assertEquals(before, Corpus.load(dir).sha256());
        write("basic/B-COGS-002.fcl", POSITIVE.replace("valve: 0}", "valve: 0.5}"));
        assertFalse(before.equals(Corpus.load(dir).sha256()));
        assertEquals(64, before.length());
    }
}
