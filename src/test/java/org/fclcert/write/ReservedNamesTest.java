package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.junit.jupiter.api.Test;

/**
 * No writer of standard FCL emits a keyword as a name: a name a dialect reader gave (an unnamed FFLL block is
 * {@code function_block}; jFuzzyLogic takes {@code BSUM} as a rule's name) is written with {@code _1} at every use,
 * and the conversion lists the renaming as an exact finding. Before issue 28 both ended in "internal error: the
 * converted program is not valid standard FCL".
 */
class ReservedNamesTest {
    private static Program read(Dialect d, String text) {
        Analysis a = Analysis.analyze(DialectReaders.reader(d), "t.fcl", text);
        return a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
    }

    @Test
    void anUnnamedFfllBlockConvertsUnderAName() {
        String ffll = """
                FUNCTION_BLOCK
                VAR_INPUT
                \tx\tREAL; (* RANGE(0 .. 10) *)
                END_VAR
                VAR_OUTPUT
                \ty\tREAL; (* RANGE(0 .. 100) *)
                END_VAR
                FUZZIFY x
                \tTERM lo := (0, 0) (0, 1) (10, 0) ;
                END_FUZZIFY
                FUZZIFY y
                \tTERM on := 100;
                END_FUZZIFY
                RULEBLOCK first
                \tAND:MIN;
                \tACCU:MAX;
                \tRULE 0: IF (x IS lo) THEN (y IS on);
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        StandardConversion.Result r = new StandardConversion().convert(read(Dialect.FFLL, ffll));
        String text = new CanonicalWriter().write(r.program());
        assertTrue(text.startsWith("FUNCTION_BLOCK function_block_1\n"), text);
        List<String> notes = r.findings().stream().filter(f -> f.construct().equals("reserved name"))
                .map(StandardConversion.Finding::message).toList();
        assertEquals(List.of("'function_block' is a keyword of standard FCL (Table 7): written as 'function_block_1'"
                + " at every use"), notes);
        Analysis strict = Analysis.analyze(new StrictReader(), "c.fcl", text);
        assertTrue(strict.program().isPresent() && strict.diagnostics().stream().noneMatch(d -> d.code().startsWith(
                "FCL-S")), strict.diagnostics()::toString);
    }

    @Test
    void aRuleNamedByAKeywordIsRenamedEverywhereItIsWritten() {
        String jfl = """
                FUNCTION_BLOCK fan
                VAR_INPUT temp : REAL; END_VAR
                VAR_OUTPUT speed : REAL; END_VAR
                FUZZIFY temp TERM cold := trian 0 10 20; END_FUZZIFY
                DEFUZZIFY speed TERM slow := trian 0 25 50; METHOD : COG; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK rules
                    AND : MIN; ACT : MIN; ACCU : MAX;
                    RULE BSUM : IF temp IS cold THEN speed IS slow;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        StandardConversion.Result r = new StandardConversion().convert(read(Dialect.JFUZZYLOGIC, jfl));
        String text = new CanonicalWriter().write(r.program());
        assertTrue(text.contains("RULE BSUM_1 : IF temp IS cold THEN speed IS slow;"), text);
        assertTrue(r.exact(), r.findings().toString());
        Analysis strict = Analysis.analyze(new StrictReader(), "c.fcl", text);
        assertTrue(strict.program().isPresent() && strict.diagnostics().stream().noneMatch(d -> d.code().startsWith(
                "FCL-S")), strict.diagnostics()::toString);
    }
}
