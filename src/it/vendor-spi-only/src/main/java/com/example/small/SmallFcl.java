package com.example.small;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;

/**
 * A small Basic Level FCL implementation, written against fclcert-spi alone (the Java twin of
 * examples/iut/basic_iut.py): REAL, LREAL and integer variables, input terms of two or three points,
 * singleton output terms, AND: MIN, ACCU: MAX, METHOD: CoGS, DEFAULT value or NC, one rule block, rules
 * 'IF v IS t AND ... THEN v IS t [WITH w];'. Anything else is rejected at the line where it starts.
 */
public final class SmallFcl implements FclImplementation {
    private static final Pattern TOKEN = Pattern.compile("(\\(\\*.*?\\*\\))|(\\s+)"
            + "|([+-]?\\d[\\d_]*(?:\\.[\\d_]+)?(?:[eE][+-]?[\\d_]+)?)|([A-Za-z_]\\w*)|(:=|[():;,])", Pattern.DOTALL);
    private static final Pattern NUMBER = Pattern.compile("[+-]?\\d(?:_?\\d)*(?:\\.\\d(?:_?\\d)*(?:[eE][+-]?\\d(?:_?\\d)*)?)?");
    private static final Pattern IDENTIFIER = Pattern.compile("(?:[A-Za-z]|_[A-Za-z0-9])(?:_?[A-Za-z0-9])*");
    private static final Set<String> RESERVED = Set.of(("ACCU ACT AND ASUM BDIF BSUM COA COG COGS DEFAULT DEFUZZIFY"
            + " END_DEFUZZIFY END_FUNCTION_BLOCK END_FUZZIFY END_OPTIONS END_RULEBLOCK END_VAR FUNCTION_BLOCK FUZZIFY IF"
            + " IS LM MAX METHOD MIN NC NOT NSUM OPTIONS OR PROD RANGE RM RULE RULEBLOCK TERM THEN VAR VAR_INPUT"
            + " VAR_OUTPUT WITH REAL LREAL SINT INT DINT LINT USINT UINT UDINT ULINT").split(" "));
    private static final Map<String, double[]> INTEGERS = Map.of("SINT", range(7, true), "INT", range(15, true),
            "DINT", range(31, true), "LINT", range(63, true), "USINT", range(8, false), "UINT", range(16, false),
            "UDINT", range(32, false), "ULINT", range(64, false));

    private static double[] range(int bits, boolean signed) {
        double top = Math.pow(2, bits);
        return signed ? new double[] {-top, top - 1} : new double[] {0, top - 1};
    }

    @Override
    public String name() {
        return "Small FCL";
    }

    @Override
    public String version() {
        return "1.0";
    }

    @Override
    public List<String> claims() {
        return List.of("B-FB", "B-IN-TERM", "B-OUT-SINGLETON", "B-AND-MIN", "B-ACCU-MAX", "B-COGS",
                "B-DEFAULT-VALUE", "B-DEFAULT-NC", "B-ONE-RULEBLOCK", "B-SUBCONDITIONS", "B-ONE-SUBCONCLUSION");
    }

    @Override
    public FclLoadResult load(String fcl) {
        try {
            List<Block> blocks = new Parser(fcl).program();
            return FclLoadResult.loaded(new Program(blocks));
        } catch (Reject r) {
            return FclLoadResult.rejected(r.getMessage(), r.line);
        }
    }

    /** A refusal of the program at a line. */
    static final class Reject extends Exception {
        private static final long serialVersionUID = 1L;
        final int line;

        Reject(String message, int line) {
            super(message);
            this.line = line;
        }
    }

    record Token(String kind, String text, double number, int line) {
    }

    record Variable(String name, String type, double initial) {
    }

    record Cond(String variable, String term, int line) {
    }

    record Rule(List<Cond> conditions, Cond conclusion, double weight, int andLine) {
    }

    static final class Output {
        final Map<String, Double> terms = new LinkedHashMap<>();
        String method;
        Double defaultValue;   // null: NC
        boolean hasDefault;
    }

    static final class Block {
        String name;
        final Map<String, Variable> inputs = new LinkedHashMap<>();
        final Map<String, Variable> outputs = new LinkedHashMap<>();
        final Map<String, Map<String, double[][]>> fuzzify = new HashMap<>();
        final Map<String, Output> defuzzify = new LinkedHashMap<>();
        List<Rule> rules;
    }

