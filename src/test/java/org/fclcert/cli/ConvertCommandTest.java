package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code fclcert convert}: exit codes, what goes to stdout and stderr, --out, --from, --approximate-points. */
class ConvertCommandTest {
    @Test
    void anExactConversionExitsZeroAndPrintsStandardFcl() {
        Cli c = Cli.run("convert", "examples/jfuzzylogic/fan.fcl");
        assertEquals(0, c.exitCode(), c.err());
        assertTrue(c.out().startsWith("FUNCTION_BLOCK fan\n"), c.out());
        assertTrue(c.out().contains("    TERM warm := (10, 0) (20, 1) (30, 0);\n"), c.out());
        assertTrue(c.out().contains("    METHOD : CoG;\n"), c.out());
        assertTrue(c.err().contains("fclcert: converted from jFuzzyLogic: 10 non-standard constructs, 10 exact,"
                + " 0 approximated, 0 not expressible"), c.err());
        assertTrue(c.errLines().get(0).startsWith("fclcert: examples/jfuzzylogic/fan.fcl: read as jFuzzyLogic: "),
                c.err());
    }

    @Test
    void aLossyConversionExitsOneUnlessAllowed() {
        Cli refused = Cli.run("convert", "--from", "fuzzylite",
                "src/test/resources/org/fclcert/syntax/dialect/fuzzylite/obstacle.fcl");
        assertEquals(1, refused.exitCode(), refused.err());
        assertEquals("", refused.out());
        assertTrue(refused.err().contains("obstacle.fcl:47:15: error FCL-X001: O-HEDGE-VERY is not expressible"),
                refused.err());
        Cli allowed = Cli.run("convert", "--from", "fuzzylite", "--allow-lossy",
                "src/test/resources/org/fclcert/syntax/dialect/fuzzylite/obstacle.fcl");
        assertEquals(0, allowed.exitCode(), allowed.err());
        assertTrue(allowed.err().contains("obstacle.fcl:47:15: warning FCL-X001: O-HEDGE-VERY"), allowed.err());
        assertTrue(allowed.out().contains("METHOD : CoGS;"), allowed.out());
    }

    /** Standard input ('-') goes by {@code <stdin>} in every location and message, as in check. */
    @Test
    void standardInputIsNamedStdinInEveryMessage() throws Exception {
        byte[] lossy = Files.readAllBytes(Path.of("src/test/resources/org/fclcert/syntax/dialect/fuzzylite/obstacle.fcl"));
        Cli toStandard = SarifOutputTest.withStdin(lossy, "convert", "--from", "fuzzylite", "-");
        assertEquals(1, toStandard.exitCode(), toStandard.err());
        assertTrue(toStandard.err().contains("<stdin>:47:15: error FCL-X001: O-HEDGE-VERY is not expressible"),
                toStandard.err());
        assertTrue(toStandard.errLines().contains("fclcert: <stdin> not converted: standard FCL cannot say exactly what"
                + " it says; add --allow-lossy to write the nearest standard program anyway"), toStandard.err());

        byte[] weighted = Files.readAllBytes(Path.of("conformance/extension/E-WITH-VAR-001.fcl"));
        Cli toLibrary = SarifOutputTest.withStdin(weighted, "convert", "--to", "jfuzzylogic", "-");
        assertEquals(1, toLibrary.exitCode(), toLibrary.err());
        assertTrue(toLibrary.err().contains("<stdin>:29:17: error FCL-X101: jFuzzyLogic rejects initial values"),
                toLibrary.err());
        assertTrue(toLibrary.errLines().contains("fclcert: <stdin> not converted: jFuzzyLogic cannot say exactly what"
                + " it says; add --allow-lossy to write the nearest jFuzzyLogic program anyway"), toLibrary.err());

        for (Cli c : List.of(toStandard, toLibrary)) {
            assertTrue(c.errLines().stream().noneMatch(l -> l.startsWith("-:") || l.contains("fclcert: - ")
                    || l.contains(" - not ")), c.err());
        }
    }

