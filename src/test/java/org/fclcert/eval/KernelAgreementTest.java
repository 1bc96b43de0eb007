package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.IntStream;
import org.fclcert.check.Analysis;
import org.fclcert.fuzz.FuzzSettings;
import org.fclcert.fuzz.Fuzzer;
import org.fclcert.fuzz.ProgramGenerator;
import org.fclcert.fuzz.ReferenceProgram;
import org.fclcert.fuzz.VectorGenerator;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.junit.jupiter.api.Test;

/**
 * Issue 24: the three evaluations agree — the interpreter ({@link FunctionBlockInstance} without its kernel), the
 * compiled kernel ({@link KernelCompiler}; the same instance class with the kernel taken from the first step) and
 * the exact path ({@link ExactInstance}) — on programs of the two generators built to sit on decision points:
 * {@link FastExactAgreementTest.Gen} (coarse grids: clip levels at vertices, tied maxima, degrees exactly 0, ½ or
 * 1, CoGS on .5) and the fuzzer's {@link ProgramGenerator} with {@link VectorGenerator}'s candidate steps
 * unjudged. Every step, from the same state: the interpreter and the compiled kernel give the same error code or
 * the same outputs, bounds, term degrees, contributions and fallbacks <em>bit for bit</em>, and the
 * same first undecided decision; the exact path the same
 * error code and every output within the bound plus the exact value's rounding (so the same DEFAULT, the same INT
 * values). No exemption. The counts (programs and steps the kernel ran, outputs it computed whole, steps that fell
 * back to exact arithmetic) are printed and asserted, so that the test cannot pass by compiling nothing.
 */
class KernelAgreementTest {
    private static final int PROGRAMS = Integer.getInteger("fclcert.kernelPrograms", 5_000);
    private static final CanonicalWriter WRITER = new CanonicalWriter();

    private static final class Counts {
        final AtomicLong programs = new AtomicLong();
        final AtomicLong compiledPrograms = new AtomicLong();
        final AtomicLong steps = new AtomicLong();
        final AtomicLong compiledSteps = new AtomicLong();
        final AtomicLong wholeSteps = new AtomicLong();
        final AtomicLong fallbacks = new AtomicLong();
        final AtomicLong staticSteps = new AtomicLong();

        @Override
        public String toString() {
            return programs + " programs (" + compiledPrograms + " compiled), " + steps + " steps (" + compiledSteps
                    + " by the kernel, " + wholeSteps + " of them with every output compiled, " + staticSteps
                    + " decided by the static filter; "
                    + (steps.get() - compiledSteps.get()) + " interpreted), " + fallbacks
                    + " fell back to exact arithmetic";
        }
    }

    @Test
    void interpreterKernelAndExactPathAgree() {
        List<String> wrong = new CopyOnWriteArrayList<>();
        Counts decision = new Counts();
        Counts fuzz = new Counts();
        ProgramGenerator generator = new ProgramGenerator(FuzzSettings.open());
        VectorGenerator candidates = new VectorGenerator((p, before, step) -> true);
        IntStream.range(0, PROGRAMS).parallel().forEach(p -> {
            try {
                Random rnd = new Random(24_0_61131L + p);
                FastExactAgreementTest.Gen g = new FastExactAgreementTest.Gen(rnd);
                Program program = g.program();
                List<Map<String, Double>> steps = new ArrayList<>();
                for (int s = 0; s < 4; s++) {
                    steps.add(g.vector());
                }
                run(program, steps, decision, wrong);
            } catch (RuntimeException | EvaluationException e) {
                wrong.add("decision-point program " + p + ": " + e);
            }
            try {
                Program generated = generator.generate(Fuzzer.programSeed(2424, p));
                Program program = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", WRITER.write(generated))
                        .program().orElseThrow();
                ReferenceProgram ref = new ReferenceProgram(program);
                run(program, candidates.steps(ref, new Random(p)), fuzz, wrong);
            } catch (RuntimeException | EvaluationException e) {
                wrong.add("fuzz program " + p + ": " + e);
            }
        });
        System.out.println("kernel agreement, decision-point programs: " + decision);
        System.out.println("kernel agreement, fuzzer's programs: " + fuzz);
        assertEquals(List.of(), wrong.stream().limit(3).toList(), wrong.size() + " disagreements");
        for (Counts c : List.of(decision, fuzz)) {
            assertEquals(PROGRAMS, c.programs.get());
            assertTrue(c.compiledPrograms.get() >= c.programs.get() / 4, "programs compiled: " + c);
            assertTrue(c.compiledSteps.get() >= c.steps.get() / 4, "steps by the kernel: " + c);
            assertTrue(c.fallbacks.get() > 0, "no step fell back: the test cannot tell a decision: " + c);
        }
        assertTrue(decision.wholeSteps.get() + fuzz.wholeSteps.get() > 0, "no output compiled whole");
        assertTrue(decision.staticSteps.get() + fuzz.staticSteps.get() > 0, "no step decided by the static filter");
    }

