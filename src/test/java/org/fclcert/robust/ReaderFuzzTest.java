package org.fclcert.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.fclcert.write.CanonicalWriter;
import org.fclcert.write.StandardConversion;

/**
 * Coverage-guided fuzzing (Jazzer) of the readers of untrusted FCL text, with properties beyond "no
 * exception": a reader returns diagnostics and never throws nor reports an internal error (FCL-S999);
 * what the strict reader and the checks accept is written by fmt as text that reads back clean to the
 * same model (so it evaluates identically) and is a fixed point; what a dialect reader accepts converts
 * to a program that reads back strictly without errors and, where convert says it is exact, evaluates like the
 * source. {@code mvn verify} replays the committed inputs
 * under {@code src/test/resources/org/fclcert/robust/ReaderFuzzTestInputs/<method>/}; how to fuzz for a
 * budget is in docs/fuzzing-readers.md.
 */
class ReaderFuzzTest {
    private static final int MAX_TEXT = 20_000;

    @FuzzTest(maxDuration = "10m")
    void strictReaderChecksAndFmt(byte[] bytes) {
        String text = new String(bytes, java.nio.charset.StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        Analysis a = Analysis.analyze(new StrictReader(), "fuzz.fcl", text);
        assertNoInternalError(a.diagnostics());
        if (a.program().isEmpty() || a.hasErrors()) {
            return;
        }
        String written = new CanonicalWriter().write(a.program().get());
        Analysis back = Analysis.analyze(new StrictReader(), "fmt.fcl", written);
        assertFalse(back.hasErrors(), () -> "fmt output does not check clean: " + back.diagnostics() + "\n" + written);
        assertEquals(a.program().get().functionBlocks(), back.program().orElseThrow().functionBlocks(),
                "fmt changed the model");
        assertEquals(written, new CanonicalWriter().write(back.program().get()), "fmt is not a fixed point");
    }

    @FuzzTest(maxDuration = "10m")
    void dialectReadersAndConvert(byte[] bytes) {
        if (bytes.length == 0) {
            return;
        }
        Dialect[] dialects = {Dialect.FFLL, Dialect.JFUZZYLOGIC, Dialect.FUZZYLITE};
        Dialect dialect = dialects[Math.floorMod(bytes[0], dialects.length)];
        String text = new String(bytes, 1, bytes.length - 1, java.nio.charset.StandardCharsets.UTF_8);
        if (text.length() > MAX_TEXT) {
            return;
        }
        DialectReaders.Choice auto = DialectReaders.auto(text);
        assertTrue(auto.problem().stream().noneMatch(d -> d.code().equals("FCL-S999")), () -> "auto: " + auto.problem());
        FclReader reader = DialectReaders.reader(dialect);
        Analysis a = Analysis.analyze(reader, "fuzz.fcl", text);
        assertNoInternalError(a.diagnostics());
        if (a.program().isEmpty() || a.hasErrors()) {
            return;
        }
        StandardConversion.Result conversion = new StandardConversion().convert(a.program().get());
        String standard = new CanonicalWriter().write(conversion.program());
        Analysis back = Analysis.analyze(new StrictReader(), "converted.fcl", standard);
        assertFalse(back.hasErrors(), () -> dialect + ": converted program is not valid standard FCL: "
                + back.diagnostics() + "\n" + standard);
        if (conversion.exact()) {
            assertEvaluatesAlike(a.program().get(), back.program().orElseThrow(), standard);
        }
    }

    /** Inputs every input of the first block is set to, in turn: in and out of typical ranges, on term corners. */
    private static final double[] PROBES = {-1, 0, 0.25, 0.5, 1, 2.5, 10, 100};

    /**
     * The first function block of both programs, fed the same inputs in the same order, fails alike or gives the
     * same outputs (within 1e-9, relative): what convert says is exact must evaluate like the source.
     */
    private static void assertEvaluatesAlike(Program source, Program converted, String text) {
        LoadedProgram a = Evaluator.load(source);
        LoadedProgram b = Evaluator.load(converted);
        FunctionBlockInstance x = a.newInstance();
        FunctionBlockInstance y = b.newInstance();
        List<Variable> inputs = source.functionBlocks().get(0).variables(VariableKind.INPUT);
        List<Variable> outputs = source.functionBlocks().get(0).variables(VariableKind.OUTPUT);
        for (double v : PROBES) {
            String left = outcome(x, inputs, outputs, v);
            String right = outcome(y, inputs, outputs, v);
            assertTrue(alike(left, right), () -> "at " + v + ": the source gives " + left + ", the conversion "
                    + right + "\n" + text);
        }
    }

    private static String outcome(FunctionBlockInstance fb, List<Variable> inputs, List<Variable> outputs, double v) {
        try {
            for (Variable in : inputs) {
                fb.set(in.name(), v);
            }
            fb.evaluate();
            StringBuilder sb = new StringBuilder();
            for (Variable out : outputs) {
                sb.append(fb.get(out.name())).append(' ');
            }
            return sb.toString();
        } catch (EvaluationException e) {
            return "refused";
        }
    }

    private static boolean alike(String left, String right) {
        String[] l = left.split(" ");
        String[] r = right.split(" ");
        if (l.length != r.length) {
            return false;
        }
        for (int i = 0; i < l.length; i++) {
            if (l[i].equals(r[i])) {
                continue;
            }
            if (l[i].equals("refused") || r[i].equals("refused")) {
                return false;
            }
            double p = Double.parseDouble(l[i]);
            double q = Double.parseDouble(r[i]);
            if (!(Math.abs(p - q) <= 1e-9 * Math.max(1, Math.abs(p)))) {
                return false;
            }
        }
        return true;
    }

    private static void assertNoInternalError(List<Diagnostic> diagnostics) {
        for (Diagnostic d : diagnostics) {
            assertFalse(d.code().equals("FCL-S999"), () -> "internal error: " + d);
        }
    }
}
