package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.fclcert.model.Limits;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A condition nested {@link Limits#MAX_NESTING_DEPTH} deep is legal FCL: every command must read, check,
 * evaluate and write it (they run on {@code Main}'s large stack), never end in an internal error (exit 3).
 */
class DeepNestingTest {
    @TempDir
    Path dir;

    /** The first condition wrapped {@code depth} times in {@code NOT (c AND b IS hi)}. */
    static String deepProgram(int depth) {
        String c = "a IS hi";
        for (int i = 0; i < depth; i++) {
            c = "NOT (" + c + " AND b IS hi)";
        }
        return """
                FUNCTION_BLOCK deep
                VAR_INPUT a : REAL; b : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY a TERM hi := (0, 0) (10, 1); END_FUZZIFY
                FUZZIFY b TERM hi := (0, 0) (10, 1); END_FUZZIFY
                DEFUZZIFY y TERM high := 100; TERM low := 0; METHOD : COGS; DEFAULT := 50; END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    ACCU : MAX;
                    RULE 1 : IF %s THEN y IS high;
                    RULE 2 : IF a IS hi THEN y IS low;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """.formatted(c);
    }

    @Test
    void everyCommandHandlesTheDeepestLegalNesting() {
        Path file = Cli.write(dir, "deep.fcl", deepProgram(Limits.MAX_NESTING_DEPTH));
        String f = file.toString();
        Cli check = Cli.run("check", f);
        assertEquals(0, check.exitCode(), check.err());
        // a=3, b=4: hi(a) = .3, hi(b) = .4; c1 = 1 - min(.3, .4) = .7, then c(k+1) = 1 - min(c(k), .4) = .6 for
        // every further level: rule 1 fires at .6 on 100, rule 2 at .3 on 0: (.6*100 + .3*0) / .9 = 66.666…
        Cli eval = Cli.run("eval", f, "--in", "a=3", "--in", "b=4");
        assertEquals(0, eval.exitCode(), eval.err());
        assertTrue(eval.out().startsWith("y=66.6666666666666"), eval.out());
        for (List<String> command : List.of(List.of("fmt", f), List.of("convert", f),
                List.of("features", f))) {
            Cli run = Cli.run(command.toArray(String[]::new));
            assertFalse(run.exitCode() == 3 || run.err().contains("internal error"), command + ": " + run.err());
        }
        Cli ffll = Cli.run("check", "--dialect", "ffll", f);
        assertFalse(ffll.exitCode() == 3 || ffll.err().contains("FCL-S999") || ffll.out().contains("FCL-S999")
                || ffll.err().contains("internal error"), ffll.err());
    }
}
