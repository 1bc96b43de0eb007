package org.fclcert.syntax;

import static org.fclcert.syntax.StrictReaderTest.minimal;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.Severity;
import org.junit.jupiter.api.Test;

/** Constructs accepted only because the standard contradicts itself: read, with a warning (FCL-W1nn). */
class ReaderWarningsTest {
    private final StrictReader reader = new StrictReader();

    private ReadResult read(String text) {
        return reader.read("w.fcl", text);
    }

    /** The only diagnostic of an accepted program: a warning with this code at this line:column. */
    private Diagnostic onlyWarning(String text, String code, int line, int column) {
        ReadResult r = read(text);
        assertTrue(r.program().isPresent(), () -> r.diagnostics().toString());
        assertEquals(1, r.diagnostics().size(), () -> r.diagnostics().toString());
        Diagnostic d = r.diagnostics().get(0);
        assertEquals(Severity.WARNING, d.severity());
        assertEquals(code + "@" + line + ":" + column, d.code() + "@" + d.location().line() + ":" + d.location().column());
        return d;
    }

    private static String defuzzify(String items) {
        return "FUNCTION_BLOCK f\nVAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y\n" + items + "\nEND_DEFUZZIFY\nEND_FUNCTION_BLOCK\n";
    }

    @Test
    void rangeLastIsTheDraftOrder() {
        Diagnostic d = onlyWarning(defuzzify("TERM a := 1;\nMETHOD : CoG;\nDEFAULT := 0;\nRANGE (0 .. 10);"),
                "FCL-W101", 7, 1);
        assertTrue(d.message().contains("1996 draft"));
        Program p = read(defuzzify("TERM a := 1;\nMETHOD : CoG;\nDEFAULT := 0;\nRANGE (0 .. 10);")).program().get();
        assertEquals(10.0, p.functionBlocks().get(0).defuzzifications().get(0).range().get().max().value());
    }

    @Test
    void rangeFirstIsTheStandardOrderWithoutWarning() {
        assertEquals(List.of(), read(defuzzify("RANGE (0 .. 10);\nTERM a := 1;\nMETHOD : CoG;\nDEFAULT := 0;"))
                .diagnostics());
    }

    @Test
    void rangeInTheMiddleIsAnError() {
        ReadResult r = read(defuzzify("TERM a := 1;\nRANGE (0 .. 10);\nTERM b := 2;\nMETHOD : CoG;"));
        assertEquals(List.of("FCL-S013@5:1"), r.diagnostics().stream()
                .map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList());
        assertEquals("RANGE after TERM: a DEFUZZIFY block gives RANGE, then its TERMs, then METHOD, then DEFAULT (5.4)",
                r.diagnostics().get(0).message());
    }

    @Test
    void optionSpellingOf54() {
        String text = "FUNCTION_BLOCK f\nOPTION\n  speed := high;\nEND_OPTION\nEND_FUNCTION_BLOCK\n";
        ReadResult r = read(text);
        assertEquals(List.of("FCL-W102@2:1", "FCL-W102@4:1"), r.diagnostics().stream()
                .map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList());
        assertEquals("speed := high;", r.program().get().functionBlocks().get(0).options().get(0).content());
        assertEquals(List.of(), read(text.replace("OPTION\n", "OPTIONS\n").replace("END_OPTION\n", "END_OPTIONS\n"))
                .diagnostics());
    }

    @Test
    void optionsContentIsKeptVerbatimWhateverItHolds() {
        String content = "$weird \"chars\" .5 a__b RULE1: (* a comment *) ((( FUNCTION_BLOCK";
        ReadResult r = read("FUNCTION_BLOCK f\nOPTIONS " + content + "\nEND_OPTIONS\nEND_FUNCTION_BLOCK\n");
        assertEquals(List.of(), r.diagnostics());
        assertEquals(content, r.program().get().functionBlocks().get(0).options().get(0).content());
    }

    @Test
    void rangeWithAssignmentIsTheProseForm() {
        Diagnostic d = onlyWarning(defuzzify("RANGE := (0 .. 10);\nTERM a := 1;"), "FCL-W103", 4, 7);
        assertTrue(d.message().contains("5.4 production"));
    }

    @Test
    void ruleNamedByAnIdentifier() {
        String text = minimal("RULE warm_up : IF x IS a THEN y IS b;");
        onlyWarning(text, "FCL-W104", 7, 6);
        Rule rule = read(text).program().get().functionBlocks().get(0).ruleBlocks().get(0).rules().get(0);
        assertEquals("warm_up", rule.name());
        assertTrue(!rule.numbered());
    }

    @Test
    void withAfterTheLastOfSeveralSubconclusionsWeightsThatOneOnly() {
        String text = minimal("RULE 1 : IF x IS a THEN y, y IS b WITH 0.5;");
        onlyWarning(text, "FCL-W105", 7, 35);
        Rule rule = read(text).program().get().functionBlocks().get(0).ruleBlocks().get(0).rules().get(0);
        assertEquals(Optional.empty(), rule.conclusion().get(0).weight());
        assertEquals(0.5, ((org.fclcert.model.Literal) rule.conclusion().get(1).weight().get()).value());
        // WITH on a single subconclusion, or on a non-last one, is plain FCL
        assertEquals(List.of(), read(minimal("RULE 1 : IF x IS a THEN y IS b WITH 0.5;")).diagnostics());
        assertEquals(List.of(), read(minimal("RULE 1 : IF x IS a THEN y IS b WITH 0.5, y;")).diagnostics());
    }

    @Test
    void commentOpenerInsideACommentDoesNotNest() {
        // the first '*)' ends the comment, so ' still comment? *)' below would be FCL text: here it is not there
        String text = "FUNCTION_BLOCK f (* outer (* inner *)\nEND_FUNCTION_BLOCK\n";
        onlyWarning(text, "FCL-W106", 1, 18);
        // with a second '*)', the text after the first one is read as FCL and fails
        ReadResult r = read("FUNCTION_BLOCK f (* outer (* inner *) rest *)\nEND_FUNCTION_BLOCK\n");
        assertTrue(r.hasErrors());
    }

    @Test
    void manyWarningsOfOneCodeAreSummarised() {
        StringBuilder rules = new StringBuilder();
        for (int i = 0; i < 30; i++) {
            rules.append("RULE r").append(i).append(" : IF x IS a THEN y IS b;\n");
        }
        ReadResult r = read(minimal(rules.toString()));
        assertEquals(ReaderDiagnostics.MAX_WARNINGS_PER_CODE + 1, r.diagnostics().size());
        assertEquals("5 more FCL-W104 warning(s) like the ones above are not shown",
                r.diagnostics().get(r.diagnostics().size() - 1).message());
    }
}
