package org.fclcert.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Limits;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

/**
 * One small program per check code, each triggering exactly that code. The first line of every file
 * says what it expects: {@code (* expect: FCL-C002 25:17 -- why *)}.
 */
class NegativeProgramsTest {
    private static final Pattern EXPECT = Pattern.compile("\\(\\* expect: (FCL-[CW]\\d{3}) (\\d+):(\\d+) -- .*\\*\\)");

    static Stream<String> programs() throws IOException, URISyntaxException {
        Path dir = Path.of(NegativeProgramsTest.class.getResource("negative").toURI());
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".fcl")).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("programs")
    void triggersExactlyItsCodeAtTheExpectedPlace(String file) {
        String text = Programs.text("negative/" + file);
        Matcher m = EXPECT.matcher(text.lines().findFirst().orElse(""));
        assertTrue(m.matches(), "first line of " + file + " must state the expectation");
        Analysis analysis = Programs.analyze(file, text);
        // these minimal programs often leave inputs where no rule fires (FCL-W005), which is not what they test
        List<Diagnostic> found = analysis.diagnostics().stream()
                .filter(d -> m.group(1).equals("FCL-W005") || !d.code().equals("FCL-W005")).toList();
        assertEquals(1, found.size(), () -> file + ": " + found);
        Diagnostic d = found.get(0);
        assertEquals(m.group(1), d.code(), d::toString);
        assertEquals(Integer.parseInt(m.group(2)), d.location().line(), d::toString);
        assertEquals(Integer.parseInt(m.group(3)), d.location().column(), d::toString);
        assertEquals(d.isError(), analysis.program().isEmpty(), "program present iff no error");
        assertTrue(d.message().length() > 30, d::toString);
    }

    @Test
    void everyCheckCodeHasANegativeProgram() throws IOException, URISyntaxException {
        List<String> files = programs().toList();
        for (CheckRule rule : Checker.standardRules()) {
            if (rule.code().equals("FCL-C026")) {
                continue; // the strict reader rejects such text itself (see below); CheckerModelTest covers C026
            }
            if (rule.code().equals("FCL-C040") || rule.code().equals("FCL-C041")) {
                continue; // named shapes come only from dialect readers: LibraryDialectReadersTest covers them
            }
            assertTrue(files.stream().anyMatch(f -> f.startsWith(rule.code())), "no negative program for " + rule.code());
        }
    }

    /** The base program of the negative cases with a third rule nesting {@code temp IS hot} in parentheses. */
    private static String nestedProgram(int depth) {
        String base = Programs.text("negative/FCL-C001.fcl");
        String rule3 = "    RULE 3 : IF " + "(".repeat(depth) + "temp IS hot" + ")".repeat(depth) + " THEN valve IS closed;";
        return base.replace("    RULE 3 : IF tmp IS hot THEN valve IS closed;", rule3);
    }

    @Test
    void parenthesesNestedToTheLimitAreAccepted() {
        Analysis analysis = Programs.analyze("nest.fcl", nestedProgram(Limits.MAX_NESTING_DEPTH));
        assertEquals(List.of(), analysis.diagnostics());
    }

    @Test
    void beyondTheLimitTheStrictReaderRejectsTheNestingItself() {
        // the strict reader refuses deeper nesting before parsing (FCL-S008), so FCL-C026 guards programs that
        // other readers build; CheckerModelTest exercises it on a hand-built model
        Analysis analysis = Programs.analyze("nest.fcl", nestedProgram(Limits.MAX_NESTING_DEPTH + 1));
        assertTrue(analysis.program().isEmpty());
        assertEquals(List.of("FCL-S008"), analysis.diagnostics().stream().map(Diagnostic::code).toList());
    }
}
