package org.fclcert.bench;

import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
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
 * What the child JVM of a {@code java:} implementation adds to a run (issue 27): one session of the test vendor
 * class {@code SummingFcl} from its start to its end ({@code hello}, {@code load}, one {@code eval}, {@code bye}) in
 * a child JVM in the sandbox, in a child JVM without it, and {@code --in-process}. A certify run opens the session
 * once (and again after each crash or timeout). Run from the repository root as docs/performance.md describes, with
 * {@code JavaIsolationBenchmark} as the pattern.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
@State(Scope.Thread)
public class JavaIsolationBenchmark {
    private static final String PROGRAM = "FUNCTION_BLOCK adder\nVAR_INPUT a, b : REAL; END_VAR\n"
            + "VAR_OUTPUT y : REAL; count : REAL; END_VAR\nEND_FUNCTION_BLOCK\n";

    @Param({"child-jvm-sandbox", "child-jvm-no-sandbox", "in-process"})
    public String mode;

    private IutOptions options;

    @Setup
    public void setUp() {
        options = IutOptions.defaults().withInProcess(mode.equals("in-process"))
                .withSandbox(mode.equals("child-jvm-no-sandbox") ? SandboxSettings.none() : SandboxSettings.defaults());
    }

    @Benchmark
    public double session() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open("java:org.fclcert.iut.SummingFcl", options)) {
            iut.hello();
            iut.load(PROGRAM);
            return iut.eval(null, Map.of("a", 1.0, "b", 2.0)).get("y");
        }
    }
}