    static final class Parser {
        private final List<Token> tokens = new ArrayList<>();
        private int i;

        Parser(String text) {
            Matcher m = TOKEN.matcher(text);
            int pos = 0;
            int line = 1;
            while (pos < text.length()) {
                if (!m.region(pos, text.length()).lookingAt()) {
                    tokens.add(new Token("bad", text.startsWith("(*", pos) ? "comment is never closed"
                            : "unexpected '" + text.charAt(pos) + "'", 0, line));
                    break;
                }
                String value = m.group();
                if (m.group(3) != null) {
                    tokens.add(NUMBER.matcher(value).matches()
                            ? new Token("number", value, Double.parseDouble(value.replace("_", "")), line)
                            : new Token("bad", "malformed number '" + value + "'", 0, line));
                } else if (m.group(4) != null) {
                    tokens.add(IDENTIFIER.matcher(value).matches() ? new Token("name", value, 0, line)
                            : new Token("bad", "malformed identifier '" + value + "'", 0, line));
                } else if (m.group(5) != null) {
                    tokens.add(new Token(value, value, 0, line));
                }
                line += (int) value.chars().filter(c -> c == '\n').count();
                pos = m.end();
            }
            tokens.add(new Token("eof", "end of text", 0, line));
        }

        Token peek() throws Reject {
            Token t = tokens.get(i);
            if (t.kind().equals("bad")) {
                throw new Reject(t.text(), t.line());
            }
            return t;
        }

        int line() throws Reject {
            return peek().line();
        }

        Token take() throws Reject {
            Token t = peek();
            i++;
            return t;
        }

        boolean at(String... words) throws Reject {
            Token t = peek();
            for (String w : words) {
                if (t.kind().equals("name") ? t.text().toUpperCase(Locale.ROOT).equals(w) : t.kind().equals(w)) {
                    return true;
                }
            }
            return false;
        }

        Reject fail(String what) throws Reject {
            Token t = peek();
            int line = t.line();
            if (what.equals(";") && i > 0 && tokens.get(i - 1).line() < line) {
                line = tokens.get(i - 1).line();   // a missing ';' is the mistake of the line that lacks it
            }
            return new Reject("expected " + what + ", found '" + t.text() + "'", line);
        }

        Token expect(String word) throws Reject {
            if (!at(word)) {
                throw fail(word);
            }
            return take();
        }

        String name() throws Reject {
            if (!peek().kind().equals("name")) {
                throw fail("a name");
            }
            if (RESERVED.contains(peek().text().toUpperCase(Locale.ROOT))) {
                throw new Reject(peek().text() + " is a keyword and cannot be used as a name", line());
            }
            return take().text();
        }

        double number() throws Reject {
            if (!peek().kind().equals("number")) {
                throw fail("a number");
            }
            return take().number();
        }

        Reject unsupported(String what) throws Reject {
            return new Reject((what == null ? "'" + peek().text() + "'" : what) + " is not supported at the Basic Level",
                    line());
        }

        List<Block> program() throws Reject {
            if (at("eof")) {
                throw new Reject("the text holds no FUNCTION_BLOCK", 1);
            }
            List<Block> blocks = new ArrayList<>();
            do {
                blocks.add(block());
            } while (!at("eof"));
            return blocks;
        }

        private static final List<String> ORDER = List.of("VAR_INPUT", "FUZZIFY", "DEFUZZIFY", "RULEBLOCK");

        Block block() throws Reject {
            expect("FUNCTION_BLOCK");
            Block fb = new Block();
            fb.name = name();
            int last = 0;
            while (!at("END_FUNCTION_BLOCK")) {
                String keyword = peek().text().toUpperCase(Locale.ROOT);
                int rank = ORDER.indexOf(keyword.equals("VAR_OUTPUT") ? "VAR_INPUT" : keyword);
                if (rank < 0) {
                    throw at("eof") ? fail("END_FUNCTION_BLOCK") : unsupported(null);
                }
                if (rank < last) {
                    throw new Reject(keyword + " must come before " + ORDER.get(last), line());
                }
                last = rank;
                switch (keyword) {
                    case "VAR_INPUT", "VAR_OUTPUT" -> variables(fb);
                    case "FUZZIFY" -> fuzzify(fb);
                    case "DEFUZZIFY" -> defuzzify(fb);
                    default -> ruleblock(fb);
                }
            }
            take();
            resolve(fb);
            return fb;
        }

