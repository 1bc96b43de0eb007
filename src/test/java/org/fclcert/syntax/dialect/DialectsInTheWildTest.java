package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.Program;
import org.fclcert.model.ShapeKind;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;
import org.junit.jupiter.api.Test;

/**
 * Small programs written in each library's style, one construct each, of the kinds found in FCL files in the
 * wild (issue 13): each read with its library's meaning, values calculated by hand.
 */
class DialectsInTheWildTest {

    private static Analysis analyze(FclReader reader, String text) {
        return Analysis.analyze(reader, "t.fcl", text);
    }

    private static Program read(FclReader reader, String text) {
        Analysis a = analyze(reader, text);
        return a.program().orElseThrow(() -> new AssertionError(a.diagnostics() + "\n" + text));
    }

    private static boolean has(Analysis a, String code, int line) {
        return a.diagnostics().stream().anyMatch(d -> d.code().equals(code) && d.location().line() == line);
    }

    private static double eval(Program p, Map<String, Double> in, String out) throws Exception {
        FunctionBlockInstance x = Evaluator.load(p).newInstance();
        for (Map.Entry<String, Double> e : in.entrySet()) {
            x.set(e.getKey(), e.getValue());
        }
        x.evaluate();
        return x.get(out);
    }

    private static final String TS_HEAD = """
            FUNCTION_BLOCK sugeno
            VAR_INPUT
              a: REAL;
              b: REAL;
            END_VAR
            VAR_OUTPUT
              y: REAL;
            END_VAR
            FUZZIFY a
              RANGE := (0.000 .. 1.000);
              TERM low := Ramp 1.000 0.000;
              TERM high := Ramp 0.000 1.000;
            END_FUZZIFY
            FUZZIFY b
              RANGE := (0.000 .. 4.000);
            END_FUZZIFY
            """;

    /** fuzzylite Linear (one coefficient per input, then a constant) and Constant: a weighted average. */
    @Test
    void fuzzyliteTakagiSugenoIsTheWeightedAverageOfLinearFunctions() throws Exception {
        String text = TS_HEAD + """
                DEFUZZIFY y
                  RANGE := (0.000 .. 20.000);
                  TERM lin := Linear 2.000 3.000 1.000;
                  TERM five := Constant 5.000;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                RULEBLOCK
                  RULE 1 : if a is low then y is lin
                  RULE 2 : if a is high then y is five
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Program p = read(new FuzzyliteReader(), text);
        // a = 0.25: low 0.75, high 0.25; lin = 2·0.25 + 3·2 + 1 = 7.5; (0.75·7.5 + 0.25·5) / 1 = 6.875
        assertEquals(6.875, eval(p, Map.of("a", 0.25, "b", 2.0), "y"), 1e-12);
        // a = 1: only high fires: 5, whatever b
        assertEquals(5.0, eval(p, Map.of("a", 1.0, "b", 3.0), "y"), 0.0);
        assertTrue(p.dialectFeatures().stream().anyMatch(u -> u.feature() == Feature.O_TAKAGI_SUGENO));
        assertTrue(p.dialectFeatures().stream().anyMatch(u -> u.feature() == Feature.O_UNNAMED_BLOCK));
        // the conversion says the Linear term is not standard FCL, and writes the Constant as a singleton
        StandardConversion.Result r = new StandardConversion().convert(p);
        assertTrue(r.findings().stream().anyMatch(f -> f.construct().equals("O-TAKAGI-SUGENO")
                && f.kind() instanceof StandardConversion.Kind.NotExpressible && f.location().line() == 19));
        assertTrue(r.findings().stream().anyMatch(f -> f.construct().equals("O-TAKAGI-SUGENO")
                && f.kind() instanceof StandardConversion.Kind.Exact && f.location().line() == 20));
    }

    /** fuzzylite Function: a formula of the variables; a mistake in it is located at the formula. */
    @Test
    void fuzzyliteFunctionTermsAreFormulasOfTheVariables() throws Exception {
        String body = """
                DEFUZZIFY y
                  RANGE := (0.000 .. 20.000);
                  TERM f := Function %s;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                RULEBLOCK
                  RULE 1 : if a is any then y is f
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Program p = read(new FuzzyliteReader(), TS_HEAD + body.formatted("2*a + b^2 - fabs(-1)"));
        assertEquals(2 * 0.25 + 9 - 1, eval(p, Map.of("a", 0.25, "b", 3.0), "y"), 1e-12);
        Analysis bad = analyze(new FuzzyliteReader(), TS_HEAD + body.formatted("2*c + 1"));
        assertTrue(has(bad, "FCL-S305", 19), bad.diagnostics()::toString);
    }

