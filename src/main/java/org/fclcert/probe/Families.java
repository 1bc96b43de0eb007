package org.fclcert.probe;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;

/**
 * The generated program families, one per "maximum number of" row of Table 11. Size {@code n} is the
 * number of elements the row counts. Each family keeps the other dimensions small, and is built so that
 * the <em>sampled</em> elements — the first, two in between and the last — each change an output
 * when an implementation drops, truncates or confuses them. Filler elements only make up the count.
 * Totals over several variables or blocks are laid out with the per-variable limits already measured,
 * so that a total is not capped by a per-variable limit; when that layout cannot reach {@code n} the
 * family answers empty ("bounded by the rows it is made of").
 *
 * <p>The "degree meter": output {@code y} has singletons {@code hi := 1} and {@code lo := 0}; rule
 * {@code IF z IS half THEN y IS lo} with {@code z = 0.5} gives {@code lo} degree 0.5, so that
 * {@code y = d / (d + 0.5)} shows the degree {@code d} of {@code hi} — not only whether it fired.
 */
final class Families {
    /** How many elements of a row are made to matter (first, last and two between). */
    static final int SAMPLES = 4;

    private Families() {
    }

    /** Layout limits taken from rows measured before (per-variable limits for the totals). */
    interface Measured {
        /** The largest size that worked for the row, or {@code fallback} when it was not measured. */
        long limit(String id, long fallback);
    }

    /** Distinct sorted indices 0 … n-1 to make matter: first, n/3, 2n/3, last. */
    static int[] sample(int n) {
        TreeSet<Integer> s = new TreeSet<>(List.of(0, n / 3, (2 * n) / 3, n - 1));
        return s.stream().mapToInt(Integer::intValue).toArray();
    }

    private static boolean sampled(int[] samples, int i) {
        for (int s : samples) {
            if (s == i) {
                return true;
            }
        }
        return false;
    }

    static Map<String, Double> vector(Object... nameValue) {
        Map<String, Double> m = new LinkedHashMap<>();
        for (int i = 0; i < nameValue.length; i += 2) {
            m.put((String) nameValue[i], ((Number) nameValue[i + 1]).doubleValue());
        }
        return m;
    }

    private static void meter(FclText f) {
        f.input("z").fuzzify("z", List.of("half := " + FclText.RAMP));
    }

    private static List<String> meterOutput() {
        return List.of("lo := 0", "hi := 1");
    }

    /** Output singletons o1 := 1 … oCount := count: the k-th sampled element selects the value k. */
    private static List<String> numberedSingletons(int count) {
        List<String> terms = new ArrayList<>(count);
        for (int k = 1; k <= count; k++) {
            terms.add("o" + k + " := " + k);
        }
        return terms;
    }

    /** Input variables x1…xn, each with one ramp term; sampled inputs each switch the output on. */
    static ProbeProgram inputs(int n) {
        FclText f = new FclText();
        for (int i = 1; i <= n; i++) {
            f.input("x" + i);
        }
        f.output("y");
        for (int i = 1; i <= n; i++) {
            f.fuzzify("x" + i, List.of("hi := " + FclText.RAMP));
        }
        int[] s = sample(n);
        f.singletons("y", numberedSingletons(s.length)).ruleBlock("main");
        List<Map<String, Double>> vectors = new ArrayList<>();
        vectors.add(vector());
        String previous = null;
        for (int k = 0; k < s.length; k++) {
            String x = "x" + (s[k] + 1);
            f.rule(x + " IS hi", "y IS o" + (k + 1));
            Map<String, Double> v = new LinkedHashMap<>();
            if (previous != null) {
                v.put(previous, 0.0);
            }
            v.put(x, 1.0);
            vectors.add(v);
            previous = x;
        }
        return new ProbeProgram(f.text(), vectors);
    }

    /** Terms t1…tn of one input (triangles peaking at 1…n); sampled terms each select an output value. */
    static ProbeProgram termsPerInput(int n) {
        return termsAllInputs(n, n);
    }