        void variables(Block fb) throws Reject {
            Map<String, Variable> table = take().text().equalsIgnoreCase("VAR_INPUT") ? fb.inputs : fb.outputs;
            while (!at("END_VAR")) {
                int line = line();
                List<String> names = new ArrayList<>(List.of(name()));
                while (at(",")) {
                    take();
                    names.add(name());
                }
                expect(":");
                String type = peek().text().toUpperCase(Locale.ROOT);
                if (!peek().kind().equals("name") || !type.equals("REAL") && !type.equals("LREAL")
                        && !INTEGERS.containsKey(type)) {
                    throw unsupported("data type '" + peek().text() + "'");
                }
                take();
                double init = 0;
                if (at(":=")) {
                    take();
                    init = number();
                }
                expect(";");
                double[] bounds = INTEGERS.getOrDefault(type, new double[] {Double.NEGATIVE_INFINITY,
                    Double.POSITIVE_INFINITY});
                if (init < bounds[0] || init > bounds[1] || INTEGERS.containsKey(type) && init != Math.rint(init)) {
                    throw new Reject("initial value " + init + " does not fit " + type, line);
                }
                for (String n : names) {
                    String key = n.toLowerCase(Locale.ROOT);
                    if (fb.inputs.containsKey(key) || fb.outputs.containsKey(key)) {
                        throw new Reject("variable " + n + " is declared twice", line);
                    }
                    table.put(key, new Variable(n, type, init));
                }
            }
            take();
        }

        void fuzzify(Block fb) throws Reject {
            take();
            int line = line();
            String variable = name().toLowerCase(Locale.ROOT);
            if (!fb.inputs.containsKey(variable) || fb.fuzzify.containsKey(variable)) {
                throw new Reject("FUZZIFY " + variable + ": not a declared input, or fuzzified twice", line);
            }
            Map<String, double[][]> terms = new HashMap<>();
            fb.fuzzify.put(variable, terms);
            while (at("TERM")) {
                take();
                line = line();
                String term = name().toLowerCase(Locale.ROOT);
                expect(":=");
                List<double[]> points = new ArrayList<>();
                while (at("(")) {
                    take();
                    double x = number();
                    expect(",");
                    points.add(new double[] {x, number()});
                    expect(")");
                    if (at(",") && tokens.get(i + 1).kind().equals("(")) {
                        take();   // points may be separated by commas, as in figure 5
                    }
                }
                expect(";");
                boolean ascending = true;
                for (int k = 1; k < points.size(); k++) {
                    ascending &= points.get(k - 1)[0] <= points.get(k)[0];
                }
                if (points.size() < 2 || points.size() > 3 || !ascending) {
                    throw new Reject("term " + term + " needs 2 or 3 points in ascending order", line);
                }
                if (points.stream().anyMatch(p -> p[1] < 0 || p[1] > 1)) {
                    throw new Reject("term " + term + " has a degree outside [0, 1]", line);
                }
                if (terms.put(term, points.toArray(new double[0][])) != null) {
                    throw new Reject("term " + term + " is defined twice", line);
                }
            }
            expect("END_FUZZIFY");
        }

        private static final List<String> DEFUZZIFY_ORDER = List.of("TERM", "METHOD", "DEFAULT");

        void defuzzify(Block fb) throws Reject {
            int start = take().line();
            int line = line();
            String variable = name().toLowerCase(Locale.ROOT);
            if (!fb.outputs.containsKey(variable) || fb.defuzzify.containsKey(variable)) {
                throw new Reject("DEFUZZIFY " + variable + ": not a declared output, or defuzzified twice", line);
            }
            Output out = new Output();
            fb.defuzzify.put(variable, out);
            int last = 0;
            while (!at("END_DEFUZZIFY")) {
                line = line();
                String keyword = take().text().toUpperCase(Locale.ROOT);
                int rank = DEFUZZIFY_ORDER.indexOf(keyword);
                if (rank >= 0 && (rank < last || rank == last && last > 0)) {
                    throw new Reject(keyword + " is out of place (order: TERMs, METHOD, DEFAULT; once each)", line);
                }
                last = Math.max(last, rank);
                switch (keyword) {
                    case "TERM" -> {
                        line = line();
                        String term = name().toLowerCase(Locale.ROOT);
                        if (out.terms.containsKey(term)) {
                            throw new Reject("term " + term + " is defined twice", line);
                        }
                        expect(":=");
                        out.terms.put(term, number());
                    }
                    case "METHOD" -> {
                        expect(":");
                        if (!at("COGS")) {
                            throw unsupported(null);
                        }
                        out.method = take().text();
                    }
                    case "DEFAULT" -> {
                        expect(":=");
                        out.defaultValue = at("NC") ? null : Double.valueOf(number());
                        if (out.defaultValue == null) {
                            take();
                        }
                        out.hasDefault = true;
                    }
                    default -> {
                        i--;
                        throw unsupported(null);
                    }
                }
                expect(";");
            }
            take();
            if (out.method == null || !out.hasDefault) {
                throw new Reject("DEFUZZIFY " + variable + " needs METHOD: CoGS and a DEFAULT", start);
            }
        }

