package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CheckCommandTest {
    static final String VALVE = """
            FUNCTION_BLOCK Fuzzy_FB
            VAR_INPUT
                temp : REAL;
                pressure : REAL;
            END_VAR
            VAR_OUTPUT
                valve : REAL;
            END_VAR
            FUZZIFY temp
                TERM cold := (3, 1) (27, 0);
                TERM hot := (3, 0) (27, 1);
            END_FUZZIFY
            FUZZIFY pressure
                TERM low := (55, 1) (95, 0);
                TERM high := (55, 0) (95, 1);
            END_FUZZIFY
            DEFUZZIFY valve
                TERM drainage := -100;
                TERM closed := 0;
                TERM inlet := 100;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF temp IS cold AND pressure IS low THEN valve IS inlet;
                RULE 2 : IF temp IS cold AND pressure IS high THEN valve IS closed WITH 0.8;
                RULE 3 : IF temp IS hot AND pressure IS low THEN valve IS closed;
                RULE 4 : IF temp IS hot AND pressure IS high THEN valve IS drainage;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * The valve with rule 3 concluding an undefined term - error FCL-C002 on line 29 at the
     * subconclusion: "    RULE 3 : IF temp IS hot AND pressure IS low THEN " is 53 characters, so
     * 'valve' starts in column 54.
     */
    static final String UNDEFINED_TERM = VALVE.replace("low THEN valve IS closed;", "low THEN valve IS shut;");

    /**
     * The valve with WITH 0 in rule 2 - warning FCL-W004 only, on line 28 at the factor:
     * "    RULE 2 : IF temp IS cold AND pressure IS high THEN valve IS closed WITH " is 76 characters.
     */
    static final String ZERO_WEIGHT = VALVE.replace("WITH 0.8", "WITH 0");

    /** The valve without the ';' after the first input declaration - a syntax error on line 3. */
    static final String MISSING_SEMICOLON = VALVE.replace("temp : REAL;", "temp : REAL");

    @TempDir
    Path dir;

    @Test
    void aValidProgramHasNoOutputAndExitCodeZero() {
        Path valve = Cli.write(dir, "valve.fcl", VALVE);
        Cli r = Cli.run("check", valve.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertEquals("", r.out());
        assertEquals(List.of("fclcert: 1 file checked: 0 errors, 0 warnings"), r.errLines());
    }

    @Test
    void anErrorIsOneLocatedLineAndExitCodeOne() {
        Path bad = Cli.write(dir, "bad.fcl", UNDEFINED_TERM);
        Cli r = Cli.run("check", bad.toString());
        assertEquals(1, r.exitCode());
        assertEquals(1, r.outLines().size(), r.out());
        assertTrue(r.outLines().get(0).startsWith(bad + ":29:54: error FCL-C002: "), r.out());
        assertTrue(r.outLines().get(0).contains("'shut'"), r.out());
        assertEquals(List.of("fclcert: 1 file checked: 1 error, 0 warnings"), r.errLines());
    }

    @Test
    void warningsAloneKeepExitCodeZero() {
        Path file = Cli.write(dir, "zero.fcl", ZERO_WEIGHT);
        Cli r = Cli.run("check", file.toString());
        assertEquals(0, r.exitCode(), r.out());
        assertEquals(1, r.outLines().size(), r.out());
        assertTrue(r.outLines().get(0).startsWith(file + ":28:77: warning FCL-W004: "), r.out());
        assertEquals(List.of("fclcert: 1 file checked: 0 errors, 1 warning"), r.errLines());
    }

    @Test
    void syntaxErrorsAreLocatedToo() {
        Path file = Cli.write(dir, "semi.fcl", MISSING_SEMICOLON);
        Cli r = Cli.run("check", file.toString());
        assertEquals(1, r.exitCode());
        assertFalse(r.outLines().isEmpty());
        assertTrue(r.outLines().get(0).matches(java.util.regex.Pattern.quote(file.toString())
                + ":[34]:[0-9]+: error FCL-S[0-9]{3}: .+"), r.out());
    }

    @Test
    void severalFilesAreCheckedInOrderAndAnyErrorGivesOne() {
        Path good = Cli.write(dir, "good.fcl", VALVE);
        Path bad = Cli.write(dir, "bad.fcl", UNDEFINED_TERM);
        Cli r = Cli.run("check", good.toString(), bad.toString());
        assertEquals(1, r.exitCode());
        assertTrue(r.out().startsWith(bad + ":29:54: error FCL-C002: "), r.out());
        assertEquals(List.of("fclcert: 2 files checked: 1 error, 0 warnings"), r.errLines());
    }

    @Test
    void aMissingFileIsExitCodeTwoWithoutStackTrace() {
        Path good = Cli.write(dir, "good.fcl", VALVE);
        String missing = dir.resolve("missing.fcl").toString();
        Cli r = Cli.run("check", missing, good.toString());
        assertEquals(2, r.exitCode());
        assertEquals("", r.out());
        assertEquals(List.of("fclcert: cannot read " + missing + ": no such file",
                "fclcert: 1 file checked: 0 errors, 0 warnings"), r.errLines());
    }

    @Test
    void aDirectoryIsNotAProgram() {
        Cli r = Cli.run("check", dir.toString());
        assertEquals(2, r.exitCode());
        assertEquals("fclcert: cannot read " + dir + ": it is a directory", r.errLines().get(0));
    }

    /* Issue 18 item 12: /dev/zero used 5.5 GB then exit 3; a FIFO hung forever. */
    @Test
    void onlyRegularFilesAreRead() throws Exception {
        Cli zero = Cli.run("check", "/dev/zero");
        assertEquals(2, zero.exitCode());
        assertEquals("fclcert: cannot read /dev/zero: not a regular file (a device, pipe or socket);"
                + " fclcert reads only files", zero.errLines().get(0));
        Path fifo = dir.resolve("pipe.fcl");
        org.junit.jupiter.api.Assumptions.assumeTrue(
                new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor() == 0, "mkfifo is not available");
        Cli pipe = Cli.run("check", fifo.toString());   // would block in open() if it were opened
        assertEquals(2, pipe.exitCode());
        assertTrue(pipe.errLines().get(0).endsWith(": not a regular file (a device, pipe or socket); fclcert reads only files"),
                pipe.err());
    }

    @Test
    void aFileOverTheSizeLimitIsRefusedUnread() throws Exception {
        Path big = dir.resolve("big.fcl");
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(org.fclcert.model.Limits.MAX_SOURCE_BYTES + 1);   // sparse: no disk, no memory
        }
        Cli r = Cli.run("check", big.toString());
        assertEquals(2, r.exitCode());
        assertEquals("fclcert: cannot read " + big + ": larger than fclcert's limit of 128 MiB"
                + " (org.fclcert.model.Limits.MAX_SOURCE_BYTES)", r.errLines().get(0));
    }

    @Test
    void aByteOrderMarkIsNotPartOfTheProgram() {
        Path file = Cli.write(dir, "bom.fcl", "\uFEFF" + UNDEFINED_TERM);
        Cli r = Cli.run("check", file.toString());
        assertEquals(1, r.exitCode());
        assertEquals(1, r.outLines().size(), r.out());
        assertTrue(r.outLines().get(0).startsWith(file + ":29:54: error FCL-C002: "), r.out());
    }

    @Test
    void noFileIsAUsageError() {
        Cli r = Cli.run("check");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().startsWith("Missing required parameter: 'FILE'"), r.err());
    }

    @Test
    void anUnknownFormatIsAUsageError() {
        Cli r = Cli.run("check", "--format", "xml", "x.fcl");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().startsWith("Invalid value for option '--format'"), r.err());
    }

    @Test
    void jsonIsAnArrayOfDiagnostics() throws Exception {
        Path good = Cli.write(dir, "good.fcl", VALVE);
        Path bad = Cli.write(dir, "bad.fcl", UNDEFINED_TERM);
        Cli r = Cli.run("check", "--format", "json", good.toString(), bad.toString());
        assertEquals(1, r.exitCode());
        JsonNode array = new ObjectMapper().readTree(r.out());
        assertTrue(array.isArray());
        assertEquals(1, array.size(), r.out());
        JsonNode d = array.get(0);
        assertEquals(bad.toString(), d.get("file").asText());
        assertEquals(29, d.get("line").asInt());
        assertEquals("error", d.get("severity").asText());
        assertEquals("FCL-C002", d.get("code").asText());
        assertEquals(54, d.get("column").asInt());
        assertTrue(d.get("message").asText().contains("shut"));
        assertEquals(List.of("file", "line", "column", "severity", "code", "message"),
                iterableToList(d.fieldNames()));
    }

    @Test
    void jsonOfAValidProgramIsAnEmptyArray() throws Exception {
        Path good = Cli.write(dir, "good.fcl", VALVE);
        Cli r = Cli.run("check", "--format", "json", good.toString());
        assertEquals(0, r.exitCode());
        assertEquals(0, new ObjectMapper().readTree(r.out()).size());
    }

    private static List<String> iterableToList(java.util.Iterator<String> it) {
        List<String> out = new java.util.ArrayList<>();
        it.forEachRemaining(out::add);
        return out;
    }

    @Test
    void aLibraryFileReadStrictlyNamesTheDialectThatReadsItWithFewerErrors() {
        Cli r = Cli.run("check", "examples/jfuzzylogic/fan.fcl");
        assertEquals(1, r.exitCode());
        List<String> hints = r.errLines().stream().filter(l -> l.contains(": read as ")).toList();
        assertEquals(1, hints.size(), r.err());
        assertTrue(hints.get(0).startsWith("fclcert: examples/jfuzzylogic/fan.fcl: read as jFuzzyLogic ("), hints.get(0));
        // strictly 6 errors (the summary line says so); read as jFuzzyLogic, none
        assertTrue(r.err().contains("fclcert: 1 file checked: 6 errors, 0 warnings"), r.err());
        assertTrue(hints.get(0).endsWith(") it has 0 errors instead of 6: use --dialect jfuzzylogic, or 'fclcert convert"
                + " --from jfuzzylogic examples/jfuzzylogic/fan.fcl' to turn it into standard FCL"), hints.get(0));
        assertEquals(0, Cli.run("check", "--dialect", "jfuzzylogic", "examples/jfuzzylogic/fan.fcl").exitCode());
        // a standard program with a syntax error gets no such guess
        Cli standard = Cli.run("check", "examples/broken.fcl");
        assertTrue(standard.errLines().stream().noneMatch(l -> l.contains("read as")), standard.err());
    }

    @Test
    void aHabitFromALibraryInAStandardFileGetsNoHintThatWouldAddErrors(@TempDir Path dir) {
        // ACCU inside DEFUZZIFY is a fuzzylite sign; but fuzzylite does not accept '(*' comments, so reading this
        // commented standard program as fuzzylite gives more errors than the one strict error: no hint
        String text = Cli.read(Path.of("examples/heater.fcl")).replace("    METHOD : CoGS;\n",
                "    METHOD : CoGS;\n    ACCU : MAX;\n");
        Path file = Cli.write(dir, "habit.fcl", text);
        Cli r = Cli.run("check", file.toString());
        assertEquals(1, r.exitCode());
        assertEquals(1, r.outLines().stream().filter(l -> l.contains(": error ")).count(), r.out());
        assertTrue(r.errLines().stream().noneMatch(l -> l.contains("read as") || l.contains("looks like")), r.err());
        // the same with a missing ';' and no DEFAULT (jFuzzyLogic's habit): the ';' stays an error in every dialect
        String two = Cli.read(Path.of("examples/heater.fcl")).replace("    DEFAULT := 0;\n", "")
                .replace("    TERM half := 50;", "    TERM half := 50");
        Cli r2 = Cli.run("check", Cli.write(dir, "two.fcl", two).toString());
        assertEquals(1, r2.exitCode());
        assertTrue(r2.errLines().stream().noneMatch(l -> l.contains("read as") || l.contains("looks like")), r2.err());
    }

    @Test
    void controlCharactersOfAProgramNeverReachTheTerminalRaw(@TempDir Path dir) {
        // a dialect reader takes a block name verbatim, ESC and all, and quotes it in its warning
        Path file = Cli.write(dir, "esc.fcl", "FUNCTION_BLOCK f\u001b]0;pwned\u0007 x\nEND_FUNCTION_BLOCK\n");
        for (String dialect : List.of("strict", "jfuzzylogic", "fuzzylite", "ffll")) {
            Cli c = Cli.run("check", "--dialect", dialect, file.toString());
            String all = c.out() + c.err();
            assertTrue(all.chars().noneMatch(ch -> ch == 0x1b || ch == 0x07), dialect + ": " + all);
        }
        Cli jfl = Cli.run("check", "--dialect", "jfuzzylogic", file.toString());
        assertTrue((jfl.out() + jfl.err()).contains("the block name 'f\\e]0' as written"), jfl.out() + jfl.err());
    }
}