    /** n input terms over inputs of at most {@code perInput} terms each. */
    static ProbeProgram termsAllInputs(int n, long perInput) {
        int per = (int) Math.max(1, Math.min(n, perInput));
        int vars = (n + per - 1) / per;
        FclText f = new FclText();
        for (int v = 1; v <= vars; v++) {
            f.input("x" + v);
        }
        f.output("y");
        for (int v = 1; v <= vars; v++) {
            int count = Math.min(per, n - (v - 1) * per);
            List<String> terms = new ArrayList<>(count);
            for (int j = 1; j <= count; j++) {
                terms.add("t" + j + " := " + FclText.triangle(j));
            }
            f.fuzzify("x" + v, terms);
        }
        int[] s = sample(n);
        f.singletons("y", numberedSingletons(s.length)).ruleBlock("main");
        List<Map<String, Double>> vectors = new ArrayList<>();
        String previous = null;
        for (int k = 0; k < s.length; k++) {
            String x = "x" + (s[k] / per + 1);
            int term = s[k] % per + 1;
            f.rule(x + " IS t" + term, "y IS o" + (k + 1));
            Map<String, Double> vec = new LinkedHashMap<>();
            if (previous != null) {
                vec.put(previous, 0.0);
            }
            vec.put(x, (double) term);
            vectors.add(vec);
            previous = x;
        }
        return new ProbeProgram(f.text(), vectors);
    }

    /** Degrees 0 and 1 alternating at x = 0, 1, 2, …: dropping any point changes the degree at its x. */
    static String zigzag(int points) {
        StringBuilder b = new StringBuilder();
        for (int j = 0; j < points; j++) {
            b.append(j == 0 ? "" : " ").append('(').append(j).append(", ").append(j % 2).append(')');
        }
        return b.toString();
    }

    /** One input term of n points (n ≥ 2, zig-zag), read through the degree meter at sampled points. */
    static ProbeProgram pointsPerInputTerm(int n) {
        FclText f = new FclText().input("x");
        meter(f);
        f.output("y").fuzzify("x", List.of("p := " + zigzag(n)));
        f.singletons("y", meterOutput()).ruleBlock("main").rule("x IS p", "y IS hi").rule("z IS half", "y IS lo");
        List<Map<String, Double>> vectors = new ArrayList<>();
        vectors.add(vector("z", 0.5));
        for (int j : sample(n)) {
            vectors.add(vector("x", j));
            if (j < n - 1) {
                vectors.add(vector("x", j + 0.25));
            }
        }
        return new ProbeProgram(f.text(), vectors);
    }

    /**
     * n points over input terms of at most {@code perTerm} points, grouped in inputs of at most
     * {@code perInput} terms; empty when that needs more than {@code maxInputs} inputs.
     */
    static Optional<ProbeProgram> pointsAllInputTerms(int n, long perTerm, long perInput, long maxInputs) {
        List<Integer> sizes = termSizes(n, perTerm, 2);
        int per = (int) Math.max(1, Math.min(sizes.size(), perInput));
        int vars = (sizes.size() + per - 1) / per;
        if (vars > maxInputs) {
            return Optional.empty();
        }
        FclText f = new FclText();
        for (int v = 1; v <= vars; v++) {
            f.input("x" + v);
        }
        meter(f);
        f.output("y");
        for (int v = 0; v < vars; v++) {
            List<String> terms = new ArrayList<>();
            for (int j = v * per; j < Math.min(sizes.size(), (v + 1) * per); j++) {
                terms.add("p" + (j - v * per + 1) + " := " + zigzag(sizes.get(j)));
            }
            f.fuzzify("x" + (v + 1), terms);
        }
        f.singletons("y", meterOutput()).ruleBlock("main");
        List<Map<String, Double>> vectors = new ArrayList<>();
        vectors.add(vector("z", 0.5));
        int[] s = sample(sizes.size());
        for (int g : s) {
            f.rule("x" + (g / per + 1) + " IS p" + (g % per + 1), "y IS hi");
        }
        f.rule("z IS half", "y IS lo");
        for (int g : s) {
            String x = "x" + (g / per + 1);
            int last = sizes.get(g) - 1;
            vectors.add(vector(x, last));
            vectors.add(vector(x, last - 0.25));
        }
        return Optional.of(new ProbeProgram(f.text(), vectors));
    }

