package org.fclcert.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
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

/**
 * Cost of one {@code eval} through the implementation-under-test layer on the valve example of
 * clause 5.3: the reference in process, and a process IUT over JSON lines (the Python example of
 * docs/iut-protocol.md), whose score is dominated by the pipe round trip and Python. Run from the
 * repository root as docs/performance.md describes, with {@code IutBenchmark} as the pattern.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 3, time = 2)
@Fork(1)
@State(Scope.Thread)
public class IutBenchmark {
    private static final double[][] INPUTS = {{5, 60}, {15, 75}, {21, 65}, {9, 85}, {5, 90}, {26, 58}};

    @Param({"reference", "process:python3 examples/iut/basic_iut.py"})
    public String spec;

    private ImplementationUnderTest iut;
    private int i;

    @Setup(Level.Trial)
    public void setUp() throws Exception {
        iut = Iuts.open(spec, IutOptions.defaults());
        iut.load(Files.readString(Path.of("src/test/resources/org/fclcert/check/standard/valve_5_3.fcl")));
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        iut.close();
    }

    @Benchmark
    public double eval() throws IutException {
        double[] in = INPUTS[i++ % INPUTS.length];
        return iut.eval(null, Map.of("temp", in[0], "pressure", in[1])).get("valve");
    }
}
