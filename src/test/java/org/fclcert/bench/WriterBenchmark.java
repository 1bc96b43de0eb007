package org.fclcert.bench;

import java.util.concurrent.TimeUnit;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
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
 * Speed of the canonical writer ({@code fclcert fmt} minus reading) on a program of {@code rules}
 * rules, each with three real-valued input terms and a weighted two-part conclusion, so that the
 * real-literal spelling and condition writing dominate. Run:
 * <pre>
 * mvn -B -q test-compile dependency:build-classpath -Dmdep.outputFile=target/test-cp.txt -Dmdep.includeScope=test
 * java -cp target/test-classes:target/classes:$(cat target/test-cp.txt) org.openjdk.jmh.Main WriterBenchmark
 * </pre>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class WriterBenchmark {
    @Param({"10000"})
    int rules;

    private Program program;
    private final CanonicalWriter writer = new CanonicalWriter();

    @Setup
    public void read() {
        program = new StrictReader().read("bench.fcl", text(rules)).program()
                .orElseThrow(() -> new IllegalStateException("benchmark program does not read"));
    }

    @Benchmark
    public String write() {
        return writer.write(program);
    }

    /** A valid program with {@code n} rules over two inputs and two outputs. */
    static String text(int n) {
        StringBuilder s = new StringBuilder("""
                FUNCTION_BLOCK bench
                VAR_INPUT a : REAL; b : REAL; w : REAL := 0.75; END_VAR
                VAR_OUTPUT y : REAL; z : REAL; END_VAR
                FUZZIFY a TERM low := (0.0, 1.0) (0.333, 0.0); TERM mid := (0.1, 0.0) (0.55, 1.0) (0.9, 0.0);
                  TERM high := (0.667, 0.0) (1.0, 1.0); END_FUZZIFY
                FUZZIFY b TERM low := (-1.5E-3, 1.0) (2.5E-3, 0.0); TERM high := (-1.5E-3, 0.0) (2.5E-3, 1.0); END_FUZZIFY
                DEFUZZIFY y RANGE (0.0 .. 100.0); TERM off := (0.0, 1.0) (50.0, 0.0); TERM on := (50.0, 0.0) (100.0, 1.0);
                  METHOD : CoG; DEFAULT := 0.0; END_DEFUZZIFY
                DEFUZZIFY z TERM lo := 1.25; TERM hi := 98.75; METHOD : CoGS; DEFAULT := NC; END_DEFUZZIFY
                RULEBLOCK r AND : PROD; OR : ASUM; ACT : MIN; ACCU : MAX;
                """);
        String[] terms = {"low", "mid", "high"};
        for (int i = 1; i <= n; i++) {
            s.append("RULE ").append(i).append(" : IF a IS ").append(terms[i % 3])
                    .append(" AND (b IS NOT high OR NOT a IS ").append(terms[(i + 1) % 3])
                    .append(") THEN y IS on WITH 0.").append(100 + i % 900).append(", z IS hi WITH w;\n");
        }
        return s.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n").toString();
    }
}