        private static final List<String> RULEBLOCK_ORDER = List.of("AND", "ACT", "ACCU", "RULE");
        private static final Map<String, List<String>> SETTINGS = Map.of("AND", List.of("MIN"),
                "ACT", List.of("MIN", "PROD"), "ACCU", List.of("MAX"));

        void ruleblock(Block fb) throws Reject {
            if (fb.rules != null) {
                throw unsupported("a second RULEBLOCK");
            }
            int start = take().line();
            name();
            fb.rules = new ArrayList<>();
            Set<String> declared = new HashSet<>();
            Set<String> names = new HashSet<>();
            int last = -1;
            while (!at("END_RULEBLOCK")) {
                String keyword = peek().text().toUpperCase(Locale.ROOT);
                int rank = RULEBLOCK_ORDER.indexOf(keyword);
                if (rank < 0) {
                    throw unsupported(null);
                }
                if (rank < last || rank == last && rank < 3) {
                    throw new Reject(keyword + " is out of place (order: AND, ACT, ACCU, rules)", line());
                }
                last = rank;
                if (keyword.equals("RULE")) {
                    fb.rules.add(rule(names));
                    continue;
                }
                take();
                expect(":");
                if (!at(SETTINGS.get(keyword).toArray(new String[0]))) {
                    throw unsupported(null);
                }
                take();
                expect(";");
                declared.add(keyword);
            }
            take();
            if (!declared.contains("ACCU")) {
                throw new Reject("the rule block needs ACCU: MAX", start);
            }
            for (Rule r : fb.rules) {
                if (r.andLine() > 0 && !declared.contains("AND")) {
                    throw new Reject("AND is used but the rule block does not declare AND: MIN", r.andLine());
                }
            }
        }

        Rule rule(Set<String> names) throws Reject {
            take();
            if (!peek().kind().equals("name") && !peek().kind().equals("number")) {
                throw fail("a rule name or number");
            }
            int line = line();
            String name = take().text().toLowerCase(Locale.ROOT);
            if (!names.add(name)) {
                throw new Reject("rule " + name + " is defined twice", line);
            }
            expect(":");
            expect("IF");
            List<Cond> conditions = new ArrayList<>(List.of(subcondition()));
            int andLine = 0;
            while (at("AND")) {
                andLine = andLine > 0 ? andLine : line();
                take();
                conditions.add(subcondition());
            }
            if (!at("THEN")) {
                throw at("OR", "NOT", "(") ? unsupported(null) : fail("THEN");
            }
            take();
            line = line();
            String variable = name().toLowerCase(Locale.ROOT);
            expect("IS");
            Cond conclusion = new Cond(variable, name().toLowerCase(Locale.ROOT), line);
            double weight = 1;
            if (at("WITH")) {
                throw unsupported("WITH");
            }
            if (at(",")) {
                throw unsupported("a second subconclusion");
            }
            expect(";");
            return new Rule(conditions, conclusion, weight, andLine);
        }

        Cond subcondition() throws Reject {
            if (at("(", "NOT")) {
                throw unsupported(null);
            }
            int line = line();
            String variable = name().toLowerCase(Locale.ROOT);
            expect("IS");
            if (at("NOT")) {
                throw unsupported(null);
            }
            return new Cond(variable, name().toLowerCase(Locale.ROOT), line);
        }