    @Test
    void fuzzyliteConcaveAndSpikeFollowItsFormulas() {
        // Concave 0.85 0.25 (falling): ½ at the inflection, 1 up to the end, 0.6 / (0.35 + u) beyond it
        assertEquals(0.5, ShapeKind.CONCAVE.degree(new double[] {0.85, 0.25}, 0.85), 1e-15);
        assertEquals(1.0, ShapeKind.CONCAVE.degree(new double[] {0.85, 0.25}, 0.1), 0.0);
        assertEquals(0.6 / 1.35, ShapeKind.CONCAVE.degree(new double[] {0.85, 0.25}, 1.0), 1e-15);
        // rising Concave 5.65 6.25: (6.25 − 5.65) / (12.5 − 5.65 − u)
        assertEquals(0.6 / 1.85, ShapeKind.CONCAVE.degree(new double[] {5.65, 6.25}, 5.0), 1e-15);
        // Spike 3.64 1.04: 1 at the centre, 1/e a tenth of the width away
        assertEquals(1.0, ShapeKind.SPIKE.degree(new double[] {3.64, 1.04}, 3.64), 0.0);
        assertEquals(Math.exp(-1), ShapeKind.SPIKE.degree(new double[] {3.64, 1.04}, 3.64 + 0.104), 1e-12);
    }

    /** fuzzylite 5 wrote the engine name verbatim; DEFAULT := nan | NC keeps the previous value. */
    @Test
    void fuzzyliteVerbatimNamesAndKeepingThePreviousValue() {
        String text = """
                FUNCTION_BLOCK my engine-1
                VAR_INPUT
                  a: REAL;
                END_VAR
                VAR_OUTPUT
                  y: REAL;
                END_VAR
                FUZZIFY a
                  TERM low := Triangle 0.000 0.000 1.000;
                END_FUZZIFY
                DEFUZZIFY y
                  TERM one := 1.000;
                  METHOD : COGS;
                  DEFAULT := nan | NC;
                END_DEFUZZIFY
                RULEBLOCK
                  RULE 1 : if a is low then y is one
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = analyze(new FuzzyliteReader(), text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertEquals("my_engine_1", p.functionBlocks().get(0).name());
        assertTrue(has(a, "FCL-W308", 1) && has(a, "FCL-W305", 14), a.diagnostics()::toString);
        Defuzzification d = p.functionBlocks().get(0).defuzzifications().get(0);
        assertTrue(d.defaultValue().orElseThrow() instanceof DefaultValue.NoChange);
    }

    /** fuzzylite evaluates AND PROD with OR MAX as written: read so, with a warning naming Table 3. */
    @Test
    void fuzzyliteOperatorsOutsideTable3AreEvaluatedAsWritten() throws Exception {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT
                  a: REAL;
                  b: REAL;
                END_VAR
                VAR_OUTPUT
                  y: REAL;
                END_VAR
                FUZZIFY a
                  TERM hi := Ramp 0.000 1.000;
                END_FUZZIFY
                FUZZIFY b
                  TERM hi := Ramp 0.000 1.000;
                END_FUZZIFY
                DEFUZZIFY y
                  TERM one := 1.000;
                  TERM zero := 0.000;
                  METHOD : COGS;
                  DEFAULT := 0.000;
                END_DEFUZZIFY
                RULEBLOCK r
                  AND : PROD;
                  OR : MAX;
                  ACCU : MAX;
                  RULE 1 : if a is hi or b is hi then y is one
                  RULE 2 : if a is hi and b is hi then y is zero
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = analyze(new FuzzyliteReader(), text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertTrue(has(a, "FCL-W308", 21), a.diagnostics()::toString);
        // a = 0.5, b = 0.4: OR MAX 0.5 for one, AND PROD 0.2 for zero: (0.5·1 + 0.2·0) / 0.7
        assertEquals(0.5 / 0.7, eval(p, Map.of("a", 0.5, "b", 0.4), "y"), 1e-12);
    }

    /**
     * fuzzylite applies a conclusion's hedge to the rule's degree itself, so it holds for the later subconclusions
     * of the rule too (the fuzzylite binary gives y = 0.2, z = 0.310345 here); EPROD is the Einstein product.
     */
    @Test
    void fuzzyliteHedgesInConclusionsAndEinsteinProduct() throws Exception {
        String text = """
                FUNCTION_BLOCK h
                VAR_INPUT
                  a: REAL;
                END_VAR
                VAR_OUTPUT
                  y: REAL;
                  z: REAL;
                END_VAR
                FUZZIFY a
                  TERM hi := Ramp 0.000 1.000;
                END_FUZZIFY
                DEFUZZIFY y
                  TERM one := 1.000;
                  TERM zero := 0.000;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                DEFUZZIFY z
                  TERM one := 1.000;
                  TERM zero := 0.000;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                RULEBLOCK
                  AND : EPROD;
                  RULE 1 : if a is hi then y is very one and z is one
                  RULE 2 : if a is any then y is zero and z is zero
                  RULE 3 : if a is hi and a is hi then z is one
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Program p = read(new FuzzyliteReader(), text);
        // a = 0.5: rule 1 degree 0.5, very → 0.25 for y and for z; rule 3: 0.25 / (2 − 0.75) = 0.2
        assertEquals(0.25 / 1.25, eval(p, Map.of("a", 0.5), "y"), 1e-15);
        assertEquals((0.25 + 0.2) / 1.45, eval(p, Map.of("a", 0.5), "z"), 1e-15);
        StandardConversion.Result r = new StandardConversion().convert(p);
        assertTrue(r.findings().stream().anyMatch(f -> f.construct().equals("O-HEDGE-IN-CONCLUSION")
                && f.kind() instanceof StandardConversion.Kind.NotExpressible));
        assertTrue(r.findings().stream().anyMatch(f -> f.construct().equals("O-OTHER-NORM")
                && f.kind() instanceof StandardConversion.Kind.NotExpressible));
        // the strict reader does not take EPROD
        assertTrue(analyze(new StrictReader(), text.replace("RULEBLOCK\n", "RULEBLOCK r\n")).program().isEmpty());
    }

