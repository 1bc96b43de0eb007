package org.fclcert.syntax;

import static org.fclcert.syntax.StrictReaderTest.minimal;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Stream;
import org.fclcert.model.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Each kind of mistake gets its code, at the right place, with a sentence a person understands. */
class SyntaxDiagnosticsTest {
    private final StrictReader reader = new StrictReader();

    private List<Diagnostic> diagnostics(String text) {
        ReadResult r = reader.read("t.fcl", text);
        assertEquals(r.hasErrors(), r.program().isEmpty(), "program present iff no error");
        return r.diagnostics();
    }

    /** "CODE@line:col" for every diagnostic, in order. */
    private List<String> codes(String text) {
        return diagnostics(text).stream()
                .map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList();
    }

    private Diagnostic only(String text) {
        List<Diagnostic> all = diagnostics(text);
        assertEquals(1, all.size(), () -> all.toString());
        return all.get(0);
    }

    private static String fb(String body) {
        return "FUNCTION_BLOCK f\n" + body + "\nEND_FUNCTION_BLOCK\n";
    }

    static Stream<Arguments> mistakes() {
        // line 7 is the rule line in minimal(...); columns counted by hand from the text
        return Stream.of(
                Arguments.of(fb("VAR_INPUT x : REAL; $ END_VAR"), "FCL-S001@2:21"),
                Arguments.of(fb("VAR_INPUT x : REAL; END_VAR (* open"), "FCL-S002@2:29"),
                Arguments.of(fb("VAR_INPUT a__b : REAL; END_VAR"), "FCL-S003@2:11"),
                Arguments.of(fb("VAR_INPUT speed_ : REAL; END_VAR"), "FCL-S003@2:11"),
                Arguments.of(fb("VAR_INPUT x : REAL := .5; END_VAR"), "FCL-S004@2:23"),
                Arguments.of(fb("VAR_INPUT x : REAL := 5.; END_VAR"), "FCL-S004@2:23"),
                Arguments.of(fb("VAR_INPUT x : REAL := 1E5; END_VAR"), "FCL-S004@2:23"),
                Arguments.of(fb("VAR_INPUT x : REAL := 1__000; END_VAR"), "FCL-S004@2:23"),
                Arguments.of(fb("VAR_INPUT x : INT := 2#1012; END_VAR"), "FCL-S004@2:22"),
                Arguments.of(fb("VAR_INPUT x : INT := 7#12; END_VAR"), "FCL-S004@2:22"),
                Arguments.of("VAR_INPUT x : REAL; END_VAR", "FCL-S006@1:1"),
                Arguments.of(fb("") + "junk", "FCL-S006@4:1"),
                Arguments.of(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM max := 1; END_FUZZIFY"), "FCL-S007@3:16"),
                Arguments.of(fb("VAR_INPUT IF : REAL; END_VAR"), "FCL-S007@2:11"),
                Arguments.of(fb("VAR_INPUT x : BOOL; END_VAR"), "FCL-S009@2:15"),
                Arguments.of(fb("VAR x : REAL; END_VAR\nVAR_INPUT y : REAL; END_VAR"), "FCL-S010@3:1"),
                Arguments.of(fb("VAR_INPUT x : REAL = 1; END_VAR"), "FCL-S011@2:20"),
                Arguments.of(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x x := 1; END_FUZZIFY"), "FCL-S012@3:11"),
                Arguments.of(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y METHOD: CoGS; TERM a := 1; END_DEFUZZIFY"),
                        "FCL-S013@3:27"),
                Arguments.of(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM a := (0, 1) (1, 0) END_FUZZIFY"),
                        "FCL-S014@3:35"),
                Arguments.of(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM a := (0 1) (1, 0); END_FUZZIFY"),
                        "FCL-S015@3:24"),
                Arguments.of(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y RANGE (0 , 1); END_DEFUZZIFY"),
                        "FCL-S016@3:22"),
                Arguments.of(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y METHOD: MoM; END_DEFUZZIFY"), "FCL-S017@3:21"),
                Arguments.of(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y DEFAULT := ; END_DEFUZZIFY"), "FCL-S018@3:24"),
                Arguments.of(minimal("ACT : MIN;"), "FCL-S019@7:1"),
                Arguments.of(fb("RULEBLOCK r AND : ASUM; END_RULEBLOCK"), "FCL-S020@2:19"),
                Arguments.of(fb("RULEBLOCK r ACT : MAX; END_RULEBLOCK"), "FCL-S021@2:19"),
                Arguments.of(fb("RULEBLOCK r ACCU : SUM; END_RULEBLOCK"), "FCL-S022@2:20"),
                Arguments.of(minimal("RULE 1 IF x IS a THEN y IS b;"), "FCL-S023@7:8"),
                Arguments.of(minimal("RULE 1 : IF x IS a y IS b;"), "FCL-S024@7:20"),
                Arguments.of(minimal("RULE 1 : IF x = a THEN y IS b;"), "FCL-S025@7:15"),
                Arguments.of(minimal("RULE 1 : IF NOT NOT x IS a THEN y IS b;"), "FCL-S026@7:17"),
                Arguments.of(minimal("RULE 1 : IF x IS a THEN y IS ;"), "FCL-S027@7:30"),
                Arguments.of(minimal("RULE 1 : IF x IS a THEN y IS b AND y IS b;"), "FCL-S028@7:32"),
                Arguments.of(minimal("RULE 1 : IF x IS a THEN y IS b WITH ;"), "FCL-S029@7:37"),
                Arguments.of(fb("OPTIONS x"), "FCL-S030@3:1"),
                Arguments.of(minimal("RULE1 : IF x IS a THEN y IS b;"), "FCL-S031@7:1"),
                Arguments.of(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y METHOD: CoG; METHOD: CoA; END_DEFUZZIFY"),
                        "FCL-S032@3:26"),
                Arguments.of(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y TERM a := 1; END_FUZZIFY"), "FCL-S033@3:26"),
                Arguments.of("FUNCTION_BLOCK\nVAR_INPUT x : REAL; END_VAR\nEND_FUNCTION_BLOCK", "FCL-S034@2:1"),
                Arguments.of("FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\n", "FCL-S035@3:1"));
    }

    @ParameterizedTest(name = "{1}")
    @MethodSource("mistakes")
    void eachKindOfMistakeHasItsCodeAndPlace(String text, String expected) {
        assertEquals(List.of(expected), codes(text));
    }

    @Test
    void messagesNameWhatWasExpectedAndTheClause() {
        assertEquals("expected ':=' or ';' after 'REAL' (5.2.1), found '='",
                only(fb("VAR_INPUT x : REAL = 1; END_VAR")).message());
        assertEquals("expected 'THEN' after the condition (5.2.4), found 'y'",
                only(minimal("RULE 1 : IF x IS a y IS b;")).message());
        assertEquals("expected ',' after '0' (5.2.2), found '1'",
                only(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM a := (0 1) (1, 0); END_FUZZIFY")).message());
        assertEquals("expected a variable name or a number after 'WITH' (5.2.4), found ';'",
                only(minimal("RULE 1 : IF x IS a THEN y IS b WITH ;")).message());
        assertEquals("expected a variable name, 'NOT' or '(' after 'OR' (5.2.4), found 'THEN'",
                only(minimal("RULE 1 : IF x IS a OR THEN y IS b;")).message());
        assertEquals("the text ends inside the FUZZIFY block that starts at line 3: expected 'END_FUZZIFY' or 'TERM'",
                only("FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\nFUZZIFY x\n").message());
        assertEquals("'1E5' is not a valid real literal: a real literal needs a decimal point before the exponent"
                + " (write 1.0E5)", only(fb("VAR_INPUT x : REAL := 1E5; END_VAR")).message());
        assertEquals("'.5' is not a valid real literal: IEC 61131-3 requires a digit before the decimal point"
                + " (write 0.5)", only(fb("VAR_INPUT x : REAL := .5; END_VAR")).message());
        assertEquals("'speed_' is not a valid identifier: an identifier cannot end with '_' (IEC 61131-3 B.1.1)",
                only(fb("VAR_INPUT speed_ : REAL; END_VAR")).message());
        assertEquals("'a__b' is not a valid identifier: two underscores in a row are not allowed (IEC 61131-3 B.1.1)",
                only(fb("VAR_INPUT a__b : REAL; END_VAR")).message());
    }

    @Test
    void otherDialectsMistakesGetAHint() {
        assertEquals("expected ';' after the term's membership function (5.2.2), found '0'; named shapes such as"
                + " 'Triangle' are not FCL: a membership function is a singleton value or points (x, degree) (5.2.2)",
                only(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM a := Triangle 0 1 2; END_FUZZIFY")).message());
        assertEquals("expected 'END_DEFUZZIFY', 'TERM', 'RANGE', 'METHOD' or 'DEFAULT' after ';' (5.2.3), found 'ACCU';"
                + " ACCU and ACT belong in a RULEBLOCK (5.2.4)",
                only(fb("VAR_OUTPUT y : REAL; END_VAR\nDEFUZZIFY y TERM a := 1; ACCU : MAX; END_DEFUZZIFY")).message());
        assertEquals("unexpected character '/': it is not part of FCL; comments are written (* ... *)",
                diagnostics(fb("VAR_INPUT x : REAL; // input\nEND_VAR")).get(0).message());
    }

    @Test
    void commentsMayStandWhereverWhiteSpaceMay() {
        String text = "(*a*)FUNCTION_BLOCK(*b*)f(*c*)VAR_INPUT(*d*)x(*e*):(*f*)REAL(*g*);(*h*)END_VAR\n"
                + "VAR_OUTPUT y : REAL; END_VAR\n"
                + "FUZZIFY x TERM(*i*)a(*j*):=(*k*)((*l*)0(*m*),(*n*)0(*o*))(*p*)(1,1)(*q*);END_FUZZIFY\n"
                + "DEFUZZIFY y TERM b := 1; METHOD(*r*):(*s*)CoGS; DEFAULT := 0; END_DEFUZZIFY\n"
                + "RULEBLOCK r AND : MIN; ACCU : MAX;\n"
                + "RULE(*t*)1(*u*):(*v*)IF(*w*)x(*x*)IS(*y*)a(*z*)THEN(**)y(*1*)IS(*2*)b(*3*);\n"
                + "END_RULEBLOCK END_FUNCTION_BLOCK(*end*)";
        assertEquals(List.of(), codes(text));
    }

    @Test
    void isNotInAConclusionIsAnError() {
        assertEquals("FCL-S027@7:30", codes(minimal("RULE 1 : IF x IS a THEN y IS NOT b;")).get(0));
    }

    @Test
    void reservedKeywordsCannotNameAnything() {
        assertEquals("'MAX' is a reserved keyword (Table 7) and cannot name a term",
                only(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM max := 1; END_FUZZIFY")).message());
        assertEquals("'RANGE' is a reserved keyword (Table 7) and cannot name a variable",
                only(fb("VAR_INPUT Range : REAL; END_VAR")).message());
        assertEquals("'REAL' is a reserved keyword (an IEC 61131-3 data type) and cannot name a function block",
                only("FUNCTION_BLOCK real\nEND_FUNCTION_BLOCK").message());
        assertEquals("'CoGS' is a reserved keyword (Table 7) and cannot name a rule block",
                only(fb("RULEBLOCK cogs END_RULEBLOCK")).message());
        assertEquals("'IS' is a reserved keyword (Table 7) and cannot name a variable",
                only(fb("VAR_INPUT IS : REAL; END_VAR")).message());
        assertEquals("'AND' is a reserved keyword (Table 7) and cannot name a term",
                only(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM and := 1; END_FUZZIFY")).message());
        assertEquals("'NC' is a reserved keyword (Table 7) and cannot name a term",
                only(minimal("RULE 1 : IF x IS nc THEN y IS b;")).message());
        assertEquals("'MIN' is a reserved keyword (Table 7) and cannot name a variable",
                only(minimal("RULE 1 : IF x IS a THEN y IS b WITH min;")).message());
        assertEquals("'OPTIONS' is a reserved keyword (Table 7) and cannot name a variable",
                only(fb("VAR_INPUT options : REAL; END_VAR")).message());
        assertEquals("'TERM' is a reserved keyword (Table 7) and cannot name a term",
                only(fb("VAR_INPUT x : REAL; END_VAR\nFUZZIFY x TERM term := 1; END_FUZZIFY")).message());
        // a structural keyword where a name is missing is reported as what is missing
        assertEquals("expected a variable name or 'END_VAR' after ';' (5.2.1), found 'FUZZIFY'",
                only(fb("VAR_INPUT x : REAL;\nFUZZIFY x TERM a := 1; END_FUZZIFY")).message());
        // the same words are fine as parts of identifiers, and identifiers may start with one '_'
        assertEquals(List.of(), codes(fb("VAR_INPUT max_speed, _range, cogs1, real_value : REAL; END_VAR")));
    }

    @Test
    void identifiersAndKeywordsAreCaseInsensitive() {
        String text = "function_block F\nvar_input X : real; end_var\nvar_output Y : Real; end_var\n"
                + "fuzzify x term A := (0, 0) (1, 1); end_fuzzify\n"
                + "defuzzify y term B := 1; method : COGS; default := nc; end_defuzzify\n"
                + "ruleblock R and : min; accu : max; rule 1 : if x is a then y is b; end_ruleblock\n"
                + "end_function_block\n";
        assertEquals(List.of(), codes(text));
    }

    @Test
    void annexDGetsClearErrorsAtEachOfItsMistakes() {
        // Figure D.4 (the FUNCTION_BLOCK): its color_type is a STRUCT, RULE1: has no space,
        // 'color = brown' is not a subcondition and AND separates two subconclusions
        List<Diagnostic> all = diagnostics(FclTestPrograms.text("annexD_oven.fcl"));
        assertEquals(List.of("FCL-S009@4:13", "FCL-S031@37:5", "FCL-S025@37:44", "FCL-S028@38:9", "FCL-S031@39:5",
                "FCL-S031@40:5", "FCL-S031@41:5", "FCL-S025@41:44", "FCL-S031@42:5", "FCL-S025@42:44"),
                all.stream().map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList());
        assertEquals("'=' is not FCL: a subcondition is 'variable IS term' or a bare variable (5.2.4)",
                all.get(2).message());
        assertEquals("subconclusions are separated by ',' (5.2.4), not AND", all.get(3).message());
        assertEquals("'RULE1' is read as one name; a rule starts with the keyword RULE, a space and its number:"
                + " write 'RULE 1:' (5.2.4)", all.get(1).message());
        assertTrue(all.get(0).message().startsWith("'color_type' is not an elementary numeric data type"));
    }

    @Test
    void annexDWithItsTypeDeclarationStopsAtTheFirstNonFclLine() {
        String text = "TYPE\nSTRUCT color_type\n    brown: REAL;\nEND_STRUCT\nEND_TYPE\n\n"
                + FclTestPrograms.text("annexD_oven.fcl");
        List<Diagnostic> all = diagnostics(text);
        assertEquals("FCL-S006@1:1", all.get(0).code() + "@" + all.get(0).location().line() + ":"
                + all.get(0).location().column());
    }

    @Test
    void doubleNotIsAnErrorButNotOfAParenthesisIsFine() {
        assertEquals("FCL-S026", only(minimal("RULE 1 : IF NOT NOT x IS a THEN y IS b;")).code());
        assertEquals(List.of(), codes(minimal("RULE 1 : IF NOT (NOT x IS a) THEN y IS b;")));
        assertEquals(List.of(), codes(minimal("RULE 1 : IF NOT x IS NOT a THEN y IS b;")));
    }

    @Test
    void pointsMaySeparateWithCommasOrWhiteSpaceAndMixBoth() {
        assertEquals(List.of(), codes(fb("VAR_INPUT x : REAL; END_VAR\n"
                + "FUZZIFY x TERM a := (0, 0), (1, 1) (2, 0); TERM b := (0,1)(2,0); END_FUZZIFY")));
    }

    @Test
    void theFirstErrorDoesNotCascade() {
        // a missing ';' and a missing THEN in one rule: one report for the rule, the next rules still read
        String text = minimal("RULE 1 : IF x IS a y IS b\nRULE 2 : IF x IS a THEN y IS b;\nRULE 3 : IF x IS THEN y IS b;");
        assertEquals(List.of("FCL-S024@7:20", "FCL-S024@9:18"), codes(text));
    }

    /**
     * After the parser has recovered from a first error, the rules, items and declarations it completes are dropped
     * as they complete (ModelBuilder.buildWhile: the tree is never built then); a later message still names such a
     * part by what it is: rule 3 and the VAR section below were completed after the recovery at rule 1.
     */
    @Test
    void laterMessagesNamePartsCompletedAfterARecovery() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM low := (0, 1) (10, 0); END_FUZZIFY
                DEFUZZIFY y TERM a := 2; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r ACCU : MAX;
                RULE 1 : IF x IS low THEN y IS a
                RULE 2 : IF x IS low THEN y IS a;
                RULE 3 : IF x IS low THEN y IS a; 7
                END_RULEBLOCK
                VAR x2 : REAL; END_VAR q
                END_FUNCTION_BLOCK
                """;
        List<Diagnostic> all = diagnostics(text);
        assertEquals(List.of("FCL-S027@7:33", "FCL-S019@9:35", "FCL-S034@11:24"), codes(text));
        assertEquals("expected 'END_RULEBLOCK', 'AND', 'OR', 'ACT', 'ACCU' or 'RULE' after the rule (5.2.4),"
                + " found '7'", all.get(1).message());
        assertTrue(all.get(2).message().endsWith(
                "or END_FUNCTION_BLOCK after the VAR section (5.2.1, 5.4), found 'q'"), all.get(2).message());
    }

    @Test
    void errorsAreCappedWithOneSummary() {
        StringBuilder body = new StringBuilder("VAR_INPUT\n");
        for (int i = 0; i < 40; i++) {
            body.append("x").append(i).append(" : BOOL;\n");
        }
        body.append("END_VAR");
        List<Diagnostic> all = diagnostics(fb(body.toString()));
        assertEquals(ReaderDiagnostics.MAX_ERRORS + 1, all.size());
        Diagnostic last = all.get(all.size() - 1);
        assertEquals("FCL-S099", last.code());
        assertEquals("too many syntax errors: 15 more not reported; fix the ones above first", last.message());
    }
}
