package org.fclcert.bench;

import java.util.concurrent.TimeUnit;
import org.fclcert.syntax.ReadResult;
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
import org.openjdk.jmh.annotations.Warmup;

/**
 * Speed of the strict reader (lex, pre-scan, parse, build the model) on a generated program of
 * 100 000 rules (about 10 MB) and on the standard's 5.3 example. See docs/performance.md for the
 * command and the figures.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@Fork(value = 1, jvmArgs = {"-Xmx2g"})
public class ParseBenchmark {
    static final int RULES = 100_000;

    private final StrictReader reader = new StrictReader();
    private String large;
    private String figure7;

    @Setup(Level.Trial)
    public void generate() {
        large = largeProgram(RULES);
        figure7 = FIGURE_7;
    }

    /** A valid program: one rule block of {@code rules} rules with AND, OR, NOT, parentheses, WITH and comments. */
    static String largeProgram(int rules) {
        StringBuilder sb = new StringBuilder(rules * 110);
        sb.append("FUNCTION_BLOCK big\nVAR_INPUT temp, pressure : REAL; END_VAR\nVAR_OUTPUT valve : REAL; END_VAR\n")
                .append("FUZZIFY temp TERM cold := (3, 1) (27, 0); TERM hot := (3, 0) (27, 1); END_FUZZIFY\n")
                .append("FUZZIFY pressure TERM low := (55, 1) (95, 0); TERM high := (55, 0) (95, 1); END_FUZZIFY\n")
                .append("DEFUZZIFY valve TERM drainage := -100; TERM closed := 0; TERM inlet := 100;\n")
                .append("    METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY\n")
                .append("RULEBLOCK No1\nAND : MIN;\nOR : MAX;\nACCU : MAX;\n");
        for (int i = 1; i <= rules; i++) {
            sb.append("RULE ").append(i).append(" : IF temp IS cold AND pressure IS low OR (temp IS hot AND NOT")
                    .append(" pressure IS high) THEN valve IS inlet WITH 0.5; (* ").append(i).append(" *)\n");
        }
        return sb.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n").toString();
    }

    @Benchmark
    @OutputTimeUnit(TimeUnit.MILLISECONDS)
    @Warmup(iterations = 3, time = 5)
    @Measurement(iterations = 5, time = 10)
    public ReadResult read100kRules() {
        return check(reader.read("large.fcl", large));
    }

    @Benchmark
    @OutputTimeUnit(TimeUnit.MICROSECONDS)
    @Warmup(iterations = 3, time = 2)
    @Measurement(iterations = 5, time = 2)
    public ReadResult readFigure7() {
        return check(reader.read("figure7.fcl", figure7));
    }

    private static ReadResult check(ReadResult r) {
        if (r.program().isEmpty()) {
            throw new IllegalStateException("benchmark program did not read: " + r.diagnostics());
        }
        return r;
    }

    private static final String FIGURE_7 = """
            FUNCTION_BLOCK Fuzzy_FB
            VAR_INPUT
                temp:    REAL;
                pressure: REAL;
            END_VAR
            VAR_OUTPUT
                valve:    REAL;
            END_VAR
            FUZZIFY temp
                TERM cold    := (3, 1) (27, 0);
                TERM hot     := (3, 0) (27, 1);
            END_FUZZIFY
            FUZZIFY pressure
                TERM low     := (55, 1) (95, 0);
                TERM high    := (55, 0) (95, 1);
            END_FUZZIFY
            DEFUZZIFY valve
                TERM drainage := -100;
                TERM closed  := 0;
                TERM inlet   := 100;
                METHOD: CoGS;
                DEFAULT     := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
                AND: MIN;
                ACCU: MAX;
                RULE 1: IF temp IS cold AND pressure IS low THEN valve IS inlet;
                RULE 2: IF temp IS cold AND pressure IS high THEN valve IS closed WITH 0.8;
                RULE 3: IF temp IS hot AND pressure IS low THEN valve IS closed;
                RULE 4: IF temp IS hot AND pressure IS high THEN valve IS drainage;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;
}