    @Test
    void approximationsAskedForAreWrittenWithTheirBound(@TempDir Path dir) {
        Cli without = Cli.run("convert", "examples/jfuzzylogic/tipper.fcl");
        assertEquals(1, without.exitCode(), without.err());
        Path out = dir.resolve("tipper.fcl");
        Cli with = Cli.run("convert", "--approximate-points", "21", "--out", out.toString(),
                "examples/jfuzzylogic/tipper.fcl");
        assertEquals(0, with.exitCode(), with.err());
        assertEquals("", with.out());
        assertTrue(with.err().contains("tipper.fcl:17:5: warning FCL-X002: O-SHAPE-GAUSSIAN: approximated, largest"
                + " membership error at most "), with.err());
        assertTrue(with.err().contains("5 approximated, 0 not expressible"), with.err());
        assertTrue(Cli.read(out).startsWith("FUNCTION_BLOCK tipper\n"));
        Cli check = Cli.run("check", out.toString());
        assertEquals(0, check.exitCode(), check.out() + check.err());
    }

    @Test
    void badInputGetsLocatedErrorsAndNonZeroExits(@TempDir Path dir) throws Exception {
        Cli missing = Cli.run("convert", dir.resolve("nope.fcl").toString());
        assertEquals(2, missing.exitCode());
        assertTrue(missing.err().startsWith("fclcert: "), missing.err());

        Path broken = Cli.write(dir, "broken.fcl", "FUNCTION_BLOCK b\nFUZZIFY x\n  TERM a := Triangle 0 1;\n"
                + "END_FUZZIFY\nEND_FUNCTION_BLOCK\n");
        Cli errors = Cli.run("convert", "--from", "fuzzylite", broken.toString());
        assertEquals(1, errors.exitCode(), errors.err());
        assertTrue(errors.err().contains("broken.fcl:"), errors.err());
        assertTrue(errors.err().contains("has errors; not converted"), errors.err());
        assertTrue(!errors.err().contains("Exception"), errors.err());

        Cli usage = Cli.run("convert", "--approximate-points", "1", "examples/jfuzzylogic/tipper.fcl");
        assertEquals(2, usage.exitCode());
        // issue 18 item 12: 1000000 took 117 s, then exhausted the heap
        Cli huge = Cli.run("convert", "--approximate-points", "1000000", "examples/jfuzzylogic/tipper.fcl");
        assertEquals(2, huge.exitCode());
        assertEquals(List.of("fclcert: --approximate-points must be at most 10000 (got 1000000)"), huge.errLines());
        assertEquals("", huge.out());
        assertTrue(Files.exists(Path.of("examples/jfuzzylogic/tipper.fcl")));
    }

    @Test
    void featuresListsTheOpenLevelConstructsWithTheirLines() {
        Cli f = Cli.run("features", "--dialect", "fuzzylite", "examples/fuzzylite/parking.fcl");
        assertEquals(0, f.exitCode(), f.err());
        assertTrue(f.out().matches("(?s).*\\n  O-SHAPE-RECTANGLE +named shape: rectangle +at 34:3\\n.*"), f.out());
        assertTrue(f.out().matches("(?s).*\\n  O-HEDGE-ANY +'x is any': degree 1, no term +at 56:36\\n.*"), f.out());
        Cli j = Cli.run("features", "--dialect", "jfuzzylogic", "examples/jfuzzylogic/fan.fcl");
        assertTrue(j.out().matches("(?s).*\\n  O-METHOD-COGF +jFuzzyLogic's 'COGF', read as CoG +at 31:14\\n.*"),
                j.out());
        assertTrue(j.out().matches("(?s).*\\n  O-DECLARATION-RANGE .* at 7:5\\n.*"), j.out());
    }

    /**
     * No comment is lost unsaid: a standard program converted to standard FCL keeps its comments where they stood;
     * a library's text carries none, and the command says how many it left out.
     */
    @Test
    void commentsAreKeptOrTheirLossIsSaid() {
        Cli standard = Cli.run("convert", "--to", "strict", "examples/valve.fcl");
        assertEquals(0, standard.exitCode(), standard.err());
        assertTrue(standard.out().startsWith("(* The fuzzy function block of IEC 61131-7, 5.3 (Figure 7): a valve"),
                standard.out());
        assertFalse(standard.err().contains("comment"), standard.err());

        Cli library = Cli.run("convert", "--to", "fuzzylite", "examples/valve.fcl");
        assertEquals(0, library.exitCode(), library.err());
        assertFalse(library.out().contains("(*"), library.out());
        assertTrue(library.errLines().contains("fclcert: note: 1 comment of examples/valve.fcl not written: fclcert"
                + " writes no comments into fuzzylite's text"), library.err());
    }
}
