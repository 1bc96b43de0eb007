package org.fclcert.cli;

import static org.fclcert.cli.CheckCommandTest.UNDEFINED_TERM;
import static org.fclcert.cli.CheckCommandTest.VALVE;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FmtCommandTest {
    /** The valve in canonical layout, written by hand from the layout rules of CanonicalWriter. */
    static final String CANONICAL_VALVE = """
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

    /** The same program as the figure lays it out, in mixed-case keywords with a comment and a list declaration. */
    static final String SLOPPY_VALVE = """
            function_block Fuzzy_FB (* the valve of 5.3 *)
            var_input temp, pressure: REAL; end_var
            var_output valve: REAL; end_var
            fuzzify temp term cold := (3, 1) (27, 0); term hot := (3, 0) (27, 1); end_fuzzify
            fuzzify pressure term low := (55, 1) (95, 0); term high := (55, 0) (95, 1); end_fuzzify
            defuzzify valve term drainage := -100; term closed := 0; term inlet := 100;
              method: cogs; default := 0; end_defuzzify
            ruleblock No1 and: min; accu: max;
              rule 1: if temp is cold and pressure is low then valve is inlet;
              rule 2: if temp is cold and pressure is high then valve is closed with 0.8;
              rule 3: if temp is hot and pressure is low then valve is closed;
              rule 4: if temp is hot and pressure is high then valve is drainage;
            end_ruleblock
            end_function_block
            """;

    @TempDir
    Path dir;

    @Test
    void printsTheCanonicalText() {
        Path file = Cli.write(dir, "valve.fcl", VALVE);
        Cli r = Cli.run("fmt", file.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(CANONICAL_VALVE, r.out());
        assertEquals("", r.err());
    }

    @Test
    void anyLayoutAndKeywordCaseGivesTheSameText() {
        Path file = Cli.write(dir, "sloppy.fcl", SLOPPY_VALVE);
        Cli r = Cli.run("fmt", file.toString());
        assertEquals(0, r.exitCode(), r.err());
        // the comment ends the FUNCTION_BLOCK line, where it stood
        assertEquals(CANONICAL_VALVE.replace("FUNCTION_BLOCK Fuzzy_FB\n", "FUNCTION_BLOCK Fuzzy_FB (* the valve of 5.3 *)\n"),
                r.out());
        assertEquals("", r.err());
    }

    @Test
    void writeRewritesTheFileOnceThenLeavesItAlone() {
        String noComment = SLOPPY_VALVE.replace(" (* the valve of 5.3 *)", "");
        Path file = Cli.write(dir, "sloppy.fcl", noComment);
        Cli first = Cli.run("fmt", "--write", file.toString());
        assertEquals(0, first.exitCode(), first.err());
        assertEquals("", first.out());
        assertEquals(CANONICAL_VALVE, Cli.read(file));
        assertEquals(List.of("fclcert: rewrote " + file), first.errLines());

        Cli second = Cli.run("fmt", "--write", file.toString());
        assertEquals(0, second.exitCode());
        assertEquals(List.of("fclcert: " + file + " is already in canonical layout"), second.errLines());
    }

    @Test
    void writeKeepsCommentsAndDropCommentsLeavesThemOut() {
        Path file = Cli.write(dir, "sloppy.fcl", SLOPPY_VALVE);
        Cli kept = Cli.run("fmt", "--write", file.toString());
        assertEquals(0, kept.exitCode(), kept.err());
        assertEquals(CANONICAL_VALVE.replace("FUNCTION_BLOCK Fuzzy_FB\n",
                "FUNCTION_BLOCK Fuzzy_FB (* the valve of 5.3 *)\n"), Cli.read(file));
        assertEquals(List.of("fclcert: rewrote " + file), kept.errLines());

        Cli dropped = Cli.run("fmt", "--write", "--drop-comments", file.toString());
        assertEquals(0, dropped.exitCode(), dropped.err());
        assertEquals(CANONICAL_VALVE, Cli.read(file));
        assertEquals(List.of("fclcert: rewrote " + file), dropped.errLines());
    }

    /**
     * The comment-rich program of CommentsKeptTest (units beside terms, block comments on their own lines and at
     * line ends, before the first block, in VAR sections, between rules, at the end of the file): --write keeps
     * every comment byte for byte and in order, the file reads back to the same program, and a second --write
     * finds nothing to do.
     */
    @Test
    void writeKeepsEveryCommentOfACommentRichProgram() {
        String source = org.fclcert.write.CommentsKeptTestAccess.commentedHeater();
        Path file = Cli.write(dir, "dryer.fcl", source);
        Cli first = Cli.run("fmt", "--write", file.toString());
        assertEquals(0, first.exitCode(), first.err());
        assertEquals(List.of("fclcert: rewrote " + file), first.errLines().stream()
                .filter(l -> l.startsWith("fclcert:")).toList());
        String written = Cli.read(file);
        List<String> comments = org.fclcert.write.CommentsKeptTestAccess.comments(source);
        assertEquals(43, comments.size());
        assertEquals(comments, org.fclcert.write.CommentsKeptTestAccess.comments(written));
        StrictReader reader = new StrictReader();
        assertEquals(reader.read("a", source).program().orElseThrow(), reader.read("a", written).program().orElseThrow());

        Cli second = Cli.run("fmt", "--write", file.toString());
        assertEquals(0, second.exitCode(), second.err());
        assertTrue(second.errLines().contains("fclcert: " + file + " is already in canonical layout"), second.err());
        assertEquals(written, Cli.read(file));

        Cli check = Cli.run("fmt", "--check", file.toString());
        assertEquals(0, check.exitCode(), check.err());
        assertEquals("", check.out());
    }

    @Test
    void aProgramWithErrorsIsNotRewritten() {
        Path file = Cli.write(dir, "bad.fcl", UNDEFINED_TERM);
        Cli r = Cli.run("fmt", "--write", file.toString());
        assertEquals(1, r.exitCode());
        assertEquals("", r.out());
        assertEquals(UNDEFINED_TERM, Cli.read(file));
        List<String> err = r.errLines();
        assertEquals(2, err.size(), r.err());
        assertTrue(err.get(0).startsWith(file + ":29:54: error FCL-C002: "), r.err());
        assertEquals("fclcert: " + file + " has errors; not formatted", err.get(1));
    }

    @Test
    void aMissingFileIsExitCodeTwo() {
        String missing = dir.resolve("nope.fcl").toString();
        Cli r = Cli.run("fmt", missing);
        assertEquals(2, r.exitCode());
        assertEquals(List.of("fclcert: cannot read " + missing + ": no such file"), r.errLines());
    }
}
