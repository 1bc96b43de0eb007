package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.junit.jupiter.api.Test;

/**
 * The FLL and FIS readers on programs of our own in the libraries' style, their values worked out by hand, and
 * their errors located on the file's lines.
 */
class EngineFormatsReaderTest {
    private static Program read(Dialect d, String text) {
        Analysis a = Analysis.analyze(d.reader(), "t." + d.cliName(), text);
        assertTrue(a.program().isPresent(), () -> a.diagnostics().toString());
        return a.program().get();
    }

    private static double eval(Program p, String output, double... inputs) throws Exception {
        FunctionBlockInstance x = Evaluator.load(p).newInstance();
        List<String> names = p.functionBlocks().get(0).variables(org.fclcert.model.VariableKind.INPUT).stream()
                .map(org.fclcert.model.Variable::name).toList();
        for (int i = 0; i < inputs.length; i++) {
            x.set(names.get(i), inputs[i]);
        }
        x.evaluate();
        return x.outputs().get(output);
    }

    /**
     * A Sugeno FIS of our own: trapmf, a negated antecedent, an OR rule (connective 2), a weight. At temp = 20:
     * cold = trapmf [-10 0 10 25] = (25 - 20)/15 = 1/3. Rule 1 (cold -> high = 80): 1/3. Rule 2 (temp is not cold
     * or sun is bright -> low = 20, weight 0.5): at sun = 0.2, bright = trimf [0 1 2] = 0.2, so max(2/3, 0.2) x 0.5
     * = 1/3. Weighted average: (1/3 x 80 + 1/3 x 20) / (2/3) = 50.
     */
    @Test
    void aSugenoFisMeansWhatMatlabSays() throws Exception {
        String fis = """
                [System]
                Name='heater'
                Type='sugeno'
                NumInputs=2
                NumOutputs=1
                NumRules=2
                AndMethod='min'
                OrMethod='max'
                ImpMethod='prod'
                AggMethod='sum'
                DefuzzMethod='wtaver'

                [Input1]
                Name='temp'
                Range=[-10 40]
                NumMFs=1
                MF1='cold':'trapmf',[-10 0 10 25]

                [Input2]
                Name='sun'
                Range=[0 1]
                NumMFs=1
                MF1='bright':'trimf',[0 1 2]

                [Output1]
                Name='power'
                Range=[0 100]
                NumMFs=2
                MF1='high':'constant',[80]
                MF2='low':'constant',[20]

                [Rules]
                1 0, 1 (1) : 1
                -1 1, 2 (0.5) : 2
                """;
        Program p = read(Dialect.FIS, fis);
        assertEquals(50.0, eval(p, "power", 20, 0.2), 1e-12);
        // sun = 0.9: rule 2 = max(2/3, 0.9) x 0.5 = 0.45; (1/3 x 80 + 0.45 x 20) / (1/3 + 0.45)
        assertEquals((80.0 / 3 + 9) / (1.0 / 3 + 0.45), eval(p, "power", 20, 0.9), 1e-12);
    }

    /** gaussmf is written [sigma c], fuzzylite's Gaussian c sigma: at x = 3, exp(-(3-1)^2 / (2 x 2^2)) = e^-0.5. */
    @Test
    void fisParametersAreReorderedToTheShapesOwn() throws Exception {
        Program p = read(Dialect.FIS, """
                [System]
                Name='g'
                Type='sugeno'
                NumInputs=1
                NumOutputs=1
                [Input1]
                Name='x'
                Range=[-5 5]
                MF1='near':'gaussmf',[2 1]
                MF2='far':'trimf',[100 200 300]
                [Output1]
                Name='y'
                Range=[0 10]
                MF1='ten':'constant',[10]
                MF2='zero':'constant',[0]
                [Rules]
                1, 1 (1) : 1
                -1, 2 (1) : 1
                """);
        double mu = Math.exp(-0.5);
        // (mu x 10 + (1 - mu) x 0) / (mu + 1 - mu) = 10 mu
        assertEquals(10 * mu, eval(p, "y", 3), 1e-12);
    }

    /**
     * An FLL Mamdani engine, max accumulation, centroid (fclcert's exact CoG). At x = 0.25 only 'low' fires, at
     * degree 1 ('low' Triangle 0 0.25 0.5): the accumulated set is the output's term 'dim' Triangle 0 0.25 0.5,
     * whose centroid is 0.25.
     */
    @Test
    void anFllEngineMeansWhatFuzzyliteSays() throws Exception {
        String fll = """
                # a dimmer of our own
                Engine: my dimmer
                InputVariable: x
                  enabled: true
                  range: 0.000 1.000
                  term: low Triangle 0.000 0.250 0.500
                  term: high Ramp 0.400 1.000
                OutputVariable: y
                  enabled: true
                  range: 0.000 1.000
                  aggregation: Maximum
                  defuzzifier: Centroid 200
                  default: nan
                  term: dim Triangle 0.000 0.250 0.500
                  term: bright Triangle 0.500 0.750 1.000
                RuleBlock: rules
                  conjunction: none
                  disjunction: none
                  implication: Minimum
                  activation: General
                  rule: if x is low then y is dim
                  rule: if x is high then y is bright
                """;
        Program p = read(Dialect.FLL, fll);
        assertEquals("my_dimmer", p.functionBlocks().get(0).name());
        assertEquals(0.25, eval(p, "y", 0.25), 1e-12);
        // at x = 1: only 'high' (degree 1): bright's centroid 0.75
        assertEquals(0.75, eval(p, "y", 1.0), 1e-12);
    }

