package org.fclcert.bench;

import static org.fclcert.eval.Fcl.and;
import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.num;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.concurrent.TimeUnit;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.Fcl;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefuzzificationMethod;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Throughput of one evaluation (set inputs, evaluate, read the output) on one thread.
 * Run as documented in docs/performance.md; not part of the test suite.
 *
 * <p>Besides JMH's wall-clock score, each measurement iteration prints the evaluations per second
 * of CPU time of the benchmark thread ({@code cpu-normalised}): on a machine shared with other
 * work the wall-clock score reports the share of a core the thread got, the CPU-time figure what
 * one core does.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
@State(Scope.Thread)
public class EvaluationBenchmark {
    /** Operating points cycled through, so that the work is not one constant branch pattern. */
    private static final double[][] VALVE_INPUTS = {{5, 60}, {15, 75}, {21, 65}, {9, 85}, {5, 90}, {26, 58}};
    private static final double[] COG_INPUTS = {1.5, 3.2, 4.9, 5.0, 6.7, 8.8, 2.4, 7.1};

    private FunctionBlockInstance valve;
    private FunctionBlockInstance cog;
    /** The same two programs on the exact judging path (BigInteger rationals). */
    private ExactInstance valveExact;
    private ExactInstance cogExact;
    private int i;
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private long calls;
    private long cpuStart;

    @Setup(Level.Iteration)
    public void startIteration() {
        calls = 0;
        cpuStart = THREADS.getCurrentThreadCpuTime();
    }

    @TearDown(Level.Iteration)
    public void endIteration() {
        // iteration set-up and tear-down run on the benchmark thread (JMH guarantees it for Scope.Thread)
        double seconds = (THREADS.getCurrentThreadCpuTime() - cpuStart) / 1e9;
        System.out.printf("cpu-normalised: %.0f ops per CPU-second%n", calls / seconds);
    }

    @Setup
    public void setUp() throws EvaluationException {
        Fcl.Block valveBlock = Fcl.block("Fuzzy_FB").input("temp").input("pressure").output("valve")
                .fuzzify("temp", Fcl.term("cold", pts(3, 1, 27, 0)), Fcl.term("hot", pts(3, 0, 27, 1)))
                .fuzzify("pressure", Fcl.term("low", pts(55, 1, 95, 0)), Fcl.term("high", pts(55, 0, 95, 1)))
                .defuzzify(Fcl.defuzzify("valve", DefuzzificationMethod.COGS)
                        .term("drainage", single(-100)).term("closed", single(0)).term("inlet", single(100))
                        .defaultValue(0))
                .rules(Fcl.ruleBlock("No1").and(AndAlgorithm.MIN).accu(AccumulationMethod.MAX)
                        .rule(and(is("temp", "cold"), is("pressure", "low")), then("valve", "inlet"))
                        .rule(and(is("temp", "cold"), is("pressure", "high")), then("valve", "closed", num(0.8)))
                        .rule(and(is("temp", "hot"), is("pressure", "low")), then("valve", "closed"))
                        .rule(and(is("temp", "hot"), is("pressure", "high")), then("valve", "drainage")));
        valve = valveBlock.instance();
        valveExact = Evaluator.load(valveBlock.program()).newExactInstance();
        Fcl.Block cogBlock = Fcl.block("cog3").input("x").output("y")
                .fuzzify("x", Fcl.term("low", pts(0, 0, 2, 1, 5, 0)), Fcl.term("mid", pts(2, 0, 5, 1, 8, 0)),
                        Fcl.term("high", pts(5, 0, 8, 1, 10, 0)))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COG).range(0, 100)
                        .term("small", pts(0, 0, 20, 1, 40, 0)).term("medium", pts(30, 0, 50, 1, 70, 0))
                        .term("large", pts(60, 0, 80, 1, 100, 0)).defaultValue(0))
                .rules(Fcl.ruleBlock("r").and(AndAlgorithm.MIN).act(ActivationMethod.MIN).accu(AccumulationMethod.MAX)
                        .rule(is("x", "low"), then("y", "small"))
                        .rule(is("x", "mid"), then("y", "medium"))
                        .rule(is("x", "high"), then("y", "large")));
        cog = cogBlock.instance();
        cogExact = Evaluator.load(cogBlock.program()).newExactInstance();
        // the measured code computes exact results: 9500/127 (5.3 at temp 5, pressure 60) and, at
        // x = 5 where only "mid" fires, the CoG of the symmetric triangle "medium", 50
        expect(9500.0 / 127, valve, "valve", new String[] {"temp", "pressure"}, 5, 60);
        expect(50.0, cog, "y", new String[] {"x"}, 5);
        valveExact.set("temp", 5);
        valveExact.set("pressure", 60);
        valveExact.evaluate();
        cogExact.set("x", 5);
        cogExact.evaluate();
        if (valveExact.get("valve") != 9500.0 / 127 || cogExact.get("y") != 50.0) {
            throw new IllegalStateException("exact path: " + valveExact.get("valve") + ", " + cogExact.get("y"));
        }
    }

    private static void expect(double expected, FunctionBlockInstance fb, String output, String[] inputs,
            double... values) throws EvaluationException {
        for (int k = 0; k < inputs.length; k++) {
            fb.set(inputs[k], values[k]);
        }
        fb.evaluate();
        if (Math.abs(fb.get(output) - expected) > 1e-12 * Math.abs(expected)) {
            throw new IllegalStateException(output + " = " + fb.get(output) + ", expected " + expected);
        }
    }

    @Benchmark
    public double valveSingletonsCogs() throws EvaluationException {
        calls++;
        double[] in = VALVE_INPUTS[i++ % VALVE_INPUTS.length];
        valve.set("temp", in[0]);
        valve.set("pressure", in[1]);
        valve.evaluate();
        return valve.get("valve");
    }

    @Benchmark
    public double valveSingletonsCogsExact() throws EvaluationException {
        calls++;
        double[] in = VALVE_INPUTS[i++ % VALVE_INPUTS.length];
        valveExact.set("temp", in[0]);
        valveExact.set("pressure", in[1]);
        valveExact.evaluate();
        return valveExact.get("valve");
    }

    @Benchmark
    public double threeRuleTriangularCogExact() throws EvaluationException {
        calls++;
        cogExact.set("x", COG_INPUTS[i++ % COG_INPUTS.length]);
        cogExact.evaluate();
        return cogExact.get("y");
    }

    @Benchmark
    public double threeRuleTriangularCog() throws EvaluationException {
        calls++;
        cog.set("x", COG_INPUTS[i++ % COG_INPUTS.length]);
        cog.evaluate();
        return cog.get("y");
    }
}