    /** n split into parts of at most {@code per} (each at least {@code min}), as even as possible. */
    static List<Integer> termSizes(int n, long per, int min) {
        long p = Math.max(min, Math.min(n, per));
        int parts = (int) ((n + p - 1) / p);
        if (parts > 1 && n / parts < min) {
            parts = n / min;
        }
        List<Integer> sizes = new ArrayList<>(parts);
        for (int i = 0; i < parts; i++) {
            sizes.add(n / parts + (i < n % parts ? 1 : 0));
        }
        return sizes;
    }

    /** Output variables y1…yn with one singleton each; the sampled outputs are concluded by one rule each. */
    static ProbeProgram outputs(int n) {
        FclText f = new FclText().input("x");
        for (int i = 1; i <= n; i++) {
            f.output("y" + i);
        }
        f.fuzzify("x", List.of("hi := " + FclText.RAMP));
        int[] s = sample(n);
        for (int i = 1; i <= n; i++) {
            f.singletons("y" + i, List.of("on := " + i));
        }
        f.ruleBlock("main");
        for (int k : s) {
            f.rule("x IS hi", "y" + (k + 1) + " IS on");
        }
        return new ProbeProgram(f.text(), List.of(vector("x", 1), vector("x", 0), vector("x", 0.5)));
    }

    static ProbeProgram termsPerOutput(int n) {
        return termsAllOutputs(n, n, 1).orElseThrow();
    }

    /**
     * n singleton output terms (value = its number) over outputs of at most {@code perOutput} terms;
     * the input x has one triangle per sampled term, so that x = k selects sampled term k alone. Empty
     * when more than {@code maxOutputs} outputs would be needed.
     */
    static Optional<ProbeProgram> termsAllOutputs(int n, long perOutput, long maxOutputs) {
        int per = (int) Math.max(1, Math.min(n, perOutput));
        int vars = (n + per - 1) / per;
        if (vars > maxOutputs && vars > 1) {
            return Optional.empty();
        }
        FclText f = new FclText().input("x");
        for (int v = 1; v <= vars; v++) {
            f.output("y" + v);
        }
        int[] s = sample(n);
        List<String> inTerms = new ArrayList<>();
        for (int k = 1; k <= s.length; k++) {
            inTerms.add("p" + k + " := " + FclText.triangle(k));
        }
        f.fuzzify("x", inTerms);
        for (int v = 1; v <= vars; v++) {
            int count = Math.min(per, n - (v - 1) * per);
            List<String> terms = new ArrayList<>(count);
            for (int j = 1; j <= count; j++) {
                terms.add("s" + j + " := " + j);
            }
            f.singletons("y" + v, terms);
        }
        f.ruleBlock("main");
        List<Map<String, Double>> vectors = new ArrayList<>();
        for (int k = 0; k < s.length; k++) {
            f.rule("x IS p" + (k + 1), "y" + (s[k] / per + 1) + " IS s" + (s[k] % per + 1));
            vectors.add(vector("x", k + 1));
        }
        vectors.add(vector("x", 0));
        return Optional.of(new ProbeProgram(f.text(), vectors));
    }

    /**
     * Points of an output term: with 1 a singleton (CoGS); from 2 on a term of n points with CoG and a
     * RANGE, its degrees rising and falling unevenly so that dropping a point moves the centre of gravity.
     */
    static ProbeProgram pointsPerOutputTerm(int n) {
        return pointsAllOutputTerms(n, n, 1, 1).orElseThrow();
    }

    private static String outputShape(int points) {
        StringBuilder b = new StringBuilder();
        for (int j = 0; j < points; j++) {
            double d = j % 2 == 0 ? 0.0 : 1.0 - 0.25 * ((j / 2) % 3);
            b.append(j == 0 ? "" : " ").append('(').append(j).append(", ").append(d).append(')');
        }
        return b.toString();
    }