    /**
     * The checks' findings on an engine file stand on the file's lines, never past a line's end: the restatement puts
     * the END_… of the section before on the line that opens the next (here "END_DEFUZZIFY RULEBLOCK r", so RULEBLOCK
     * stood at column 15 of a 12-character line) and the variables' declarations before the first section, and those
     * columns are not the file's. A rule block with no aggregation anywhere has no ACCU (FCL-C018): reported where the
     * file writes "RuleBlock:", line 16, column 1.
     */
    @Test
    void checkFindingsStayOnTheFilesLines() {
        String fll = """
                Engine: tipper
                InputVariable: service
                  enabled: true
                  range: 0.000 10.000
                  term: poor Triangle 0.000 2.500 5.000
                  term: good Triangle 2.500 5.000 7.500
                  term: excellent Triangle 5.000 7.500 10.000
                InputVariable: food
                  range: 0.000 10.000
                  term: rancid Ramp 5.000 0.000
                OutputVariable: tip
                  range: 0.000 30.000
                  defuzzifier: Centroid 100
                  term: low Triangle 0.000 5.000 10.000
                  term: high Triangle 10.000 20.000 30.000
                RuleBlock: r
                  conjunction: Minimum
                  implication: Minimum
                  rule: if service is poor or food is rancid then tip is low
                  rule: if service is good then tip is high
                """;
        Analysis a = Analysis.analyze(Dialect.FLL.reader(), "tip.fll", fll);
        List<String> lines = fll.lines().toList();
        List<Diagnostic> c018 = a.diagnostics().stream().filter(d -> d.code().equals("FCL-C018")).toList();
        assertEquals(1, c018.size(), a.diagnostics().toString());
        assertEquals("tip.fll:16:1", c018.get(0).location().toString());
        // 'excellent' is used by no rule (FCL-W001): on its own line 7
        assertTrue(a.diagnostics().stream().anyMatch(d -> d.code().equals("FCL-W001") && d.location().line() == 7),
                a.diagnostics().toString());
        for (Diagnostic d : a.diagnostics()) {
            String line = lines.get(d.location().line() - 1);
            assertTrue(d.location().column() >= 1 && d.location().column() <= line.length(),
                    () -> d + " is not within its line '" + line + "'");
        }
        // the variables stand where the file declares them, the fuzzification of the first input on its own line
        org.fclcert.model.FunctionBlock fb = a.program().map(p -> p.functionBlocks().get(0))
                .orElseGet(() -> Dialect.FLL.reader().read("tip.fll", fll).program().get().functionBlocks().get(0));
        assertEquals(List.of("tip.fll:2:1", "tip.fll:8:1", "tip.fll:11:1"),
                fb.variables().stream().map(v -> v.location().toString()).toList());
        assertEquals("tip.fll:2:1", fb.fuzzifications().get(0).location().toString());
        assertEquals("tip.fll:8:1", fb.fuzzifications().get(1).location().toString());
        assertEquals("tip.fll:11:1", fb.defuzzifications().get(0).location().toString());
    }

    @Test
    void errorsAreLocatedOnTheFilesOwnLines() {
        Analysis fll = Analysis.analyze(Dialect.FLL.reader(), "bad.fll", """
                Engine: e
                InputVariable: x
                  range: 0 one
                  term: a Wobble 1 2
                """);
        List<Diagnostic> d = fll.diagnostics();
        assertTrue(fll.program().isEmpty());
        assertEquals("bad.fll:3:3", d.get(0).location().toString(), d.toString());
        assertEquals("FCL-S305", d.get(0).code());
        assertEquals("bad.fll:4:3", d.get(1).location().toString());
        assertEquals("FCL-S307", d.get(1).code());

        Analysis fis = Analysis.analyze(Dialect.FIS.reader(), "bad.fis", """
                [System]
                Name='s'
                NumInputs=1
                NumOutputs=1
                [Input1]
                Name='x'
                Range=[0 1]
                MF1='a':'wobblemf',[0 1]
                [Output1]
                Name='y'
                Range=[0 1]
                MF1='b':'trimf',[0 1]
                [Rules]
                3, 1 (1) : 1
                """);
        assertTrue(fis.program().isEmpty());
        List<String> where = fis.diagnostics().stream().map(x -> x.location().line() + " " + x.code()).toList();
        assertEquals(List.of("8 FCL-S307", "12 FCL-S305", "14 FCL-S305"), where);
    }

    @Test
    void autoTellsTheFormatsApart() {
        assertEquals(Dialect.FIS, DialectReaders.auto("[System]\nName='x'\n").dialect());
        assertEquals(Dialect.FLL, DialectReaders.auto("Engine: x\nInputVariable: a\n  term: t Triangle 0 1 2\n").dialect());
        assertEquals(Dialect.STRICT, DialectReaders.auto("FUNCTION_BLOCK f END_FUNCTION_BLOCK").dialect());
    }
}