    private static final String JFL_HEAD = """
            FUNCTION_BLOCK tipper
            VAR_INPUT
              service : REAL;
            END_VAR
            VAR_OUTPUT
              tip : REAL;
            %s
            END_VAR
            FUZZIFY service
              TERM poor := trian 0 0 10;
              TERM good := trian 0 10 10;
            END_FUZZIFY
            DEFUZZIFY tip
            %s
              METHOD : COG;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
              AND : MIN;
              ACCU : MAX;
              RULE 1 : IF service IS poor THEN tip IS cheap;
              RULE 2 : IF service IS good THEN tip IS generous;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /** jFuzzyLogic defuzzifies an output without RANGE over its terms' span: read as that RANGE, warned. */
    @Test
    void jfuzzylogicImpliedUniverseIsReadAsARange() throws Exception {
        String text = JFL_HEAD.formatted("", "  TERM cheap := (0, 1) (10, 0);\n  TERM generous := (10, 0) (30, 1);");
        Analysis a = analyze(new JFuzzyLogicReader(), text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertTrue(has(a, "FCL-W309", 13), a.diagnostics()::toString);
        Defuzzification d = p.functionBlocks().get(0).defuzzifications().get(0);
        assertEquals(0.0, d.range().orElseThrow().min().value());
        assertEquals(30.0, d.range().orElseThrow().max().value());
        // service = 0: only cheap at 1 → its triangle over [0, 10]: CoG 10/3
        assertEquals(10.0 / 3, eval(p, Map.of("service", 0.0), "tip"), 1e-12);
        // the conversion writes the RANGE out, and the strict reader reads it back
        String converted = new CanonicalWriter().write(new StandardConversion().convert(p).program());
        assertTrue(converted.contains("RANGE (0 .. 30);"), converted);
        assertTrue(analyze(new StrictReader(), converted).program().isPresent());
    }

    @Test
    void jfuzzylogicGaussianUniverseIsMeanPlusMinusFourSd() {
        String text = JFL_HEAD.formatted("", "  TERM cheap := gauss 5 2;\n  TERM generous := gauss 25 3;");
        Program p = read(new JFuzzyLogicReader(), text);
        Defuzzification d = p.functionBlocks().get(0).defuzzifications().get(0);
        assertEquals(-3.0, d.range().orElseThrow().min().value());
        assertEquals(37.0, d.range().orElseThrow().max().value());
    }

    /** 'tip : REAL; RANGE := (0 .. 30);' in VAR_OUTPUT gives tip its range. */
    @Test
    void jfuzzylogicRangeAfterADeclaration() {
        String text = JFL_HEAD.formatted("  RANGE := (0 .. 40);", "  TERM cheap := (0, 1) (10, 0);\n"
                + "  TERM generous := (10, 0) (30, 1);");
        Analysis a = analyze(new JFuzzyLogicReader(), text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertEquals(40.0, p.functionBlocks().get(0).defuzzifications().get(0).range().orElseThrow().max().value());
        assertFalse(has(a, "FCL-W309", 13));
    }

    /** Text after END_FUNCTION_BLOCK: jFuzzyLogic ignores it; read with a warning at it. */
    @Test
    void trailingTextIsToleratedWithAWarning() {
        String text = JFL_HEAD.formatted("", "  TERM cheap := 5;\n  TERM generous := 25;").replace("COG;", "COGS;")
                + "some notes here\n";
        Analysis a = analyze(new JFuzzyLogicReader(), text);
        assertTrue(a.program().isPresent(), a.diagnostics()::toString);
        assertTrue(has(a, "FCL-W308", 26), a.diagnostics()::toString);
    }

    private static final String REPEATED = """
            FUNCTION_BLOCK dup    // two inputs, one output of singletons
            VAR_INPUT
              x : REAL;
              y : REAL;
            END_VAR
            VAR_OUTPUT
              z : REAL;
            END_VAR
            FUZZIFY x
              TERM lo := (0, 1) (10, 0);
              TERM hi := (0, 0) (10, 1);
            END_FUZZIFY
            FUZZIFY y
              TERM lo := (0, 1) (10, 0);
              TERM hi := (0, 0) (10, 1);
            END_FUZZIFY
            DEFUZZIFY z
              TERM a := 0;
              TERM b := 10;
              METHOD : COGS;
              DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
              ACCU : MAX;
              RULE 1 : IF x IS lo AND y IS lo THEN z IS a;
              RULE 1 : IF x IS hi OR y IS hi THEN z IS b;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * A rule number written twice, and AND/OR without their declaration: jFuzzyLogic keeps both rules (a list) and
     * connects by MIN and MAX when nothing is declared; read so, with FCL-W308 and FCL-W304. The standard rejects
     * both (FCL-C007, FCL-C015).
     */
    @Test
    void jfuzzylogicRepeatedRuleNumbersAndItsDefaultAndOr() throws Exception {
        DialectReaders.Choice c = DialectReaders.auto(REPEATED);       // nothing but its '//' comment gives it away
        assertEquals(Dialect.JFUZZYLOGIC, c.dialect(), c.explanation());
        Analysis a = analyze(c.reader(), REPEATED);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertTrue(has(a, "FCL-W308", 26), a.diagnostics()::toString);
        assertTrue(has(a, "FCL-W304", 23), a.diagnostics()::toString);
        assertEquals(List.of("1", "r1_2"), p.functionBlocks().get(0).ruleBlocks().get(0).rules().stream()
                .map(org.fclcert.model.Rule::name).toList());
        // x = 2, y = 4: lo 0.8 and 0.6, MIN 0.6 for a (0); hi 0.2 and 0.4, MAX 0.4 for b (10): CoGS 4/1 = 4
        assertEquals(4.0, eval(p, Map.of("x", 2.0, "y", 4.0), "z"), 1e-12);
        // x = 8, y = 6: MIN(0.2, 0.4) = 0.2 for a; MAX(0.8, 0.6) = 0.8 for b: 8
        assertEquals(8.0, eval(p, Map.of("x", 8.0, "y", 6.0), "z"), 1e-12);
        Analysis strict = analyze(new StrictReader(), REPEATED.replace("    // two inputs, one output of singletons", ""));
        assertTrue(has(strict, "FCL-C007", 26) && has(strict, "FCL-C015", 25), strict.diagnostics()::toString);
    }

