package org.fclcert.check;

import static org.fclcert.check.ModelFixtures.at;
import static org.fclcert.check.ModelFixtures.is;
import static org.fclcert.check.ModelFixtures.rule;
import static org.fclcert.check.ModelFixtures.tempValve;
import static org.fclcert.check.ModelFixtures.validRules;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.SyntaxCode;
import org.junit.jupiter.api.Test;

/** How Analysis combines a reader's result with the checks, with readers that return fixed results. */
class AnalysisTest {
    private static FclReader returning(Optional<Program> program, Diagnostic... diagnostics) {
        return (name, text) -> new ReadResult(program, List.of(diagnostics));
    }

    private static List<String> summary(Analysis a) {
        return a.diagnostics().stream().map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column())
                .toList();
    }

    @Test
    void aSyntaxErrorMeansNoProgramAndNoChecks() {
        Diagnostic syntax = Diagnostic.error(at(3, 1), SyntaxCode.UNEXPECTED_CHARACTER, "expected ';'");
        Analysis a = Analysis.analyze(returning(Optional.empty(), syntax), "m.fcl", "");
        assertTrue(a.program().isEmpty());
        assertEquals(List.of(syntax), a.diagnostics());
    }

    @Test
    void aCleanProgramIsPresentWithNoDiagnostics() {
        Analysis a = Analysis.analyze(returning(Optional.of(tempValve(validRules()))), "m.fcl", "");
        assertTrue(a.program().isPresent());
        assertEquals(List.of(), a.diagnostics());
    }

    @Test
    void readerWarningsAndCheckWarningsKeepTheProgram() {
        List<Rule> rules = List.of(rule("1", is("temp", "cold", 21), "valve", "open", 21));
        Diagnostic readerWarning = Diagnostic.warning(at(21, 5), SyntaxCode.RULE_NAMED_BY_IDENTIFIER,
                "rule named by an identifier");
        Analysis a = Analysis.analyze(returning(Optional.of(tempValve(rules)), readerWarning), "m.fcl", "");
        assertTrue(a.program().isPresent());
        // 'hot' (line 10) and 'closed' (line 13) are never used; with only 'cold' ((3, 1) (27, 0)) no rule fires
        // from 27 up (FCL-W005 at the rule block, line 18)
        assertEquals(List.of("FCL-W001@10:5", "FCL-W001@13:5", "FCL-W005@18:1", "FCL-W104@21:5"), summary(a));
    }

    @Test
    void aCheckErrorDropsTheProgramAndReaderDiagnosticsComeFirstAtTheSamePosition() {
        List<Rule> rules = new ArrayList<>(validRules());
        // rule 3 at line 23 names an undefined term; the subcondition is at column 17
        rules.add(rule("3", is("temp", "warm", 23), "valve", "closed", 23));
        Diagnostic readerWarning = Diagnostic.warning(at(23, 17), SyntaxCode.RULE_NAMED_BY_IDENTIFIER,
                "a reader remark at the same place");
        Analysis a = Analysis.analyze(returning(Optional.of(tempValve(rules)), readerWarning), "m.fcl", "");
        assertTrue(a.program().isEmpty());
        assertEquals(List.of("FCL-W104@23:17", "FCL-C002@23:17"), summary(a));
    }
}
