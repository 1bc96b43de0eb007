package org.fclcert.bench;

import com.fuzzylite.Engine;
import com.fuzzylite.imex.FclImporter;
import com.fuzzylite.variable.InputVariable;
import com.fuzzylite.variable.OutputVariable;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.ToDoubleFunction;
import org.fclcert.check.Analysis;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * fclcert side by side with jfuzzylite 6.0.1 (and, for reading, jFuzzyLogic) in one JMH run, on the same
 * programs ({@link PeerPrograms}, each in the layout its reader needs) and the same cycle of operating
 * points. An evaluation is: set every input, evaluate, read the output, with names resolved once on both
 * sides (fclcert's {@link FunctionBlockInstance} sets its inputs in declaration order and reads its output by
 * index, jfuzzylite sets each of its input variable objects). Reading is the
 * whole front end: fclcert's strict reader and all checks (every diagnostic), jfuzzylite's FclImporter
 * building an Engine, jFuzzyLogic's FIS.createFromString.
 *
 * <p>At set-up each side's outputs over the cycle are compared with {@link ExactValues} and the largest
 * error is printed ({@code exactness:} lines). Every iteration also prints operations per CPU-second of
 * the benchmark thread ({@code cpu-normalised:}), the stable figure on a shared machine. Run as
 * documented in docs/performance.md; not part of the test suite. Eight seconds of warm-up: with three, the
 * readers of both sides were still speeding up through the measured iterations (the JIT was not done).
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 8, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(value = 1, jvmArgsAppend = "-Xmx1g")
@State(Scope.Thread)
public class PeerComparisonBenchmark {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private static final com.sun.management.OperatingSystemMXBean PROCESS =
            (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();

    private String valveText;
    private String valvePeerText;
    private String rulesText;
    private String rulesPeerText;
    private int i;
    private long calls;
    private long cpuStart;
    private long processStart;

    /** One engine with its inputs resolved, evaluated over one cycle of operating points. */
    interface Side {
        double step(double[] in) throws Exception;
    }

    /**
     * fclcert's side: the reference (the interpreter, the compiled kernel from its 65th evaluation) with names
     * resolved once. A final class (not a lambda) for both sides, so
     * that the benchmark methods call {@code step} directly and the JIT treats both libraries alike.
     */
    static final class Reference implements Side {
        private final FunctionBlockInstance fb;
        private final int out;

        Reference(String text) throws EvaluationException {
            Analysis a = Analysis.analyze(StrictReader.openLevel(), "<bench>", text);
            Program p = a.program().orElseThrow(() -> new IllegalStateException("fclcert rejects: " + a.diagnostics()));
            fb = Evaluator.load(p).newInstance();
            out = fb.outputIndex(fb.outputNames().get(0));
        }

        /** {@code v} in the inputs' declaration order (as the operating points are; the exactness check tells). */
        @Override
        public double step(double[] v) throws EvaluationException {
            fb.setInputs(v);
            fb.evaluate();
            return fb.output(out);
        }

        /** The evaluations so far: how many fell back to exact arithmetic, ran the kernel, the static filter decided. */
        String counts() {
            return fb.fallbacks() + " of " + fb.evaluations() + " evaluations redone in exact arithmetic; "
                    + fb.compiledEvaluations() + " ran as the compiled kernel, " + fb.staticEvaluations()
                    + " of them decided by the static filter";
        }

        /** Runs the cycle a while before the exactness check at set-up (and to count the exact fallbacks). */
        Reference warm(double[][] cycle) throws EvaluationException {
            for (int k = 0; k < 2500; k++) {
                step(cycle[k % cycle.length]);
            }
            return this;
        }
    }

    /** jfuzzylite's side: its Engine with the input variables looked up once. */
    static final class Jfuzzylite implements Side {
        private final Engine engine;
        private final InputVariable[] in;
        private final OutputVariable out;

        Jfuzzylite(String text, String... inputs) {
            engine = new FclImporter().fromString(text);
            in = new InputVariable[inputs.length];
            for (int k = 0; k < inputs.length; k++) {
                in[k] = engine.getInputVariable(inputs[k]);
            }
            out = engine.getOutputVariable(0);
        }

        @Override
        public double step(double[] v) {
            for (int k = 0; k < in.length; k++) {
                in[k].setValue(v[k]);
            }
            engine.process();
            return out.getValue();
        }
    }

    @Setup
    public void setUp() {
        valveText = PeerPrograms.valveStandard();
        valvePeerText = PeerPrograms.valveFuzzylite();
        rulesText = PeerPrograms.rules125(false);
        rulesPeerText = PeerPrograms.rules125(true);
    }

    /** One program on both sides: fclcert warmed, and both checked for exactness at set-up. */
    static final class Sides {
        final Reference ref;
        final Jfuzzylite peer;

        Sides(String program, String standard, Jfuzzylite peer, double[][] cycle, ToDoubleFunction<double[]> exact)
                throws Exception {
            this.ref = new Reference(standard).warm(cycle);
            this.peer = peer;
            exactness(program, cycle, exact, ref, peer);
            // the reference's exact fallback is on: how many of the warm-up evaluations needed it
            System.out.println("fallbacks: " + program + " " + ref.counts());
        }
    }

    /**
     * The valve on both sides. A state per program, so that each benchmark's JVM (one fork per benchmark) has
     * run only the program it measures: the call sites the programs share (fclcert's evaluator,
     * jfuzzylite's engine) then see no other program's types.
     */
    @State(Scope.Thread)
    public static class Valve {
        Sides sides;

        @Setup
        public void setUp() throws Exception {
            sides = new Sides("valve", PeerPrograms.valveStandard(),
                    new Jfuzzylite(PeerPrograms.valveFuzzylite(), "temp", "pressure"), PeerPrograms.VALVE_INPUTS,
                    v -> ExactValues.valve(v[0], v[1]));
        }
    }

    /** The three-rule CoG program on both sides (see {@link Valve}). */
    @State(Scope.Thread)
    public static class Cog3 {
        Sides sides;

        @Setup
        public void setUp() throws Exception {
            sides = new Sides("cog3", PeerPrograms.cog3Standard(), new Jfuzzylite(PeerPrograms.cog3Fuzzylite(), "x"),
                    PeerPrograms.COG3_INPUTS, v -> ExactValues.cog3(v[0]));
        }
    }

    /** The 125-rule program on both sides (see {@link Valve}). */
    @State(Scope.Thread)
    public static class Rules125 {
        Sides sides;

        @Setup
        public void setUp() throws Exception {
            sides = new Sides("rules125", PeerPrograms.rules125(false),
                    new Jfuzzylite(PeerPrograms.rules125(true), PeerPrograms.INPUTS125), PeerPrograms.RULES125_INPUTS,
                    v -> ExactValues.rules125(v[0], v[1], v[2]));
        }
    }

    /** Prints, per side, the largest |output − exact| over the cycle (and in units of the last place). */
    static String exactness(String program, double[][] inputs, ToDoubleFunction<double[]> exact, Side ref, Side peer)
            throws Exception {
        StringBuilder s = new StringBuilder("exactness: " + program);
        String[] names = {"fclcert", "jfuzzylite"};
        Side[] sides = {ref, peer};
        for (int k = 0; k < 2; k++) {
            double worst = 0;
            double worstUlps = 0;
            String where = "";
            for (double[] in : inputs) {
                double want = exact.applyAsDouble(in);
                double got = sides[k].step(in);
                double err = Math.abs(got - want);
                if (!(err <= worst)) {
                    worst = err;
                    worstUlps = err / Math.ulp(want);
                    where = java.util.Arrays.toString(in) + " gives " + got + " for " + want;
                }
            }
            s.append(String.format(Locale.ROOT, "; %s max |error| %.3g (%.1f ulp)%s", names[k], worst, worstUlps,
                    worst > 0 ? " at " + where : ""));
        }
        System.out.println(s);
        return s.toString();
    }

    @Setup(Level.Iteration)
    public void startIteration() {
        calls = 0;
        cpuStart = THREADS.getCurrentThreadCpuTime();
        processStart = PROCESS.getProcessCpuTime();
    }

    /**
     * Prints operations per CPU-second of the benchmark thread ({@code cpu-normalised}) and of the whole JVM
     * ({@code process-cpu-normalised}: the garbage collector's and the JIT's threads too, so that a library
     * that allocates pays for collecting it).
     */
    @TearDown(Level.Iteration)
    public void endIteration() {
        double seconds = (THREADS.getCurrentThreadCpuTime() - cpuStart) / 1e9;
        double process = (PROCESS.getProcessCpuTime() - processStart) / 1e9;
        System.out.printf(Locale.ROOT, "cpu-normalised: %.0f ops per CPU-second; process-cpu-normalised: %.0f ops "
                + "per process CPU-second%n", calls / seconds, calls / process);
    }

    private double[] next(double[][] cycle) {
        calls++;
        if (++i >= cycle.length) {
            i = 0;   // no division: a modulo would cost as much as a small evaluation
        }
        return cycle[i];
    }

    // ---------------------------------------------------------------- evaluation

    @Benchmark
    public double referenceValve(Valve p) throws Exception {
        return p.sides.ref.step(next(PeerPrograms.VALVE_INPUTS));
    }

    @Benchmark
    public double jfuzzyliteValve(Valve p) throws Exception {
        return p.sides.peer.step(next(PeerPrograms.VALVE_INPUTS));
    }

    @Benchmark
    public double referenceCog3(Cog3 p) throws Exception {
        return p.sides.ref.step(next(PeerPrograms.COG3_INPUTS));
    }

    @Benchmark
    public double jfuzzyliteCog3(Cog3 p) throws Exception {
        return p.sides.peer.step(next(PeerPrograms.COG3_INPUTS));
    }

    @Benchmark
    public double referenceRules125(Rules125 p) throws Exception {
        return p.sides.ref.step(next(PeerPrograms.RULES125_INPUTS));
    }

    @Benchmark
    public double jfuzzyliteRules125(Rules125 p) throws Exception {
        return p.sides.peer.step(next(PeerPrograms.RULES125_INPUTS));
    }

    // ---------------------------------------------------------------- reading

    @Benchmark
    public Object referenceParseValve() {
        calls++;
        return Analysis.analyze(StrictReader.openLevel(), "<bench>", valveText);
    }

    @Benchmark
    public Object jfuzzyliteParseValve() {
        calls++;
        return new FclImporter().fromString(valvePeerText);
    }

    @Benchmark
    public Object referenceParseRules125() {
        calls++;
        return Analysis.analyze(StrictReader.openLevel(), "<bench>", rulesText);
    }

    @Benchmark
    public Object jfuzzyliteParseRules125() {
        calls++;
        return new FclImporter().fromString(rulesPeerText);
    }

    @Benchmark
    public Object jfuzzylogicParseValve(JFuzzyLogic j) throws Throwable {
        calls++;
        return j.create.invoke(valveText, false);
    }

    @Benchmark
    public Object jfuzzylogicParseRules125(JFuzzyLogic j) throws Throwable {
        calls++;
        return j.create.invoke(rulesText, false);
    }

    /**
     * jFuzzyLogic's reader, present only when its jar is on the class path (the pom's jfuzzylogic profiles);
     * without it these benchmarks fail at set-up with that reason and the others run.
     */
    @State(Scope.Benchmark)
    public static class JFuzzyLogic {
        MethodHandle create;

        @Setup
        public void find() throws Throwable {
            Class<?> fis;
            try {
                fis = Class.forName("net.sourceforge.jFuzzyLogic.FIS");
            } catch (ClassNotFoundException e) {
                throw new IllegalStateException("jFuzzyLogic is not on the class path (its jar is not in "
                        + "../shared/peers/jfuzzylogic or /work/shared/peers/jfuzzylogic)", e);
            }
            create = MethodHandles.publicLookup().findStatic(fis, "createFromString",
                    MethodType.methodType(fis, String.class, boolean.class));
            Object system = create.invoke(PeerPrograms.valveStandard(), false);
            if (system == null) {
                throw new IllegalStateException("jFuzzyLogic does not read the valve program");
            }
        }
    }
}
