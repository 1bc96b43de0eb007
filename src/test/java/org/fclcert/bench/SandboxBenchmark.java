package org.fclcert.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.sandbox.SandboxSettings;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * What the bubblewrap sandbox adds to a launch: one session of an implementation from its start to its end (start,
 * {@code hello}, {@code load} of the valve example of clause 5.3, one {@code eval}, {@code bye}), with the sandbox
 * on and off. A certify run starts each implementation process once (and again after each crash or timeout); the
 * fuzzylite command line is launched once per request, so for it the difference is paid per request. Run from the
 * repository root as docs/performance.md describes, with {@code SandboxBenchmark} as the pattern.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
@State(Scope.Thread)
public class SandboxBenchmark {
    @Param({"process:python3 examples/iut/basic_iut.py", "fuzzylite"})
    public String spec;

    @Param({"on", "off"})
    public String sandbox;

    private String valve;
    private IutOptions options;

    @Setup
    public void setUp() throws Exception {
        valve = Files.readString(Path.of("src/test/resources/org/fclcert/check/standard/valve_5_3.fcl"));
        options = IutOptions.defaults().withSandbox(sandbox.equals("on") ? SandboxSettings.defaults()
                : SandboxSettings.none());
    }

    @Benchmark
    public double session() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open(spec, options)) {
            iut.hello();
            // fuzzylite rejects the standard's layout (docs/iut-protocol.md): its session ends after the load
            if (!(iut.load(valve) instanceof LoadOutcome.Loaded)) {
                return 0;
            }
            return iut.eval(null, Map.of("temp", 5.0, "pressure", 60.0)).get("valve");
        }
    }
}
