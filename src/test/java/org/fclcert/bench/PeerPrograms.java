package org.fclcert.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The programs of {@link PeerComparisonBenchmark}, each written once per reader in the layout that reader
 * needs, with the same meaning: strict IEC 61131-7 text for fclcert and jFuzzyLogic, fuzzylite's layout
 * (one statement per line, ACCU in DEFUZZIFY, lower-case rule words, its named shapes Ramp/Triangle for
 * the same piece-wise linear terms) for jfuzzylite. The operating points are cycled through by the
 * benchmarks; {@link ExactValues} gives the exact output at each.
 */
final class PeerPrograms {
    private PeerPrograms() {
    }

    static final double[][] VALVE_INPUTS = {{5, 60}, {15, 75}, {21, 65}, {9, 85}, {5, 90}, {26, 58}};
    static final double[][] COG3_INPUTS = {{1.5}, {3.2}, {4.9}, {5.0}, {6.7}, {8.8}, {2.4}, {7.1}};
    /** Off the grid of one decimal, where a 100-point midpoint rule over 0..100 would happen to be exact. */
    static final double[][] RULES125_INPUTS = {{1.37, 4.41, 7.93}, {0.0, 5.0, 10.0}, {2.21, 2.63, 3.14},
        {9.12, 6.45, 0.71}, {4.93, 5.17, 5.66}, {7.31, 1.86, 8.89}, {3.33, 9.91, 4.27}, {6.13, 7.77, 2.95}};