    /**
     * Files wrong even for their library (issue 13's table: a missing END_VAR, 'DEFAULT = 0', 'WITH 5', an undefined
     * term, 'TRIAN 0 0 0'): no program, a located error each, never a stack trace.
     */
    @Test
    void filesWrongEvenForTheirLibraryGetLocatedErrors() {
        String[][] cases = {
            {"  y : REAL;\nEND_VAR\n", "  y : REAL;\n", "FCL-S305", "5"},
            {"  DEFAULT := 0;", "  DEFAULT = 0;", "FCL-S301", "21"},
            {"THEN z IS b;", "THEN z IS b WITH 5;", "FCL-C012", "26"},
            {"OR y IS hi THEN", "OR y IS middle THEN", "FCL-C002", "26"},
            {"  TERM lo := (0, 1) (10, 0);\n  TERM hi := (0, 0) (10, 1);\nEND_FUZZIFY\nFUZZIFY y", "  TERM lo := TRIAN 0 0 0;\n"
                + "  TERM hi := (0, 0) (10, 1);\nEND_FUZZIFY\nFUZZIFY y", "FCL-C041", "10"},
        };
        for (String[] c : cases) {
            assertTrue(REPEATED.contains(c[0]), c[0]);
            Analysis a = analyze(new JFuzzyLogicReader(), REPEATED.replace(c[0], c[1]));
            assertTrue(a.program().isEmpty(), c[1]);
            assertTrue(has(a, c[2], Integer.parseInt(c[3])), () -> c[1] + ": " + a.diagnostics());
        }
    }

