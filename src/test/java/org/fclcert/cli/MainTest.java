package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.Callable;
import org.fclcert.model.Toolkit;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import picocli.CommandLine.Command;

class MainTest {
    @Test
    void versionNamesTheBuild() {
        Cli r = Cli.run("--version");
        assertEquals(0, r.exitCode());
        assertFalse(Toolkit.version().equals("unknown") || Toolkit.version().contains("${"), Toolkit.version());
        assertEquals("fclcert " + Toolkit.version(), r.out().strip());
    }

    @ParameterizedTest
    @ValueSource(strings = {"check", "features", "fmt"})
    void everyCommandHasHelpWithExitCodes(String command) {
        Cli r = Cli.run(command, "--help");
        assertEquals(0, r.exitCode());
        assertTrue(r.out().startsWith("Usage: fclcert " + command + " "), r.out());
        assertTrue(r.out().contains("Exit codes:"), r.out());
        assertTrue(r.out().contains("  3   internal error in fclcert"), r.out());
    }

    @Test
    void noCommandIsAUsageErrorThatPrintsTheUsage() {
        Cli r = Cli.run();
        assertEquals(2, r.exitCode());
        assertEquals("", r.out());
        assertTrue(r.err().startsWith("Usage: fclcert "), r.err());
    }

    @Test
    void anInvalidOptionValueIsOneLineAndAHintNotTheWholeHelp() {
        Cli r = Cli.run("check", "--dialect", "foo", "x.fcl");
        assertEquals(2, r.exitCode());
        assertEquals(List.of("Invalid value for option '--dialect': expected one of [strict, ffll, jfuzzylogic,"
                + " fuzzylite, fll, fis, auto] (case-insensitive) but was 'foo'",
                "Try 'fclcert check --help' for more information."), r.err().lines().toList());
    }

    @Test
    void unknownCommandIsAUsageError() {
        Cli r = Cli.run("certifyy");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().startsWith("Unmatched argument at index 0: 'certifyy'"), r.err());
    }

    @Test
    void unknownOptionIsAUsageError() {
        Cli r = Cli.run("check", "--colour", "x.fcl");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().startsWith("Unknown option: '--colour'"), r.err());
    }

    @Command(name = "boom")
    static final class Boom implements Callable<Integer> {
        @Override
        public Integer call() {
            throw new IllegalStateException("the writer met a NaN");
        }
    }

    @Command(name = "overflow")
    static final class Overflow implements Callable<Integer> {
        @Override
        public Integer call() {
            throw new StackOverflowError();
        }
    }

    @Test
    void anErrorSuchAsStackOverflowIsOneLineAndExitCodeThree() {
        Cli r = Cli.runWith("overflow", new Overflow(), "overflow");
        assertEquals(3, r.exitCode());
        assertEquals(java.util.List.of("fclcert: internal error: java.lang.StackOverflowError"), r.errLines());
    }

    @Test
    void anUnexpectedExceptionIsOneLineAndExitCodeThree() {
        Cli r = Cli.runWith("boom", new Boom(), "boom");
        assertEquals(3, r.exitCode());
        assertEquals("", r.out());
        assertEquals(java.util.List.of("fclcert: internal error: the writer met a NaN"), r.errLines());
    }
}
