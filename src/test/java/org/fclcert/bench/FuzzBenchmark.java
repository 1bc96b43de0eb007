package org.fclcert.bench;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.fclcert.check.Analysis;
import org.fclcert.fuzz.FuzzSettings;
import org.fclcert.fuzz.Fuzzer;
import org.fclcert.fuzz.ProgramGenerator;
import org.fclcert.fuzz.ReferenceProgram;
import org.fclcert.fuzz.VectorGenerator;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;

/**
 * Throughput of {@code fclcert fuzz}, one operation = one generated program: {@code generate} (generate, write,
 * strict read and check), {@code referenceSide} (that, plus loading on the reference, drawing and judging the
 * fair steps and evaluating them) and {@code againstIut} (that, plus loading the text on the implementation
 * and evaluating every step there), with the screened or the exact fairness judge. Basic Level programs, so that
 * the Python example IUT (Basic Level only) accepts them. Vectors per program are counted in the {@code vectors} auxiliary counter. Run as
 * docs/performance.md describes, with {@code FuzzBenchmark} as the pattern.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 2, time = 3)
@Measurement(iterations = 3, time = 3)
@Fork(1)
@State(Scope.Thread)
public class FuzzBenchmark {
    @Param({"basic", "open"})
    public String level;

    @Param({"reference", "process:python3 examples/iut/basic_iut.py"})
    public String spec;

    /** The fairness judge: {@code screened} (the default of fclcert fuzz) or {@code exact} (the exact judge alone). */
    @Param({"screened", "exact"})
    public String judge;

    private final CanonicalWriter writer = new CanonicalWriter();
    private ProgramGenerator generator;
    private VectorGenerator vectors;
    private ImplementationUnderTest iut;
    private long index;
    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory.getThreadMXBean();
    private long cpuStart;
    private long wallStart;
    private long ops;
    private long steps;

    @Setup(Level.Iteration)
    public void startIteration() {
        ops = 0;
        steps = 0;
        cpuStart = THREADS.getCurrentThreadCpuTime();
        wallStart = System.nanoTime();
    }

    /** Programs and vectors per CPU-second of the benchmark thread (the fuzzer's side only) and per wall second. */
    @TearDown(Level.Iteration)
    public void endIteration() {
        double cpu = (THREADS.getCurrentThreadCpuTime() - cpuStart) / 1e9;
        double wall = (System.nanoTime() - wallStart) / 1e9;
        System.out.printf("cpu-normalised: %.0f programs, %.0f vectors per CPU-second; wall: %.0f programs, %.0f vectors/s%n",
                ops / cpu, steps / cpu, ops / wall, steps / wall);
    }

    @Setup(Level.Trial)
    public void setUp() throws Exception {
        generator = new ProgramGenerator(new FuzzSettings(ConformanceLevel.byWord(level), java.util.Set.of()));
        vectors = new VectorGenerator(judge.equals("exact") ? new org.fclcert.fuzz.ExactFairness()
                : new org.fclcert.fuzz.ScreenedFairness());
        iut = Iuts.open(spec, IutOptions.defaults());
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        iut.close();
    }

    private Optional<Program> next(long seed) {
        String text = writer.write(generator.generate(seed));
        return Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", text).program();
    }

    @Benchmark
    public Object generate() {
        ops++;
        return next(Fuzzer.programSeed(1, index++));
    }

    @Benchmark
    public int referenceSide(Blackhole bh) throws Exception {
        long seed = Fuzzer.programSeed(1, index++);
        ReferenceProgram ref = new ReferenceProgram(next(seed).orElseThrow());
        List<Map<String, Double>> steps = vectors.steps(ref, new Random(seed));
        bh.consume(ref.run(steps));
        ops++;
        this.steps += steps.size();
        return steps.size();
    }

    @Benchmark
    public int againstIut(Blackhole bh) throws Exception {
        long seed = Fuzzer.programSeed(1, index++);
        Program p = next(seed).orElseThrow();
        ReferenceProgram ref = new ReferenceProgram(p);
        List<Map<String, Double>> steps = vectors.steps(ref, new Random(seed));
        bh.consume(ref.run(steps));
        iut.load(writer.write(p));
        iut.reset();
        for (Map<String, Double> s : steps) {
            bh.consume(iut.eval(null, s));
        }
        ops++;
        this.steps += steps.size();
        return steps.size();
    }
}