    /**
     * n output points over terms of at most {@code perTerm} points (singletons when 1), grouped in outputs
     * of at most {@code perOutput} terms; empty when more than {@code maxOutputs} outputs are needed.
     */
    static Optional<ProbeProgram> pointsAllOutputTerms(int n, long perTerm, long perOutput, long maxOutputs) {
        boolean singletons = perTerm <= 1 || n == 1;
        List<Integer> sizes = singletons ? java.util.Collections.nCopies(n, 1) : termSizes(n, perTerm, 2);
        int per = (int) Math.max(1, Math.min(sizes.size(), perOutput));
        int vars = (sizes.size() + per - 1) / per;
        if (vars > maxOutputs && vars > 1) {
            return Optional.empty();
        }
        FclText f = new FclText().input("x");
        for (int v = 1; v <= vars; v++) {
            f.output("y" + v);
        }
        f.fuzzify("x", List.of("hi := " + FclText.RAMP));
        int widest = sizes.stream().mapToInt(Integer::intValue).max().orElse(1);
        for (int v = 0; v < vars; v++) {
            List<String> terms = new ArrayList<>();
            for (int j = v * per; j < Math.min(sizes.size(), (v + 1) * per); j++) {
                int local = j - v * per + 1;
                terms.add("p" + local + " := " + (singletons ? String.valueOf(local) : outputShape(sizes.get(j))));
            }
            if (singletons) {
                f.singletons("y" + (v + 1), terms);
            } else {
                f.defuzzify("y" + (v + 1), terms, "CoG", "(0 .. " + (widest - 1) + ")");
            }
        }
        f.ruleBlock("main");
        for (int g : sample(sizes.size())) {
            f.rule("x IS hi", "y" + (g / per + 1) + " IS p" + (g % per + 1));
        }
        return Optional.of(new ProbeProgram(f.text(), List.of(vector("x", 1), vector("x", 0.5), vector("x", 0))));
    }

    /**
     * n rule blocks (or n rules in blocks of at most {@code perBlock}): filler rules all read
     * {@code IF x IS hi THEN y IS base}; the sampled rules read {@code IF sK IS hi THEN y IS tK} with an
     * input and an output value of their own, so each moves y when it fires. Empty when more than
     * {@code maxBlocks} blocks would be needed.
     */
    static Optional<ProbeProgram> rules(int n, long perBlock, long maxBlocks) {
        int per = (int) Math.max(1, Math.min(n, perBlock));
        int blocks = (n + per - 1) / per;
        if (blocks > maxBlocks && blocks > 1) {
            return Optional.empty();
        }
        int[] s = sample(n);
        FclText f = new FclText().input("x");
        for (int k = 1; k <= s.length; k++) {
            f.input("s" + k);
        }
        f.output("y").fuzzify("x", List.of("hi := " + FclText.RAMP));
        for (int k = 1; k <= s.length; k++) {
            f.fuzzify("s" + k, List.of("hi := " + FclText.RAMP));
        }
        List<String> outTerms = new ArrayList<>(List.of("base := 0"));
        for (int k = 1; k <= s.length; k++) {
            outTerms.add("t" + k + " := " + (10 * k));
        }
        f.singletons("y", outTerms);
        int k = 0;
        for (int b = 0; b < blocks; b++) {
            f.ruleBlock("rb" + (b + 1));
            for (int r = b * per; r < Math.min(n, (b + 1) * per); r++) {
                if (sampled(s, r)) {
                    k++;
                    f.rule("s" + k + " IS hi", "y IS t" + k);
                } else {
                    f.rule("x IS hi", "y IS base");
                }
            }
        }
        List<Map<String, Double>> vectors = new ArrayList<>();
        vectors.add(vector("x", 0.5));
        for (int j = 1; j <= s.length; j++) {
            Map<String, Double> v = new LinkedHashMap<>();
            if (j > 1) {
                v.put("s" + (j - 1), 0.0);
            }
            v.put("s" + j, 1.0);
            vectors.add(v);
        }
        return Optional.of(new ProbeProgram(f.text(), vectors));
    }

    /** One rule blocks per rule: n blocks. */
    static Optional<ProbeProgram> ruleBlocks(int n) {
        return rules(n, 1, n);
    }