        /** Every subcondition names a fuzzified input's term, every conclusion a defuzzified output's term. */
        static void resolve(Block fb) throws Reject {
            for (Rule r : fb.rules == null ? List.<Rule>of() : fb.rules) {
                for (Cond c : r.conditions()) {
                    if (!fb.fuzzify.getOrDefault(c.variable(), Map.of()).containsKey(c.term())) {
                        throw new Reject(c.variable() + " IS " + c.term() + ": no such input term", c.line());
                    }
                }
                Cond c = r.conclusion();
                Output out = fb.defuzzify.get(c.variable());
                if (out == null || !out.terms.containsKey(c.term())) {
                    throw new Reject(c.variable() + " IS " + c.term() + ": no such output term", c.line());
                }
            }
        }
    }

    /** Linear between points, constant beyond the outer ones; at a vertical edge the larger degree. */
    static double membership(double[][] points, double x) {
        double at = -1;
        for (double[] p : points) {
            if (p[0] == x) {
                at = Math.max(at, p[1]);
            }
        }
        if (at >= 0) {
            return at;
        }
        if (x <= points[0][0]) {
            return points[0][1];
        }
        for (int k = 1; k < points.length; k++) {
            double[] a = points[k - 1];
            double[] b = points[k];
            if (x <= b[0]) {
                return b[0] == a[0] ? b[1] : a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
            }
        }
        return points[points.length - 1][1];
    }

    record Program(List<Block> functionBlocks) implements FclProgram {
        @Override
        public List<String> blocks() {
            return functionBlocks.stream().map(b -> b.name).toList();
        }

        @Override
        public FclInstance newInstance(String name) {
            Block fb = name == null ? functionBlocks.get(0) : functionBlocks.stream().filter(b -> b.name.equalsIgnoreCase(name))
                    .findFirst().orElseThrow(() -> new IllegalArgumentException("no function block " + name));
            return new Instance(fb);
        }
    }

    static final class Instance implements FclInstance {
        private final Block fb;
        private final Map<String, Double> in = new HashMap<>();
        private final Map<String, Double> out = new HashMap<>();

        Instance(Block fb) {
            this.fb = fb;
            reset();
        }

        @Override
        public void set(String name, double value) {
            String key = name.toLowerCase(Locale.ROOT);
            if (!in.containsKey(key)) {
                throw new IllegalArgumentException(name + " is not an input of " + fb.name);
            }
            // an integer input takes the value rounded half away from zero, and it must fit its type (8.)
            in.put(key, crisp(fb.inputs.get(key), value));
        }

        /** MIN over subconditions; MAX per output term; CoGS; DEFAULT (or NC) when no rule fired. */
        @Override
        public void evaluate() {
            Map<String, Double> degrees = new HashMap<>();
            for (Rule r : fb.rules == null ? List.<Rule>of() : fb.rules) {
                double d = 1;
                for (Cond c : r.conditions()) {
                    d = Math.min(d, membership(fb.fuzzify.get(c.variable()).get(c.term()), in.get(c.variable())));
                }
                degrees.merge(r.conclusion().variable() + " " + r.conclusion().term(), d * r.weight(), Math::max);
            }
            fb.defuzzify.forEach((variable, o) -> {
                double weighted = 0;
                double total = 0;
                for (Map.Entry<String, Double> t : o.terms.entrySet()) {
                    double d = degrees.getOrDefault(variable + " " + t.getKey(), 0.0);
                    weighted += d * t.getValue();
                    total += d;
                }
                if (total > 0) {
                    out.put(variable, crisp(fb.outputs.get(variable), weighted / total));
                } else if (o.defaultValue != null) {
                    out.put(variable, crisp(fb.outputs.get(variable), o.defaultValue));
                }
            });
        }

        /** An integer variable (input or output) gets the value rounded half away from zero, and it must fit its type. */
        private static double crisp(Variable v, double value) {
            double[] bounds = INTEGERS.get(v.type());
            if (bounds == null) {
                return value;
            }
            double rounded = Math.signum(value) * Math.floor(Math.abs(value) + 0.5);
            if (rounded < bounds[0] || rounded > bounds[1]) {
                throw new IllegalStateException(v.name() + " = " + rounded + " does not fit " + v.type());
            }
            return rounded;
        }

        @Override
        public double get(String name) {
            Double value = out.get(name.toLowerCase(Locale.ROOT));
            if (value == null) {
                throw new IllegalArgumentException(name + " is not an output of " + fb.name);
            }
            return value;
        }

        @Override
        public void reset() {
            fb.inputs.forEach((k, v) -> in.put(k, v.initial()));
            fb.outputs.forEach((k, v) -> out.put(k, v.initial()));
        }
    }
}
