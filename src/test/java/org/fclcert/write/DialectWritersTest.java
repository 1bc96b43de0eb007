package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.junit.jupiter.api.Test;

/** The library writers on small programs whose written text and values are worked out by hand. */
class DialectWritersTest {

    private static Program standard(String text) {
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "p.fcl", text);
        assertFalse(a.hasErrors(), a.diagnostics().toString());
        return a.program().orElseThrow();
    }

    private static final String TWO_WEIGHTS = """
            FUNCTION_BLOCK fan
            VAR_INPUT t : REAL; END_VAR
            VAR_OUTPUT speed : REAL; noise : REAL; END_VAR
            FUZZIFY t TERM warm := (10, 0) (30, 1); END_FUZZIFY
            DEFUZZIFY speed TERM fast := 100; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
            DEFUZZIFY noise TERM loud := 60; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
            RULEBLOCK r
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF NOT (t IS warm) THEN speed IS fast WITH 0.5, noise IS loud;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /** fuzzylite: one statement per line, ACCU in DEFUZZIFY, the rule split by weight, NOT as 'is not'. */
    @Test
    void fuzzyliteLayoutSplitsARuleByWeight() {
        Written w = DialectWriters.writer(Dialect.FUZZYLITE).write(standard(TWO_WEIGHTS));
        assertEquals("""
                FUNCTION_BLOCK fan

                VAR_INPUT
                  t: REAL;
                END_VAR

                VAR_OUTPUT
                  speed: REAL;
                  noise: REAL;
                END_VAR

                FUZZIFY t
                  TERM warm := (10, 0) (30, 1);
                END_FUZZIFY

                DEFUZZIFY speed
                  RANGE := (99 .. 101);
                  TERM fast := 100;
                  METHOD : COGS;
                  ACCU : MAX;
                  DEFAULT := 0;
                END_DEFUZZIFY

                DEFUZZIFY noise
                  RANGE := (59 .. 61);
                  TERM loud := 60;
                  METHOD : COGS;
                  ACCU : MAX;
                  DEFAULT := 0;
                END_DEFUZZIFY

                RULEBLOCK r
                  AND : MIN;
                  OR : MAX;
                  ACT : MIN;
                  RULE 1 : if t is not warm then speed is fast with 0.5
                  RULE 2 : if t is not warm then noise is loud
                END_RULEBLOCK

                END_FUNCTION_BLOCK
                """, w.text());
        assertTrue(w.exact());
        assertTrue(w.differences().isEmpty(), w.differences().toString());
        RoundTrip rt = DialectWriters.readBackAndCompare(standard(TWO_WEIGHTS), w);
        assertTrue(rt.equal(), rt.summary());
    }

    /** jFuzzyLogic: one WITH per rule too, ACCU and DEFAULT written out, NOT as IS NOT. */
    @Test
    void jfuzzylogicLayout() {
        Written w = DialectWriters.writer(Dialect.JFUZZYLOGIC).write(standard(TWO_WEIGHTS));
        assertTrue(w.text().contains("""
                RULEBLOCK r
                    AND : MIN;
                    ACCU : MAX;
                    RULE 1 : IF t IS NOT warm THEN speed IS fast WITH 0.5;
                    RULE 2 : IF t IS NOT warm THEN noise IS loud;
                END_RULEBLOCK
                """), w.text());
        assertTrue(w.text().contains("    METHOD : COGS;\n    DEFAULT := 0;\n"), w.text());
        assertTrue(DialectWriters.readBackAndCompare(standard(TWO_WEIGHTS), w).equal());
    }

    private static final String OR_NOT = """
            FUNCTION_BLOCK heater
            VAR_INPUT a : REAL; b : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY a TERM hot := (0, 0) (10, 1); END_FUZZIFY
            FUZZIFY b TERM dry := (0, 1) (4, 1) (8, 0) (10, 0); END_FUZZIFY
            DEFUZZIFY y TERM on := 100; TERM off := 0; METHOD : CoGS; DEFAULT := 50; END_DEFUZZIFY
            RULEBLOCK r
                AND : MIN; OR : MAX; ACCU : MAX;
                RULE 1 : IF b IS NOT dry OR a IS hot THEN y IS off;
                RULE 2 : IF b IS dry THEN y IS on;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * FFLL: the OR becomes two rules, each naming both inputs in declaration order, each subcondition and the
     * subconclusion in parentheses (FFLL's strict form; unparenthesised it takes the first word for its shorthand);
     * 'b IS NOT dry' becomes the complement term (x, 1 − y) and an input a conjunction leaves out gets the term
     * 'anything' of degree 1. Every term in the shapes FFLL holds (it ignores written degrees): a shoulder as a
     * trapezoid with a repeated point at the end of the RANGE (a triangle when its plateau is that point),
     * 'anything' as the trapezoid over the whole RANGE. Loaded in the real FFLL this gives the hand values below
     * exactly (FfllIutTest does not repeat it; checked by hand with --iut ffll).
     */
    @Test
    void ffllExpandsOrAndNotIntoRulesOverEveryInput() throws Exception {
        Program p = standard(OR_NOT);
        Written w = DialectWriters.writer(Dialect.FFLL).write(p);
        assertTrue(w.exact(), w.notExpressible().toString());
        assertTrue(w.text().contains("""
                FUZZIFY a
                    TERM hot := (0, 0) (10, 1) (10, 1);
                    TERM anything := (0, 1) (0, 1) (10, 1) (10, 1);
                END_FUZZIFY
                """), w.text());
        assertTrue(w.text().contains("""
                FUZZIFY b
                    TERM dry := (0, 1) (0, 1) (4, 1) (8, 0);
                    TERM not_dry := (4, 0) (8, 1) (10.452, 1) (10.452, 1);
                    TERM anything := (0, 1) (0, 1) (10.452, 1) (10.452, 1);
                END_FUZZIFY
                """), w.text());
        assertTrue(w.text().contains("""
                    RULE 0: IF (a IS anything) AND (b IS not_dry) THEN (y IS off);
                    RULE 1: IF (a IS hot) AND (b IS anything) THEN (y IS off);
                    RULE 2: IF (a IS anything) AND (b IS dry) THEN (y IS on);
                """), w.text());
        assertTrue(w.text().contains("    a REAL; (* RANGE(0 .. 10) *)\n"), w.text());
        // not_dry rises over 4 .. 8, more than 2/3 of 4 .. 10: FFLL would pull the trapezoid's second point back, so
        // b's RANGE moves right to 4 + 1.6 · 4 = 10.4 and a grid step (10.4 / 200 = 0.052) more
        assertTrue(w.text().contains("    b REAL; (* RANGE(0 .. 10.452) *)\n"), w.text());
        // by hand: a = 5, b = 6: hot 0.5, dry 0.5, not dry 0.5; off = max(0.5, 0.5) = 0.5, on = 0.5 → 50
        // a = 2, b = 9: hot 0.2, dry 0, not dry 1; off = 1, on = 0 → 0
        Program back = Analysis.analyze(DialectReaders.reader(Dialect.FFLL), "w.fcl", w.text()).program().orElseThrow();
        FunctionBlockInstance fb = Evaluator.load(back).newInstance();
        fb.set("a", 5);
        fb.set("b", 6);
        fb.evaluate();
        assertEquals(50, fb.get("y"), 1e-12);
        fb.set("a", 2);
        fb.set("b", 9);
        fb.evaluate();
        assertEquals(0, fb.get("y"), 1e-12);
        RoundTrip rt = DialectWriters.readBackAndCompare(p, w);
        assertTrue(rt.equal(), rt.summary());
        assertTrue(rt.comparisons() > 1000, rt.summary());
    }

    /** What cannot be said is located at the original construct and makes the written program differ. */
    @Test
    void lossesAreLocatedAndTheRoundTripSaysWhere() {
        String text = """
                FUNCTION_BLOCK w
                VAR_INPUT a : REAL; k : REAL := 0.25; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY a TERM on := (0, 0) (1, 1); END_FUZZIFY
                FUZZIFY k TERM on := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y TERM hi := 100; TERM lo := 0; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r
                    AND : PROD; OR : ASUM; ACCU : MAX;
                    RULE 1 : IF a IS on OR k IS on THEN y IS hi WITH k;
                    RULE 2 : IF a IS NOT on THEN y IS lo;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Program p = standard(text);
        Written jfl = DialectWriters.writer(Dialect.JFUZZYLOGIC).write(p);
        assertFalse(jfl.exact());
        List<String> codes = jfl.notExpressible().stream().map(d -> d.code() + "@" + d.location().line() + ":"
                + d.location().column()).toList();
        assertEquals(List.of("FCL-X101@2:33", "FCL-X102@9:54"), codes);
        RoundTrip rt = DialectWriters.readBackAndCompare(p, jfl, null, List.of(Map.of("a", 0.5)));
        assertTrue(rt.readBack().isPresent());
        assertFalse(rt.equal());
        // a = 0.5, k = 0.25 (its initial value): original OR ASUM = 0.5 + 0.25 - 0.125 = 0.625, weighted by k;
        // written, k starts at 0 (OR 0.5) and the weight is k's initial value 0.25: hi 0.125; lo = 1 - 0.5 both times
        RoundTrip.Mismatch first = rt.mismatches().get(0);
        assertEquals(Map.of("a", 0.5), first.inputs());
        assertEquals(100 * 0.625 * 0.25 / (0.625 * 0.25 + 0.5), first.original(), 1e-12);
        assertEquals(100 * 0.5 * 0.25 / (0.5 * 0.25 + 0.5), first.written(), 1e-12);
        assertEquals("FCL-X101", jfl.notExpressible().get(0).code());
        Written ffll = DialectWriters.writer(Dialect.FFLL).write(p);
        assertTrue(ffll.notExpressible().stream().anyMatch(d -> d.code().equals("FCL-X109")
                && d.location().line() == 9 && d.message().contains("no OR")), ffll.notExpressible().toString());
    }


    /**
     * Takagi–Sugeno terms are written as fuzzylite reads them (Constant, Linear with one coefficient per input in
     * declaration order, the constant last) and the unbounded sum by its class name (fuzzylite 6.0 refuses 'SUM');
     * jFuzzyLogic's and FFLL's writers name the loss instead of failing.
     */
    @Test
    void takagiSugenoTermsAndTheUnboundedSumAreWrittenAsFuzzyliteReadsThem() {
        String text = """
                FUNCTION_BLOCK ts
                VAR_INPUT
                  a: REAL;
                  b: REAL;
                END_VAR
                VAR_OUTPUT
                  y: REAL;
                END_VAR
                FUZZIFY a
                  TERM lo := Ramp 10 0;
                  TERM hi := Ramp 0 10;
                END_FUZZIFY
                FUZZIFY b
                  TERM hi := Ramp 0 10;
                END_FUZZIFY
                DEFUZZIFY y
                  RANGE := (-100 .. 100);
                  TERM c := Constant 2.5;
                  TERM l := Linear 0 3 -1;
                  METHOD : COGS;
                  ACCU : UnboundedSum;
                  DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK r
                  AND : MIN;
                  RULE 1 : if a is lo then y is c
                  RULE 2 : if a is hi and b is hi then y is l
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = Analysis.analyze(DialectReaders.reader(Dialect.FUZZYLITE), "ts.fcl", text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        Written fl = DialectWriters.writer(Dialect.FUZZYLITE).write(p);
        assertTrue(fl.text().contains("  TERM c := Constant 2.5;\n") && fl.text().contains("  TERM l := Linear 0 3 -1;\n")
                && fl.text().contains("  ACCU : UnboundedSum;\n"), fl.text());
        // a = 6, b = 4: c with 0.4, l = 3 * 4 - 1 = 11 with min(0.6, 0.4) = 0.4: (0.4 * 2.5 + 0.4 * 11) / 0.8 = 6.75
        RoundTrip rt = DialectWriters.readBackAndCompare(p, fl, null, List.of(Map.of("a", 6.0, "b", 4.0)));
        assertTrue(rt.equal(), rt.summary());
        Written fll = DialectWriters.writer(Dialect.FLL).write(p);
        assertTrue(fll.text().contains("term: l Linear 0 3 -1"), fll.text());
        for (Dialect d : List.of(Dialect.JFUZZYLOGIC, Dialect.FFLL)) {
            Written w = DialectWriters.writer(d).write(p);
            assertTrue(w.notExpressible().stream().anyMatch(x -> x.code().equals("FCL-X106")
                    && x.message().contains("Takagi-Sugeno term 'l' (Linear 0 3 -1)")), d + " " + w.notExpressible());
        }
        Analysis sum = Analysis.analyze(DialectReaders.reader(Dialect.FUZZYLITE), "sum.fcl",
                text.replace("UnboundedSum", "SUM"));
        assertTrue(sum.diagnostics().stream().anyMatch(x -> x.code().equals("FCL-S308")
                && x.message().startsWith("'SUM' is not an accumulation")), sum.diagnostics().toString());
    }

    /**
     * fuzzylite applies a conclusion's hedges to the rule's degree itself, so they also hedge every later
     * subconclusion of the rule (its Consequent::modify). The model gives each subconclusion the whole list; the
     * writer writes each hedge once, where it first applies. At a = 6 (checked with the fuzzylite 6.0 binary on this
     * text: y 4.736842105, z 12.000000000): hi 0.6, lo 0.4; y's c gets very(0.6) = 0.36, so y = 3.6 / 0.76 =
     * 4.7368…; z's d gets somewhat(very(0.6)) = 0.6, so z = 12 / 1.0 = 12 (somewhat(0.6) alone would give 13.19).
     * jFuzzyLogic and MATLAB's FIS have no hedges in conclusions: each is a named loss; FFLL refuses AND EPROD.
     */
    @Test
    void conclusionHedgesAreWrittenOnceWhereFuzzyliteAppliesThem() throws Exception {
        String text = """
                FUNCTION_BLOCK hc
                VAR_INPUT
                  a: REAL;
                END_VAR
                VAR_OUTPUT
                  y: REAL;
                  z: REAL;
                END_VAR
                FUZZIFY a
                  RANGE := (0 .. 10);
                  TERM lo := (0, 1) (10, 0);
                  TERM hi := (0, 0) (10, 1);
                END_FUZZIFY
                DEFUZZIFY y
                  RANGE := (-1 .. 11);
                  TERM e := 0;
                  TERM c := 10;
                  METHOD : COGS;
                  ACCU : MAX;
                  DEFAULT := 0;
                END_DEFUZZIFY
                DEFUZZIFY z
                  RANGE := (-1 .. 21);
                  TERM f := 0;
                  TERM d := 20;
                  METHOD : COGS;
                  ACCU : MAX;
                  DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK r
                  AND : EPROD;
                  ACT : MIN;
                  RULE 1 : if a is hi then y is very c and z is somewhat d
                  RULE 2 : if a is lo then y is e and z is f
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = Analysis.analyze(DialectReaders.reader(Dialect.FUZZYLITE), "hc.fcl", text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        for (Dialect d : List.of(Dialect.FUZZYLITE, Dialect.FLL)) {
            Written w = DialectWriters.writer(d).write(p);
            assertTrue(w.exact(), w.notExpressible()::toString);
            assertTrue(w.text().contains("if a is hi then y is very c and z is somewhat d\n"), w.text());
            RoundTrip rt = DialectWriters.readBackAndCompare(p, w);
            assertTrue(rt.equal(), rt.summary());
            FunctionBlockInstance back = Evaluator.load(rt.readBack().orElseThrow()).newInstance();
            back.set("a", 6);
            back.evaluate();
            assertEquals(3.6 / 0.76, back.get("y"), 1e-15);
            assertEquals(12.0, back.get("z"), 1e-14);
        }
        for (Dialect d : List.of(Dialect.JFUZZYLOGIC, Dialect.FIS)) {
            Written w = DialectWriters.writer(d).write(p);
            assertTrue(w.notExpressible().stream().anyMatch(x -> x.code().equals("FCL-X105")
                    && x.location().line() == 33 && x.message().contains("no hedges in a conclusion ([somewhat, very]"
                    + " on 'z')")), d + " " + w.notExpressible());
        }
        Written ffll = DialectWriters.writer(Dialect.FFLL).write(p);
        assertTrue(ffll.notExpressible().stream().anyMatch(x -> x.code().equals("FCL-X107")
                && x.message().contains("FFLL has no AND EPROD")), ffll.notExpressible().toString());
        assertTrue(DialectWriters.readBackAndCompare(p, ffll).readBack().isPresent(), ffll.text());
    }

    /** Hedge lists that do not chain (each subconclusion's list must end with the one before it) split the line. */
    @Test
    void conclusionHedgesThatDoNotChainSplitTheLine() {
        org.fclcert.model.SourceLocation at = new org.fclcert.model.SourceLocation("h", 1, 1);
        java.util.function.BiFunction<String, List<org.fclcert.model.Hedge>, org.fclcert.model.Subconclusion> s =
                (v, h) -> new org.fclcert.model.Subconclusion(v, java.util.Optional.of("t"), java.util.Optional.empty(), h, at);
        var very = org.fclcert.model.Hedge.VERY;
        var somewhat = org.fclcert.model.Hedge.SOMEWHAT;
        BlockContext.WeightGroup g = new BlockContext.WeightGroup(List.of(s.apply("u", List.of(very)),
                s.apply("v", List.of(somewhat, very)), s.apply("w", List.of(somewhat)), s.apply("x", List.of())),
                java.util.Optional.empty(), 1.0);
        List<BlockContext.WeightGroup> chains = RuleLines.hedgeChains(g);
        assertEquals(List.of(List.of("u", "v"), List.of("w"), List.of("x")),
                chains.stream().map(c -> c.parts().stream().map(org.fclcert.model.Subconclusion::variable).toList()).toList());
        assertEquals(List.of(very), RuleLines.writtenHedges(chains.get(0), 0));
        assertEquals(List.of(somewhat), RuleLines.writtenHedges(chains.get(0), 1));
        assertEquals(List.of(somewhat), RuleLines.writtenHedges(chains.get(1), 0));
        assertEquals(List.of(), RuleLines.writtenHedges(chains.get(2), 0));
    }

    /**
     * fuzzylite's Einstein ACT/ACCU and Tsukamoto's method: its writer says them (read back, equal on the grid);
     * jFuzzyLogic and FFLL cannot, and name each loss where it was written.
     */
    @Test
    void otherNormsAndTsukamotoAreFuzzyliteOnly() throws Exception {
        String text = Files.readString(Path.of("src/test/resources/org/fclcert/syntax/dialect/fuzzylite/einstein-tsukamoto.fcl"));
        Analysis a = Analysis.analyze(DialectReaders.reader(Dialect.FUZZYLITE), "m.fcl", text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        Written fl = DialectWriters.writer(Dialect.FUZZYLITE).write(p);
        assertTrue(fl.exact(), fl.notExpressible()::toString);
        assertTrue(fl.text().contains("  ACT : EPROD;\n") && fl.text().contains("  ACCU : ESUM;\n")
                && fl.text().contains("  TERM open := Sigmoid 0.5 12.0;\n"), fl.text());
        RoundTrip rt = DialectWriters.readBackAndCompare(p, fl);
        assertTrue(rt.equal(), rt.summary());
        for (Dialect d : List.of(Dialect.JFUZZYLOGIC, Dialect.FFLL)) {
            Written w = DialectWriters.writer(d).write(p);
            List<Diagnostic> lost = w.notExpressible();
            assertTrue(lost.stream().anyMatch(x -> x.code().equals("FCL-X107") && x.location().line() == 33), d + " " + lost);
            assertTrue(lost.stream().anyMatch(x -> x.code().equals("FCL-X108") && x.location().line() == 20), d + " " + lost);
            assertTrue(lost.stream().anyMatch(x -> x.code().equals("FCL-X110") && x.location().line() == 27), d + " " + lost);
        }
    }

    @Test
    void strictHasNoLibraryWriter() {
        assertThrows(IllegalArgumentException.class, () -> DialectWriters.writer(Dialect.STRICT));
    }

    @Test
    void theDiagnosticsCatalogueListsEveryWriterCode() throws Exception {
        String doc = Files.readString(Path.of("docs/diagnostics.md"));
        for (WriterCode c : WriterCode.values()) {
            assertTrue(doc.contains("| " + c.code() + " | " + c.severity().word() + " | " + c.meaning() + " |"), c.code());
            assertEquals(c.code().startsWith("FCL-X1"), c.lossOfMeaning());
        }
        assertEquals(WriterCode.values().length, java.util.Arrays.stream(WriterCode.values()).map(WriterCode::code)
                .distinct().count());
    }

    static String codes(List<Diagnostic> ds) {
        return String.join(",", ds.stream().map(Diagnostic::code).toList());
    }
}
