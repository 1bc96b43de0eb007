package org.fclcert.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Writes the large programs of docs/performance.md's memory and time figures (issue 18) to a directory:
 * {@code inputs100k.fcl}, 100 000 inputs each with a FUZZIFY block of one term and one rule (about 12 MB),
 * and {@code rules100k.fcl}, {@link ParseBenchmark}'s 100 000-rule program (about 13 MB). Both are valid and
 * check clean. Run: {@code java -cp target/test-classes:target/classes org.fclcert.bench.LargePrograms DIR}.
 */
public final class LargePrograms {
    private LargePrograms() {
    }

    public static void main(String[] args) throws IOException {
        Path dir = Path.of(args.length > 0 ? args[0] : "target/large");
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("inputs100k.fcl"), manyInputs(100_000));
        Files.writeString(dir.resolve("rules100k.fcl"), ParseBenchmark.largeProgram(100_000));
    }

    /** {@code n} inputs i0.. with one ramp each, one output, one rule per input. */
    static String manyInputs(int n) {
        StringBuilder s = new StringBuilder(n * 125);
        s.append("FUNCTION_BLOCK many\nVAR_INPUT\n");
        for (int i = 0; i < n; i++) {
            s.append("    i").append(i).append(" : REAL;\n");
        }
        s.append("END_VAR\nVAR_OUTPUT\n    y : REAL;\nEND_VAR\n");
        for (int i = 0; i < n; i++) {
            s.append("FUZZIFY i").append(i).append("\n    TERM high := (0, 0) (1, 1);\nEND_FUZZIFY\n");
        }
        s.append("DEFUZZIFY y\n    TERM low := 0;\n    TERM high := 100;\n    METHOD : CoGS;\n    DEFAULT := 0;\n"
                + "END_DEFUZZIFY\nRULEBLOCK r\n    AND : MIN;\n    ACCU : MAX;\n");
        for (int i = 0; i < n; i++) {
            s.append("    RULE ").append(i + 1).append(" : IF i").append(i).append(" IS high THEN y IS ")
                    .append(i % 2 == 0 ? "high" : "low").append(";\n");
        }
        return s.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n").toString();
    }
}