    /** FUNCTION_BLOCK without a name: jFuzzyLogic's grammar allows it; read as 'function_block'. */
    @Test
    void jfuzzylogicUnnamedFunctionBlock() throws Exception {
        String text = REPEATED.replace("FUNCTION_BLOCK dup    // two inputs, one output of singletons", "FUNCTION_BLOCK")
                .replace("RULE 1 : IF x IS hi", "RULE 2 : IF x IS hi").replace("  ACCU : MAX;", "  AND : MIN;\n  ACCU : MAX;");
        // FFLL's API sample has one too, but FFLL loads no program without RANGE comments: jFuzzyLogic
        DialectReaders.Choice c = DialectReaders.auto(text);
        assertEquals(Dialect.JFUZZYLOGIC, c.dialect(), c.explanation());
        assertEquals("read as jFuzzyLogic: FUNCTION_BLOCK without a name at line 1", c.explanation());
        Analysis a = analyze(c.reader(), text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertEquals("function_block", p.functionBlocks().get(0).name());
        assertTrue(p.dialectFeatures().stream().anyMatch(u -> u.feature() == Feature.O_UNNAMED_BLOCK && u.location().line() == 1));
        assertEquals(8.0, eval(p, Map.of("x", 8.0, "y", 6.0), "z"), 1e-12);
        assertTrue(has(analyze(new StrictReader(), text), "FCL-S034", 2));
    }

    /**
     * Points given by variables (standard FCL, 5.2.2), as jFuzzyLogic writes them: read as variable points; a variable
     * without a FUZZIFY block before the term is an error for jFuzzyLogic itself (its VAR sections create none).
     */
    @Test
    void jfuzzylogicVariablePointsNeedTheVariablesBlockFirst() throws Exception {
        String text = """
                FUNCTION_BLOCK moving
                VAR_INPUT
                  level : REAL;
                  mid : REAL;
                END_VAR
                VAR_OUTPUT
                  pump : REAL;
                END_VAR
                FUZZIFY mid
                  TERM any := (0, 1) (20, 1);
                END_FUZZIFY
                FUZZIFY level
                  TERM low := (0, 1) (mid, 0);
                  TERM high := TRIAN 0 mid 20;
                END_FUZZIFY
                DEFUZZIFY pump
                  TERM stop := 0;
                  TERM full := 100;
                  METHOD : COGS;
                  DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK No1
                  AND : MIN;
                  ACCU : MAX;
                  RULE 1 : IF level IS low THEN pump IS stop;
                  RULE 2 : IF level IS high THEN pump IS full;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Program p = read(new JFuzzyLogicReader(), text);
        // mid = 8, level = 6: low (0,1)(8,0) = 0.25, high (0,0)(8,1)(20,0) = 0.75: 100·0.75 / 1 = 75
        assertEquals(75.0, eval(p, Map.of("mid", 8.0, "level", 6.0), "pump"), 1e-12);
        // mid = 4, level = 6: low 0, high (20 − 6)/16 = 0.875: 100
        assertEquals(100.0, eval(p, Map.of("mid", 4.0, "level", 6.0), "pump"), 1e-12);
        Analysis late = analyze(new JFuzzyLogicReader(), text.replace("FUZZIFY mid\n  TERM any := (0, 1) (20, 1);\n"
                + "END_FUZZIFY\n", ""));
        assertTrue(late.program().isEmpty());
        assertTrue(has(late, "FCL-S306", 10) && has(late, "FCL-S306", 11), late.diagnostics()::toString);
        assertTrue(late.diagnostics().get(0).message().contains("FUZZIFY mid"), late.diagnostics()::toString);
    }

    /**
     * An output in a condition read as jFuzzyLogic reads it: at the output's value when the evaluation begins (its
     * DEFAULT), with FCL-W313; fuzzylite reads the same text as the degree reached so far (O-OUTPUT-CONDITION).
     */
    @Test
    void anOutputInAConditionIsReadAsEachLibraryReadsIt() throws Exception {
        String jfl = """
                FUNCTION_BLOCK chain
                VAR_INPUT
                  x : REAL;
                END_VAR
                VAR_OUTPUT
                  a : REAL;
                  b : REAL;
                END_VAR
                FUZZIFY x
                  TERM up := (0, 0) (10, 1);
                END_FUZZIFY
                DEFUZZIFY a
                  TERM one := 1;
                  METHOD : COGS;
                  DEFAULT := 2;
                END_DEFUZZIFY
                DEFUZZIFY b
                  TERM yes := 10;
                  METHOD : COGS;
                  DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK first
                  ACCU : MAX;
                  RULE 1 : IF x IS up THEN a IS one;
                END_RULEBLOCK
                RULEBLOCK second
                  ACCU : MAX;
                  RULE 1 : IF a IS lo THEN b IS yes WITH 0.5;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis bad = analyze(new JFuzzyLogicReader(), jfl);                    // 'lo' is no term of a
        assertTrue(bad.program().isEmpty(), bad.diagnostics()::toString);
        // the same with the term: read at a's DEFAULT 2 whatever the first block concludes
        Analysis a = analyze(new JFuzzyLogicReader(), jfl.replace("  TERM one := 1;\n", "  TERM one := 1;\n  TERM lo := 3;\n"));
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertTrue(has(a, "FCL-W313", 29), a.diagnostics()::toString);
        assertTrue(p.dialectFeatures().stream().anyMatch(u -> u.feature() == Feature.O_OUTPUT_VALUE_CONDITION));
        // 'lo' is the singleton 3 and a starts each evaluation at 2: degree 0, so b falls to its DEFAULT 0
        assertEquals(0.0, eval(p, Map.of("x", 5.0), "b"), 0);
        // with 'lo' at 2, its degree at the DEFAULT is 1: b = 10 (weight 0.5 on one singleton cancels)
        Program q = read(new JFuzzyLogicReader(), jfl.replace("  TERM one := 1;\n", "  TERM one := 1;\n  TERM lo := 2;\n"));
        assertEquals(10.0, eval(q, Map.of("x", 5.0), "b"), 0);
    }

    /** A fuzzylite output condition tolerates only itself: a wrong subcondition elsewhere is still reported. */
    @Test
    void anOutputConditionDoesNotHideOtherMistakes() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT
                  x: REAL;
                END_VAR
                VAR_OUTPUT
                  a: REAL;
                  b: REAL;
                END_VAR
                FUZZIFY x
                  RANGE := (0.000 .. 10.000);
                  TERM up := Ramp 0.000 10.000;
                END_FUZZIFY
                DEFUZZIFY a
                  RANGE := (0.000 .. 1.000);
                  TERM one := Constant 1.000;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                DEFUZZIFY b
                  RANGE := (0.000 .. 1.000);
                  TERM one := Constant 1.000;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                RULEBLOCK
                  RULE 1 : if x is up then a is one
                  RULE 2 : if a is one then b is one
                  RULE 3 : if x is down then b is one
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = analyze(new FuzzyliteReader(), text);
        assertTrue(a.program().isEmpty());
        assertTrue(has(a, "FCL-C002", 28), a.diagnostics()::toString);
        assertFalse(has(a, "FCL-C027", 27), a.diagnostics()::toString);
    }

