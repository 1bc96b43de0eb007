package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.Test;

/** {@code FisWriter} on small programs: the text written by hand from the FIS format, and what it says it loses. */
class FisWriterTest {
    private static final String HEAD = """
            FUNCTION_BLOCK lamp
            VAR_INPUT x : REAL; z : REAL; END_VAR
            VAR_OUTPUT y : REAL; END_VAR
            FUZZIFY x
              TERM lo := (0, 1) (10, 0);
              TERM mid := (0, 0) (5, 1) (10, 0);
              TERM hi := (0, 0) (2, 0) (4, 1) (6, 1) (8, 0);
            END_FUZZIFY
            FUZZIFY z
              TERM on := (0, 0) (1, 1);
            END_FUZZIFY
            DEFUZZIFY y
              TERM dim := 20;
              TERM bright := 80;
              TERM full := 100;
              METHOD : COGS;
              DEFAULT := %s;
            END_DEFUZZIFY
            RULEBLOCK r
              AND : MIN;
              OR : MAX;
              ACCU : MAX;
            """;

    private static Written write(String defaultValue, String rules) {
        String fcl = HEAD.formatted(defaultValue) + rules + "END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "t.fcl", fcl);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics().toString()));
        return DialectWriters.writer(Dialect.FIS).write(p);
    }

    private static List<String> losses(Written w) {
        return w.notExpressible().stream().map(Diagnostic::code).toList();
    }

    @Test
    void shouldersTrianglesTrapezoidsNotAndOrAsMatlabWritesThem() {
        // the three rules leave no gap (rule 3 fires on [2, 8], rule 2 wherever x is not 5 or z is below 1, rule 1
        // below 10 where z is below 1), so the DEFAULT is never used and FIS's lack of one loses nothing
        Written w = write("0", """
                  RULE 1 : IF x IS lo AND NOT (z IS on) THEN y IS dim;
                  RULE 2 : IF NOT (x IS mid AND z IS on) THEN y IS bright;
                  RULE 3 : IF x IS hi THEN y IS full WITH 0.5;
                """);
        assertEquals(List.of(), losses(w));
        assertEquals("""
                [System]
                Name='lamp'
                Type='sugeno'
                Version=2.0
                NumInputs=2
                NumOutputs=1
                NumRules=3
                AndMethod='min'
                OrMethod='max'
                ImpMethod='min'
                AggMethod='max'
                DefuzzMethod='wtaver'

                [Input1]
                Name='x'
                Range=[0 10]
                NumMFs=3
                MF1='lo':'trapmf',[-1.7976931348623157E308 -8.988465674311579E307 0 10]
                MF2='mid':'trimf',[0 5 10]
                MF3='hi':'trapmf',[2 4 6 8]

                [Input2]
                Name='z'
                Range=[0 1]
                NumMFs=1
                MF1='on':'trapmf',[0 1 8.988465674311579E307 1.7976931348623157E308]

                [Output1]
                Name='y'
                Range=[20 100]
                NumMFs=3
                MF1='dim':'constant',[20]
                MF2='bright':'constant',[80]
                MF3='full':'constant',[100]

                [Rules]
                1 -1, 1 (1) : 1
                -2 -1, 2 (1) : 2
                3 0, 3 (0.5) : 1
                """, w.text());
        assertTrue(DialectWriters.readBackAndCompare(program(w), w).equal(), "read back and evaluated equal");
    }

    private static Program program(Written w) {
        return Analysis.analyze(StrictReader.openLevel(), "t.fcl", HEAD.formatted("0") + """
                  RULE 1 : IF x IS lo AND NOT (z IS on) THEN y IS dim;
                  RULE 2 : IF NOT (x IS mid AND z IS on) THEN y IS bright;
                  RULE 3 : IF x IS hi THEN y IS full WITH 0.5;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """).program().orElseThrow();
    }

