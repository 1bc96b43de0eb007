package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 18 item 10: jFuzzyLogic's grammar takes any of its numbers as a rule's label ({@code rule_name : ID | REAL},
 * REAL with an optional sign, fraction and exponent) and keeps the label as text; its released jar loads
 * {@code RULE 1.5}, {@code 1.0E2}, {@code -3} and {@code 1e309} and evaluates them like any rule. fclcert reads
 * them so too, with a located warning, and gives each the smallest rule number the block does not use, so that
 * fmt and convert write standard FCL that checks clean (they printed FCL failing check, and convert exited 3).
 */
class NumericRuleLabelTest {
    /** x = 0.25: lo 0.75 concludes a (10), hi 0.25 concludes b (20); CoGS = (0.75·10 + 0.25·20) / 1 = 12.5. */
    private static final String PROGRAM = """
            FUNCTION_BLOCK labels
            VAR_INPUT x : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY x
            TERM lo := (0,1) (1,0);
            TERM hi := (0,0) (1,1);
            END_FUZZIFY
            DEFUZZIFY y
            TERM a := 10;
            TERM b := 20;
            METHOD : COGS;
            DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK rb
            AND : MIN;
            ACT : MIN;
            ACCU : MAX;
            RULE 1.5 : IF x IS lo THEN y IS a;
            RULE 1 : IF x IS hi THEN y IS b;
            RULE -3 : IF x IS hi THEN y IS b;
            RULE 1e309 : IF x IS lo THEN y IS a;
            RULE 1.0E2 : IF x IS lo THEN y IS a;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    @TempDir
    Path dir;

    @Test
    void numericLabelsAreReadAsLabelsWithALocatedWarning() {
        Path file = Cli.write(dir, "labels.fcl", PROGRAM);
        Cli check = Cli.run("check", "--dialect", "jfuzzylogic", file.toString());
        assertEquals(0, check.exitCode(), check.out() + check.err());
        String all = check.out() + check.err();
        for (String at : List.of("labels.fcl:18:6: warning FCL-W308", "labels.fcl:20:6: warning FCL-W308",
                "labels.fcl:21:6: warning FCL-W308", "labels.fcl:22:6: warning FCL-W308")) {
            assertTrue(all.contains(at), at + " in " + all);
        }
        assertTrue(all.contains("('RULE 1.5')") && all.contains("read as RULE 2"), all);
        assertTrue(all.contains("('RULE -3')") && all.contains("read as RULE 3"), all);
        Cli eval = Cli.run("eval", "--dialect", "jfuzzylogic", file.toString(), "--in", "x=0.25");
        assertEquals(0, eval.exitCode(), eval.err());
        assertEquals("y=12.5", eval.out().strip());
    }

    @Test
    void fmtAndConvertWriteStandardFclThatChecksClean() {
        Path file = Cli.write(dir, "labels.fcl", PROGRAM);
        Cli fmt = Cli.run("fmt", "--dialect", "jfuzzylogic", file.toString());
        assertEquals(0, fmt.exitCode(), fmt.err());
        // the free numbers 2, 3, 4, 5 in order; RULE 1 keeps its number
        assertTrue(fmt.out().contains("""
                    RULE 2 : IF x IS lo THEN y IS a;
                    RULE 1 : IF x IS hi THEN y IS b;
                    RULE 3 : IF x IS hi THEN y IS b;
                    RULE 4 : IF x IS lo THEN y IS a;
                    RULE 5 : IF x IS lo THEN y IS a;
                """), fmt.out());
        Path written = Cli.write(dir, "fmt.fcl", fmt.out());
        Cli check = Cli.run("check", written.toString());
        assertEquals(0, check.exitCode(), check.out() + check.err());
        assertTrue((check.out() + check.err()).contains("0 errors, 0 warnings"), check.out() + check.err());
        Cli eval = Cli.run("eval", written.toString(), "--in", "x=0.25");
        assertEquals("y=12.5", eval.out().strip(), eval.err());

        for (String to : List.of("strict", "ffll", "jfuzzylogic", "fuzzylite")) {
            Cli convert = Cli.run("convert", "--from", "jfuzzylogic", "--to", to, file.toString());
            assertEquals(0, convert.exitCode(), to + ": " + convert.err());
            assertFalse(convert.err().contains("internal error"), convert.err());
        }
    }

    @Test
    void aGaussTermOnAnInputWithoutRangeIsALocatedRefusalNotAnInternalError() {
        Path file = Cli.write(dir, "gauss.fcl", PROGRAM.replace("TERM lo := (0,1) (1,0);", "TERM lo := gauss 0 1;"));
        Cli convert = Cli.run("convert", "--from", "jfuzzylogic", "--approximate-points", "10", file.toString());
        assertEquals(1, convert.exitCode(), convert.err());
        assertTrue(convert.err().contains("gauss.fcl:5:1: error FCL-X001: O-SHAPE-GAUSSIAN is not expressible"),
                convert.err());
        assertTrue(convert.err().contains("input x has no finite RANGE to approximate over"), convert.err());
        Cli fmt = Cli.run("fmt", "--dialect", "jfuzzylogic", file.toString());
        assertEquals(1, fmt.exitCode(), fmt.err());
        assertEquals("", fmt.out());
        Cli lossy = Cli.run("convert", "--from", "jfuzzylogic", "--allow-lossy", file.toString());
        assertEquals(0, lossy.exitCode(), lossy.err());
        Cli check = Cli.run("check", Cli.write(dir, "lossy.fcl", lossy.out()).toString());
        assertEquals(0, check.exitCode(), check.out() + check.err());
    }
}