    /** The 5.3 example (Figure 7) as shipped in examples/valve.fcl. */
    static String valveStandard() {
        Path p = Path.of("examples", "valve.fcl");
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new UncheckedIOException("run the benchmark from the repository root (" + p + " not found)", e);
        }
    }

    static String valveFuzzylite() {
        return """
                FUNCTION_BLOCK Fuzzy_FB
                VAR_INPUT
                temp : REAL;
                pressure : REAL;
                END_VAR
                VAR_OUTPUT
                valve : REAL;
                END_VAR
                FUZZIFY temp
                TERM cold := Ramp 27.000 3.000;
                TERM hot := Ramp 3.000 27.000;
                END_FUZZIFY
                FUZZIFY pressure
                TERM low := Ramp 95.000 55.000;
                TERM high := Ramp 55.000 95.000;
                END_FUZZIFY
                DEFUZZIFY valve
                TERM drainage := -100.000;
                TERM closed := 0.000;
                TERM inlet := 100.000;
                METHOD : COGS;
                ACCU : MAX;
                DEFAULT := 0.000;
                END_DEFUZZIFY
                RULEBLOCK No1
                AND : MIN;
                RULE 1 : if temp is cold and pressure is low then valve is inlet;
                RULE 2 : if temp is cold and pressure is high then valve is closed with 0.8;
                RULE 3 : if temp is hot and pressure is low then valve is closed;
                RULE 4 : if temp is hot and pressure is high then valve is drainage;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
    }

    /** One input, three triangles; three rules; ACT MIN, ACCU MAX, CoG over RANGE 0..100. */
    static String cog3Standard() {
        return """
                FUNCTION_BLOCK cog3
                VAR_INPUT
                    x : REAL;
                END_VAR
                VAR_OUTPUT
                    y : REAL;
                END_VAR
                FUZZIFY x
                    TERM low := (0, 0) (2, 1) (5, 0);
                    TERM mid := (2, 0) (5, 1) (8, 0);
                    TERM high := (5, 0) (8, 1) (10, 0);
                END_FUZZIFY
                DEFUZZIFY y
                    TERM small := (0, 0) (20, 1) (40, 0);
                    TERM medium := (30, 0) (50, 1) (70, 0);
                    TERM large := (60, 0) (80, 1) (100, 0);
                    METHOD : CoG;
                    DEFAULT := 0;
                    RANGE := (0 .. 100);
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    ACT : MIN;
                    ACCU : MAX;
                    RULE 1 : IF x IS low THEN y IS small;
                    RULE 2 : IF x IS mid THEN y IS medium;
                    RULE 3 : IF x IS high THEN y IS large;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
    }

    static String cog3Fuzzylite() {
        return """
                FUNCTION_BLOCK cog3
                VAR_INPUT
                x : REAL;
                END_VAR
                VAR_OUTPUT
                y : REAL;
                END_VAR
                FUZZIFY x
                RANGE := (0.000 .. 10.000);
                TERM low := Triangle 0.000 2.000 5.000;
                TERM mid := Triangle 2.000 5.000 8.000;
                TERM high := Triangle 5.000 8.000 10.000;
                END_FUZZIFY
                DEFUZZIFY y
                RANGE := (0.000 .. 100.000);
                TERM small := Triangle 0.000 20.000 40.000;
                TERM medium := Triangle 30.000 50.000 70.000;
                TERM large := Triangle 60.000 80.000 100.000;
                METHOD : COG;
                ACCU : MAX;
                DEFAULT := 0.000;
                END_DEFUZZIFY
                RULEBLOCK r
                AND : MIN;
                ACT : MIN;
                RULE 1 : if x is low then y is small;
                RULE 2 : if x is mid then y is medium;
                RULE 3 : if x is high then y is large;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
    }

    static final String[] INPUTS125 = {"a", "b", "c"};

    /** Input term k of a, b, c: the triangle with peak 2.5k and feet 2.5 either side. */
    static double[] inputTriangle(int k) {
        return new double[] {2.5 * k - 2.5, 2.5 * k, 2.5 * k + 2.5};
    }

    /** Output term k of y: the triangle with peak 25k and feet 25 either side, cut by RANGE 0..100. */
    static double[] outputTriangle(int k) {
        return new double[] {25.0 * k - 25, 25.0 * k, 25.0 * k + 25};
    }

    /** Rule (i, j, k) concludes y IS o((i + j + k + 1) / 3): 0..4. */
    static int conclusion(int i, int j, int k) {
        return (i + j + k + 1) / 3;
    }

    /** Three inputs with five triangles each, all 125 AND combinations as rules, CoG over RANGE 0..100. */
    static String rules125(boolean fuzzylite) {
        StringBuilder s = new StringBuilder();
        String ind = fuzzylite ? "" : "    ";
        s.append("FUNCTION_BLOCK rules125\nVAR_INPUT\n");
        for (String v : INPUTS125) {
            s.append(ind).append(v).append(" : REAL;\n");
        }
        s.append("END_VAR\nVAR_OUTPUT\n").append(ind).append("y : REAL;\nEND_VAR\n");
        for (String v : INPUTS125) {
            s.append("FUZZIFY ").append(v).append('\n');
            if (fuzzylite) {
                s.append("RANGE := (0.000 .. 10.000);\n");
            }
            for (int k = 0; k < 5; k++) {
                s.append(ind).append("TERM t").append(k).append(" := ").append(triangle(inputTriangle(k), fuzzylite))
                        .append(";\n");
            }
            s.append("END_FUZZIFY\n");
        }
        s.append("DEFUZZIFY y\n");
        if (fuzzylite) {
            s.append("RANGE := (0.000 .. 100.000);\n");
        }
        for (int k = 0; k < 5; k++) {
            s.append(ind).append("TERM o").append(k).append(" := ").append(triangle(outputTriangle(k), fuzzylite))
                    .append(";\n");
        }
        s.append(ind).append(fuzzylite ? "METHOD : COG;\nACCU : MAX;\nDEFAULT := 0.000;\n"
                : "METHOD : CoG;\n    DEFAULT := 0;\n    RANGE := (0 .. 100);\n");
        s.append("END_DEFUZZIFY\nRULEBLOCK all\n").append(ind).append("AND : MIN;\n").append(ind).append("ACT : MIN;\n");
        if (!fuzzylite) {
            s.append(ind).append("ACCU : MAX;\n");
        }
        int n = 1;
        for (int i = 0; i < 5; i++) {
            for (int j = 0; j < 5; j++) {
                for (int k = 0; k < 5; k++) {
                    String rule = String.format(Locale.ROOT, "RULE %d : IF a IS t%d AND b IS t%d AND c IS t%d THEN y IS o%d;",
                            n++, i, j, k, conclusion(i, j, k));
                    if (fuzzylite) {
                        rule = rule.replace(" IF ", " if ").replace(" IS ", " is ").replace(" AND ", " and ")
                                .replace(" THEN ", " then ");
                    }
                    s.append(ind).append(rule).append('\n');
                }
            }
        }
        s.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        return s.toString();
    }

    private static String triangle(double[] t, boolean fuzzylite) {
        return fuzzylite ? String.format(Locale.ROOT, "Triangle %.3f %.3f %.3f", t[0], t[1], t[2])
                : String.format(Locale.ROOT, "(%s, 0) (%s, 1) (%s, 0)", num(t[0]), num(t[1]), num(t[2]));
    }

    private static String num(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