    /**
     * The kernel leaves the contributions of a rule settled by an exact 0 unwritten and clears only those it wrote in
     * the step before; a traced step runs the interpreter, which writes them all. So an instance switching between
     * the two (every third step traced) must still hold the interpreter's contributions bit for bit, on programs of
     * the decision-point generator, twelve steps each.
     */
    @Test
    void kernelAfterInterpreterAndBackAgrees() throws EvaluationException {
        int compiled = 0;
        int traced = 0;
        long kernelSteps = 0;
        for (int p = 0; p < 400; p++) {
            FastExactAgreementTest.Gen g = new FastExactAgreementTest.Gen(new Random(24_0_0_2L + p));
            LoadedProgram loaded = Evaluator.load(g.program());
            FunctionBlockInstance interpreter = loaded.newInstance();
            interpreter.interpretOnly();
            FunctionBlockInstance switching = loaded.newInstance();
            if (!switching.useKernel()) {
                continue;
            }
            compiled++;
            for (int s = 0; s < 12; s++) {
                Map<String, Double> step = g.vector();
                String a = outcome(interpreter, step, null);
                boolean trace = s % 3 == 2;
                traced += trace ? 1 : 0;
                String b = outcome(switching, step, trace ? new Trace() : null);
                assertEquals(a, b, "program " + p + " step " + s);
                double[][] x = interpreter.internals();
                double[][] y = switching.internals();
                for (int k = 0; k < x.length; k++) {
                    assertTrue(java.util.Arrays.equals(x[k], y[k]), "program " + p + " step " + s + " internals " + k
                            + ": " + java.util.Arrays.toString(x[k]) + " / " + java.util.Arrays.toString(y[k]));
                }
            }
            kernelSteps += switching.compiledEvaluations();
        }
        assertTrue(compiled >= 100, "programs compiled: " + compiled);
        assertTrue(kernelSteps >= compiled * 4L && traced > 0, kernelSteps + " steps on the kernel, " + traced + " traced");
    }