    @Test
    void aDefaultUsedWhereNoRuleFiresIsLostAndOneNeverUsedIsNot() {
        // lo alone (1 below 0, 0 from 10 on) leaves every x >= 10 uncovered: there FIS gives NaN, not the DEFAULT
        assertEquals(List.of("FCL-X111"), losses(write("0", "  RULE 1 : IF x IS lo THEN y IS dim;\n")));
        // lo, and NOT lo (1 - lo, 1 from 10 on): one of the two is positive for every x
        assertEquals(List.of(), losses(write("0", """
                  RULE 1 : IF x IS lo THEN y IS dim;
                  RULE 2 : IF x IS NOT lo THEN y IS bright;
                """)));
    }

    @Test
    void aRuleMixingAndWithOrOrNamingAnInputTwiceIsLeftOutAndSaidSo() {
        Written mixed = write("0", "  RULE 1 : IF (x IS lo OR x IS mid) AND z IS on THEN y IS dim;\n");
        assertEquals("FCL-X109", losses(mixed).get(0));
        assertTrue(mixed.notExpressible().get(0).message().contains("mixes AND and OR"));
        Written twice = write("0", "  RULE 1 : IF x IS lo AND x IS mid THEN y IS dim;\n");
        assertEquals("FCL-X109", losses(twice).get(0));
        assertTrue(twice.notExpressible().get(0).message().contains("names input 'x' twice"));
    }
    /**
     * What the Octave toolkit computes otherwise for named shapes it has (measured against it in EngineShapesTest):
     * its dsigmf clamps f1 - f2 at 0 where fuzzylite, and fclcert's reading, take |f1 - f2| (left 2, rising 2,
     * falling 0.5, right -2: f2 - f1 peaks at 0.72991 near x = 0.4794, found by a golden-section search in Python);
     * equal slopes with left below right never cross; and its gbellmf refuses a b that is no integer.
     */
    @Test
    void octavesOwnFormulasOfDsigmfAndGbellmfAreSaid() {
        String fcl = """
                FUNCTION_BLOCK shapes
                VAR_INPUT
                  x: REAL;
                END_VAR
                VAR_OUTPUT
                  y: REAL;
                END_VAR
                FUZZIFY x
                  RANGE := (-10.000 .. 10.000);
                  TERM d := SigmoidDifference 2.000 2.000 0.500 -2.000;
                  TERM e := SigmoidDifference 2.000 3.000 3.000 7.000;
                  TERM b := Bell 5.000 2.000 2.500;
                  TERM c := Bell 5.000 2.000 3.000;
                END_FUZZIFY
                DEFUZZIFY y
                  RANGE := (0.000 .. 1.000);
                  TERM one := 1.000;
                  METHOD : COGS;
                  ACCU : MAX;
                  DEFAULT := nan;
                END_DEFUZZIFY
                RULEBLOCK rules
                  RULE 1 : if x is d then y is one
                  RULE 2 : if x is e then y is one
                  RULE 3 : if x is b then y is one
                  RULE 4 : if x is c then y is one
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = Analysis.analyze(new org.fclcert.syntax.dialect.FuzzyliteReader(), "s.fcl", fcl);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics().toString()));
        Written w = DialectWriters.writer(Dialect.FIS).write(p);
        assertTrue(w.text().contains("MF1='d':'dsigmf',[2 2 0.5 -2]"), w.text());
        assertTrue(w.text().contains("MF3='b':'gbellmf',[2 2.5 5]"), w.text());
        List<String> said = w.differences().stream().filter(d -> d.code().equals("FCL-X212")
                || d.message().contains("gbellmf")).map(d -> d.code() + " " + d.message()).toList();
        assertEquals(2, said.size(), said.toString());
        assertTrue(said.get(0).startsWith("FCL-X212 sigmoid difference 'd': where its second sigmoid exceeds its first"
                + " (by up to 0.730 at 0.4") && said.get(0).endsWith("fuzzylite and fclcert take |f1 - f2|"),
                said.toString());
        assertEquals("FCL-X208 bell 'b' has slope 2.5: the Octave fuzzy-logic-toolkit 0.4.6 refuses a gbellmf whose b is"
                + " no integer", said.get(1));
    }
}