    /**
     * One rule of n subconditions {@code xV IS hi} over {@code min(n, maxInputs)} inputs (wrapping
     * around when there are fewer inputs than subconditions), read through the degree meter while the
     * sampled inputs are lowered one at a time.
     */
    static ProbeProgram subconditions(int n, long maxInputs) {
        int vars = (int) Math.max(1, Math.min(n, maxInputs));
        FclText f = new FclText();
        for (int v = 1; v <= vars; v++) {
            f.input("x" + v);
        }
        meter(f);
        f.output("y");
        for (int v = 1; v <= vars; v++) {
            f.fuzzify("x" + v, List.of("hi := " + FclText.RAMP));
        }
        StringBuilder cond = new StringBuilder();
        for (int j = 0; j < n; j++) {
            cond.append(j == 0 ? "" : " AND ").append('x').append(j % vars + 1).append(" IS hi");
        }
        f.singletons("y", meterOutput()).ruleBlock("main").rule(cond.toString(), "y IS hi").rule("z IS half", "y IS lo");
        List<Map<String, Double>> vectors = new ArrayList<>();
        Map<String, Double> all = new LinkedHashMap<>(vector("z", 0.5));
        for (int v = 1; v <= vars; v++) {
            all.put("x" + v, 1.0);
        }
        vectors.add(all);
        int[] s = sample(vars);
        String previous = null;
        for (int k = 0; k < s.length; k++) {
            Map<String, Double> v = new LinkedHashMap<>();
            if (previous != null) {
                v.put(previous, 1.0);
            }
            previous = "x" + (s[k] + 1);
            v.put(previous, 0.2 * (k + 1));
            vectors.add(v);
        }
        return new ProbeProgram(f.text(), vectors);
    }

    /**
     * One rule with n subconclusions {@code yV IS on} over {@code min(n, maxOutputs)} outputs (wrapping
     * around), each output with a value of its own.
     */
    static ProbeProgram subconclusions(int n, long maxOutputs) {
        int vars = (int) Math.max(1, Math.min(n, maxOutputs));
        FclText f = new FclText().input("x");
        for (int v = 1; v <= vars; v++) {
            f.output("y" + v);
        }
        f.fuzzify("x", List.of("hi := " + FclText.RAMP));
        for (int v = 1; v <= vars; v++) {
            f.singletons("y" + v, List.of("on := " + v));
        }
        StringBuilder conc = new StringBuilder();
        for (int j = 0; j < n; j++) {
            conc.append(j == 0 ? "" : ", ").append('y').append(j % vars + 1).append(" IS on");
        }
        f.ruleBlock("main").rule("x IS hi", conc.toString());
        return new ProbeProgram(f.text(), List.of(vector("x", 1), vector("x", 0), vector("x", 0.5)));
    }

    /** {@code IF (((x IS hi))) THEN y IS hi} with n pairs of parentheses, through the degree meter. */
    static ProbeProgram nesting(int n) {
        FclText f = new FclText().input("x");
        meter(f);
        f.output("y").fuzzify("x", List.of("hi := " + FclText.RAMP));
        String cond = "(".repeat(n) + "x IS hi" + ")".repeat(n);
        f.singletons("y", meterOutput()).ruleBlock("main").rule(cond, "y IS hi").rule("z IS half", "y IS lo");
        return new ProbeProgram(f.text(), List.of(vector("z", 0.5, "x", 0.3), vector("x", 0.9), vector("x", 0)));
    }

    /** The degree meter on a ramp input, {@code y = x / (x + 0.5)}; {@code comment} goes where {@code %C} is. */
    static String meterProgram(String inputType, String outputType) {
        FclText f = new FclText().input("x", inputType);
        meter(f);
        f.output("y", outputType).fuzzify("x", List.of("hi := " + FclText.RAMP));
        f.singletons("y", meterOutput()).ruleBlock("main").rule("x IS hi", "y IS hi").rule("z IS half", "y IS lo");
        return f.text();
    }

    /** Degree-meter vectors over x. */
    static List<Map<String, Double>> meterVectors(double... xs) {
        List<Map<String, Double>> vectors = new ArrayList<>();
        vectors.add(vector("z", 0.5));
        for (double x : xs) {
            vectors.add(vector("x", x));
        }
        return vectors;
    }