    /** The outputs and fallbacks after one step, or the error code. */
    private static String outcome(FunctionBlockInstance fb, Map<String, Double> step, Trace trace) {
        try {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                fb.set(e.getKey(), e.getValue());
            }
            fb.evaluate(trace);
            return fb.outputs() + " fallbacks " + fb.fallbacks() + " state " + java.util.Arrays.toString(fb.state());
        } catch (EvaluationException e) {
            return e.code();
        }
    }

    private static void run(Program program, List<Map<String, Double>> steps, Counts counts, List<String> wrong)
            throws EvaluationException {
        LoadedProgram loaded = Evaluator.load(program);
        FunctionBlockInstance interpreter = loaded.newInstance();
        interpreter.interpretOnly();
        FunctionBlockInstance compiled = loaded.newInstance();
        boolean covered = compiled.useKernel();
        ExactInstance exact = loaded.newExactInstance();
        counts.programs.incrementAndGet();
        if (covered) {
            counts.compiledPrograms.incrementAndGet();
        }
        boolean whole = covered;
        for (int i = 0; i < interpreter.outputNames().size(); i++) {
            whole &= compiled.kernelComputesOutput(i);
        }
        try {
            for (Map<String, Double> step : steps) {
                String problem = step(interpreter, compiled, exact, step);
                counts.steps.incrementAndGet();
                if (covered) {
                    counts.compiledSteps.incrementAndGet();
                }
                if (whole) {
                    counts.wholeSteps.incrementAndGet();
                }
                if (problem != null) {
                    wrong.add("step " + step + ": " + problem + "\n" + WRITER.write(program));
                    return;
                }
            }
        } finally {
            counts.fallbacks.addAndGet(compiled.fallbacks());
            counts.staticSteps.addAndGet(compiled.staticEvaluations());
        }
        if (compiled.compiledEvaluations() != (covered ? compiled.evaluations() : 0)) {
            wrong.add("the kernel ran " + compiled.compiledEvaluations() + " of " + compiled.evaluations()
                    + " steps\n" + WRITER.write(program));
        }
    }

    /** One step on all three from the same state; null when they agree, else what differs. */
    private static String step(FunctionBlockInstance interpreter, FunctionBlockInstance compiled, ExactInstance exact,
            Map<String, Double> step) {
        String interpreterError = null;
        String compiledError = null;
        String exactError = null;
        double[] start = null;
        try {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                interpreter.set(e.getKey(), e.getValue());
            }
            start = interpreter.state();
            interpreter.evaluate();
        } catch (EvaluationException e) {
            interpreterError = e.code();
        }
        try {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                compiled.set(e.getKey(), e.getValue());
            }
            compiled.evaluate();
        } catch (EvaluationException e) {
            compiledError = e.code();
        }
        if (!Objects.equals(interpreterError, compiledError)) {
            return "interpreter error " + interpreterError + ", compiled error " + compiledError;
        }
        if (interpreter.fallbacks() != compiled.fallbacks()
                || !Objects.equals(interpreter.lastUndecided(), compiled.lastUndecided())) {
            return "interpreter fell back " + interpreter.fallbacks() + " times, compiled " + compiled.fallbacks()
                    + " (" + interpreter.lastUndecided() + " / " + compiled.lastUndecided() + ")";
        }
        if (!java.util.Arrays.equals(interpreter.state(), compiled.state())) {
            return "state: interpreter " + java.util.Arrays.toString(interpreter.state()) + ", compiled "
                    + java.util.Arrays.toString(compiled.state());
        }
        double[][] a = interpreter.internals();
        double[][] b = compiled.internals();
        String[] what = {"term degrees", "term bounds", "contribution degrees", "weights", "contribution bounds",
            "degree bounds", "output bounds"};
        for (int k = 0; k < a.length; k++) {
            if (!java.util.Arrays.equals(a[k], b[k])) {
                return what[k] + ": interpreter " + java.util.Arrays.toString(a[k]) + ", compiled "
                        + java.util.Arrays.toString(b[k]);
            }
        }
        if (start == null) {
            return null;    // an input the interpreter refused (the compiled instance refused it alike)
        }
        try {
            exact.evaluateFrom(start);
        } catch (EvaluationException e) {
            exactError = e.code();
        }
        if (interpreterError != null || exactError != null) {
            return Objects.equals(interpreterError, exactError) ? null
                    : "reference error " + interpreterError + ", exact error " + exactError;
        }
        try {
            Map<String, Double> e = exact.outputs();
            for (Map.Entry<String, Double> o : compiled.outputs().entrySet()) {
                double want = e.get(o.getKey());
                double got = o.getValue();
                double bound = compiled.bound(o.getKey()) + Math.ulp(want);
                if (!(Math.abs(got - want) <= bound) && !(Double.isNaN(got) && Double.isNaN(want))) {
                    return o.getKey() + ": compiled " + got + ", exact " + want + ", bound " + compiled.bound(o.getKey());
                }
            }
        } catch (EvaluationException ex) {
            return ex.toString();
        }
        return null;
    }
}