    /**
     * What the libraries tolerate in files of the wild, read with FCL-W308: a term name written twice (fuzzylite finds
     * the first, jFuzzyLogic keeps the last), an empty RANGE of a fuzzylite weighted average (its Matlab importer
     * writes both), any characters after END_FUNCTION_BLOCK.
     */
    @Test
    void repeatedTermsAnEmptyRangeAndTrailingCharacters() throws Exception {
        String fl = TS_HEAD + """
                DEFUZZIFY y
                  RANGE := (0.000 .. 0.000);
                  TERM out1 := Constant 2.000;
                  TERM out1 := Constant 7.000;
                  METHOD : COGS;
                  DEFAULT := nan;
                END_DEFUZZIFY
                RULEBLOCK
                  RULE 1 : if a is high then y is out1
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = analyze(new FuzzyliteReader(), fl);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertTrue(has(a, "FCL-W308", 18) && has(a, "FCL-W308", 20), a.diagnostics()::toString);
        assertEquals(2.0, eval(p, Map.of("a", 0.5, "b", 1.0), "y"), 0);      // the first out1
        assertTrue(p.functionBlocks().get(0).defuzzifications().get(0).range().isEmpty());
        String jfl = REPEATED.replace("  TERM b := 10;", "  TERM b := 10;\n  TERM b := 20;")
                + "notes: see config.txt, 2 × faster\n";
        Analysis j = analyze(new JFuzzyLogicReader(), jfl);
        Program q = j.program().orElseThrow(() -> new AssertionError(j.diagnostics()));
        assertTrue(has(j, "FCL-W308", 19) && has(j, "FCL-W308", 30), j.diagnostics()::toString);
        // x = 8, y = 6: a 0.2 (at 0), b 0.8 now at 20: 16
        assertEquals(16.0, eval(q, Map.of("x", 8.0, "y", 6.0), "z"), 1e-12);
    }

    // ---------------------------------------------------------------- auto-detection

    @Test
    void wordsInCommentsAreNoEvidence() {
        String jfl = JFL_HEAD.formatted("", "  TERM cheap := (0, 1) (10, 0);\n  TERM generous := (10, 0) (30, 1);")
                .replace("VAR_OUTPUT", "VAR_OUTPUT // Define input variables Triangle Gaussian ACCUM");
        DialectReaders.Choice c = DialectReaders.auto(jfl);
        assertEquals(Dialect.JFUZZYLOGIC, c.dialect(), c.explanation());
        assertFalse(c.unsure());
        // a standard program but for '//' comments naming FFLL and fuzzylite constructs: only the comment style
        // counts (jFuzzyLogic's users write '//'; the strict reader rejects it), once, never the words in it
        String standard = """
                FUNCTION_BLOCK f // ACCUM: Triangle nan
                VAR_INPUT // Define input variables
                  a : REAL;
                END_VAR
                END_FUNCTION_BLOCK
                """;
        DialectReaders.Choice s = DialectReaders.auto(standard);
        assertEquals(Dialect.JFUZZYLOGIC, s.dialect(), s.explanation());
        assertEquals("read as jFuzzyLogic: '//' comment at line 1", s.explanation());
        assertTrue(DialectReaders.evidence(standard).stream().filter(e -> e.dialect() != Dialect.JFUZZYLOGIC)
                .allMatch(e -> e.weight() == 0), () -> DialectReaders.evidence(standard).toString());
    }

    @Test
    void upperCaseJfuzzylogicShapeNamesCount() {
        String text = JFL_HEAD.formatted("", "  TERM cheap := (0, 1) (10, 0);\n  TERM generous := (10, 0) (30, 1);")
                .replace("trian 0 0 10", "TRIAN 0 0 10").replace("trian 0 10 10", "TRIAN 0 10 10");
        assertEquals(Dialect.JFUZZYLOGIC, DialectReaders.auto(text).dialect());
        assertTrue(read(new JFuzzyLogicReader(), text).functionBlocks().size() == 1);
    }

    /**
     * Standard FCL but for what only jFuzzyLogic makes sense of: an output without RANGE whose terms do not fall to 0
     * (the survey's most frequent construct; jFuzzyLogic defuzzifies over their span), statements in an order its
     * grammar takes and the standard's does not. Each gives jFuzzyLogic away.
     */
    @Test
    void jfuzzylogicsHabitsInStandardLookingFilesGiveItAway() throws Exception {
        String text = """
                FUNCTION_BLOCK plain
                VAR_INPUT
                  load : REAL;
                END_VAR
                VAR_OUTPUT
                  fan : REAL;
                END_VAR
                FUZZIFY load
                  TERM low := (0, 1) (10, 0);
                  TERM high := (0, 0) (10, 1);
                END_FUZZIFY
                DEFUZZIFY fan
                  TERM slow := (0, 1) (50, 0);
                  TERM fast := (50, 0) (100, 1);
                  METHOD : COG;
                  DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK No1
                  AND : MIN;
                  ACT : MIN;
                  ACCU : MAX;
                  RULE 1 : IF load IS low THEN fan IS slow;
                  RULE 2 : IF load IS high THEN fan IS fast;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        assertTrue(has(analyze(new StrictReader(), text), "FCL-C025", 13));
        DialectReaders.Choice c = DialectReaders.auto(text);
        assertEquals("read as jFuzzyLogic: no RANGE over terms not falling to 0 at line 12", c.explanation());
        Program p = read(c.reader(), text);
        // load = 10: fast alone at 1, over the implied universe [0, 100]: CoG of (50, 0) (100, 1) = 250/3
        assertEquals(250.0 / 3, eval(p, Map.of("load", 10.0), "fan"), 1e-12);
        String disordered = text.replace("  METHOD : COG;\n  DEFAULT := 0;\n", "  DEFAULT := 0;\n  METHOD : COG;\n")
                .replace("  TERM slow := (0, 1) (50, 0);", "  TERM slow := (0, 0) (25, 1) (50, 0);")
                .replace("  TERM fast := (50, 0) (100, 1);", "  TERM fast := (50, 0) (75, 1) (100, 0);")
                .replace("  ACT : MIN;\n  ACCU : MAX;", "  ACCU : MAX;\n  ACT : MIN;");
        DialectReaders.Choice d = DialectReaders.auto(disordered);
        assertEquals("read as jFuzzyLogic: DEFUZZIFY statements out of order at line 12, RULEBLOCK settings out of order"
                + " at line 18", d.explanation());
        assertTrue(read(d.reader(), disordered).functionBlocks().size() == 1);
    }