    /** Input and output of one data type; y = 20 at x = 0 rising to 100 at x = 100 (CoGS of two singletons). */
    static ProbeProgram dataType(String type) {
        FclText f = new FclText().input("x", type).output("y", type);
        f.fuzzify("x", List.of("lo := (0, 1) (100, 0)", "hi := (0, 0) (100, 1)"));
        f.singletons("y", List.of("a := 20", "b := 100")).ruleBlock("main")
                .rule("x IS lo", "y IS a").rule("x IS hi", "y IS b");
        return new ProbeProgram(f.text(), List.of(vector("x", 0), vector("x", 25), vector("x", 50), vector("x", 100)));
    }

    /** A name of {@code length} characters: {@code first}, then {@code a}s, then {@code last}. */
    static String name(char first, int length, char last) {
        if (length == 1) {
            return String.valueOf(last);
        }
        return first + "a".repeat(length - 2) + last;
    }

    /** Input, term, output and rule block all named with {@code length} characters. */
    static ProbeProgram longNames(int length) {
        String x = name('x', length, 'x');
        String t = name('t', length, 't');
        String y = name('y', length, 'y');
        FclText f = new FclText().input(x).output(y);
        f.fuzzify(x, List.of(t + " := " + FclText.RAMP));
        f.singletons(y, List.of("on := 5")).ruleBlock(name('r', length, 'r')).rule(x + " IS " + t, y + " IS on");
        return new ProbeProgram(f.text(), List.of(vector(x, 1), vector(x, 0)));
    }

    /** Two inputs whose names of {@code length} characters differ only in the last one, each selecting its own value. */
    static ProbeProgram distinctNames(int length) {
        String a = name('x', length, 'b');
        String b = name('x', length, 'c');
        FclText f = new FclText().input(a).input(b).output("y");
        f.fuzzify(a, List.of("hi := " + FclText.RAMP)).fuzzify(b, List.of("hi := " + FclText.RAMP));
        f.singletons("y", List.of("o1 := 1", "o2 := 2")).ruleBlock("main")
                .rule(a + " IS hi", "y IS o1").rule(b + " IS hi", "y IS o2");
        return new ProbeProgram(f.text(), List.of(vector(a, 1, b, 0), vector(a, 0, b, 1)));
    }

    /** Names declared in one letter case and used in others (FCL names are case-insensitive). */
    static ProbeProgram mixedCase() {
        FclText f = new FclText().input("Temp").output("Valve");
        f.fuzzify("TEMP", List.of("Hot := " + FclText.RAMP));
        f.singletons("VALVE", List.of("Open := 7")).ruleBlock("main").rule("temp IS HOT", "valve IS OPEN");
        return new ProbeProgram(f.text(), List.of(vector("TEMP", 1), vector("temp", 0)));
    }

    /** A workload of 3 inputs × 3 terms, 27 rules of 3 subconditions, 5 singletons: the execution-time program. */
    static String workload() {
        FclText f = new FclText();
        for (int i = 1; i <= 3; i++) {
            f.input("x" + i);
        }
        f.output("y");
        for (int i = 1; i <= 3; i++) {
            f.fuzzify("x" + i, List.of("low := (0, 1) (2, 0)", "mid := (0, 0) (2, 1) (4, 0)", "high := (2, 0) (4, 1)"));
        }
        f.singletons("y", List.of("vlow := 0", "low := 25", "mid := 50", "high := 75", "vhigh := 100"));
        f.ruleBlock("main");
        String[] t = {"low", "mid", "high"};
        String[] o = {"vlow", "low", "mid", "high", "vhigh"};
        for (int a = 0; a < 3; a++) {
            for (int b = 0; b < 3; b++) {
                for (int c = 0; c < 3; c++) {
                    f.rule("x1 IS " + t[a] + " AND x2 IS " + t[b] + " AND x3 IS " + t[c], "y IS " + o[(a + b + c + 1) / 2]);
                }
            }
        }
        return f.text();
    }
}