    /** As many signs of jFuzzyLogic as of fuzzylite: a located FCL-S311 naming both, never a guess. */
    @Test
    void aCloseCallAsksForDialect() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT
                  a : REAL;
                END_VAR
                FUZZIFY a
                  TERM x := trian 0 1 2;
                  TERM y := Triangle 0 1 2;
                END_FUZZIFY
                END_FUNCTION_BLOCK
                """;
        DialectReaders.Choice c = DialectReaders.auto(text);
        assertTrue(c.unsure(), c.explanation());
        List<Diagnostic> d = c.reader().read("t.fcl", text).diagnostics();
        assertEquals(1, d.size());
        assertEquals("FCL-S311", d.get(0).code());
        assertEquals(6, d.get(0).location().line());
        assertTrue(d.get(0).message().contains("--dialect jfuzzylogic") && d.get(0).message().contains("--dialect fuzzylite"),
                d.get(0).message());
    }

    /**
     * An output without METHOD and DEFAULT, and nothing else outside the standard: FFLL's programs leave them out too,
     * but FFLL loads none without RANGE comments, so this is jFuzzyLogic's, with its DEFAULT NC (issue 13: two
     * jFuzzyLogic test files were read as FFLL and converted with DEFAULT := 0). With RANGE comments the absences
     * count for both, and FFLL's comments decide.
     */
    @Test
    void noMethodAndNoDefaultAreJFuzzyLogicsUnlessTheTextHasRangeComments() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT
                  t : REAL;
                END_VAR
                VAR_OUTPUT
                  v : REAL;
                END_VAR
                FUZZIFY t
                  TERM cold := (0, 1) (10, 0);
                END_FUZZIFY
                DEFUZZIFY v
                  TERM shut := 0;
                END_DEFUZZIFY
                RULEBLOCK No1
                  ACCU : MAX;
                  RULE 1 : IF t IS cold THEN v IS shut;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        DialectReaders.Choice c = DialectReaders.auto(text);
        assertEquals("read as jFuzzyLogic: no METHOD at line 11, no DEFAULT at line 11", c.explanation());
        Program p = read(c.reader(), text);
        assertTrue(p.functionBlocks().get(0).defuzzifications().get(0).defaultValue().orElseThrow()
                instanceof DefaultValue.NoChange);
        String ffll = text.replace("  t : REAL;", "  t : REAL; (* RANGE(0 .. 10) *)").replace("  v : REAL;",
                "  v : REAL; (* RANGE(0 .. 10) *)");
        assertEquals(Dialect.FFLL, DialectReaders.auto(ffll).dialect(), DialectReaders.auto(ffll).explanation());
    }

    /** A detector's failure is reported, never taken for 'no evidence' (which would read the file as strict). */
    @Test
    void aFailingDetectorIsAnErrorNotStrict() {
        LibraryDialect broken = new FuzzyliteDialect() {
            @Override
            List<DialectReader.Giveaway> giveaways(Giveaways.Scan scan) {
                throw new IndexOutOfBoundsException("bug");
            }
        };
        IllegalStateException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalStateException.class,
                () -> Giveaways.find("FUNCTION_BLOCK f END_FUNCTION_BLOCK", broken));
        assertTrue(e.getMessage().contains("fuzzylite"));
        LibraryDialect brokenReader = new FuzzyliteDialect() {
            @Override
            String defuzzifyStatements() {
                throw new IllegalStateException("bug");
            }
        };
        var r = DialectParser.read("t.fcl", "FUNCTION_BLOCK f\nDEFUZZIFY y\n  BOGUS;\nEND_DEFUZZIFY\nEND_FUNCTION_BLOCK\n",
                brokenReader);
        assertTrue(r.program().isEmpty());
        assertTrue(r.diagnostics().stream().anyMatch(d -> d.code().equals("FCL-S999")), r.diagnostics()::toString);
    }
}
