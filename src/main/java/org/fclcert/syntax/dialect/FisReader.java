package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.model.ShapeKind;
import org.fclcert.syntax.ReadResult;

/**
 * Reads MATLAB's FIS text ({@code .fis}), Mamdani and Sugeno, as the Octave fuzzy-logic-toolkit and fuzzylite read
 * it (with fuzzylite's additions: its extra membership functions, norms and per-variable keys). The file is
 * restated line by line as fuzzylite FCL and read by the fuzzylite dialect ({@link EngineText}), fuzzylite's
 * reading of FIS; where Octave computes otherwise (it samples every fuzzy set at 101 points) docs/dialects.md says
 * so. Names that are no FCL identifier ({@code 'Ten-Percent'}) are read with each run of other characters as '_'.
 */
public final class FisReader implements DialectReader {
    private static final Pattern SECTION = Pattern.compile("\\[(System|Input|Output|Rules)(\\d*)\\]");
    private static final Pattern MF = Pattern.compile("MF(\\d+)\\s*=\\s*'([^']*)'\\s*:\\s*'([^']*)'\\s*,\\s*\\[(.*)\\]");
    private static final Pattern RULE = Pattern.compile("([^,]*),([^(]*)\\(([^)]*)\\)\\s*:\\s*(\\S+)");

    /** MATLAB's and fuzzylite's t-norm names in FIS, and their fuzzylite FCL names. */
    private static final Map<String, String> T_NORMS = Map.of("min", "MIN", "prod", "PROD",
            "bounded_difference", "BDIF", "drastic_product", "DPROD", "einstein_product", "EPROD",
            "hamacher_product", "HPROD", "nilpotent_minimum", "NMIN");
    /** The s-norm names, and their fuzzylite FCL names. */
    private static final Map<String, String> S_NORMS = Map.of("max", "MAX", "probor", "ASUM", "bounded_sum", "BSUM",
            "drastic_sum", "DSUM", "einstein_sum", "ESUM", "hamacher_sum", "HSUM", "nilpotent_maximum", "NMAX",
            "normalized_sum", "NSUM", "sum", "SUM");
    private static final Map<String, String> DEFUZZIFIERS = Map.of("centroid", "COG", "bisector", "COA",
            "mom", "MM", "som", "LM", "lom", "RM", "wtaver", "COGS", "wtsum", "COGSS");

    /**
     * A membership function's FIS name, its fuzzylite class and the written position of each of the class's
     * parameters (null: as written, any count).
     */
    private record Shape(String fuzzylite, int[] order) {
    }

    private static final Map<String, Shape> SHAPES = Map.ofEntries(
            Map.entry("trimf", new Shape("Triangle", new int[] {0, 1, 2})),
            Map.entry("trapmf", new Shape("Trapezoid", new int[] {0, 1, 2, 3})),
            Map.entry("gaussmf", new Shape("Gaussian", new int[] {1, 0})),
            Map.entry("gauss2mf", new Shape("GaussianProduct", new int[] {1, 0, 3, 2})),
            Map.entry("gbellmf", new Shape("Bell", new int[] {2, 0, 1})),
            Map.entry("sigmf", new Shape("Sigmoid", new int[] {1, 0})),
            Map.entry("dsigmf", new Shape("SigmoidDifference", new int[] {1, 0, 2, 3})),
            Map.entry("psigmf", new Shape("SigmoidProduct", new int[] {1, 0, 2, 3})),
            Map.entry("smf", new Shape("SShape", new int[] {0, 1})),
            Map.entry("zmf", new Shape("ZShape", new int[] {0, 1})),
            Map.entry("pimf", new Shape("PiShape", new int[] {0, 1, 2, 3})),
            Map.entry("rampmf", new Shape("Ramp", new int[] {0, 1})),
            Map.entry("rectmf", new Shape("Rectangle", new int[] {0, 1})),
            Map.entry("concavemf", new Shape("Concave", new int[] {0, 1})),
            Map.entry("cosinemf", new Shape("Cosine", new int[] {0, 1})),
            Map.entry("spikemf", new Shape("Spike", new int[] {0, 1})),
            Map.entry("discretemf", new Shape("Discrete", null)),
            Map.entry("constant", new Shape("Constant", new int[] {0})),
            Map.entry("linear", new Shape("Linear", null)),
            Map.entry("function", new Shape("Function", null)));

    /** fuzzylite's hedges in a rule's index, by its fraction (as its FIS exporter writes them and its importer reads). */
    private static final Map<Integer, String> HEDGES = Map.of(5, "somewhat", 20, "very", 30, "extremely",
            40, "very very", 99, "any");

    /** The FIS name of a t-norm fuzzylite's FCL calls {@code fcl} ({@code PROD}: {@code prod}), as this reader maps it. */
    public static Optional<String> fisTNorm(String fcl) {
        return inverse(T_NORMS, fcl);
    }

    /** The FIS name of an s-norm fuzzylite's FCL calls {@code fcl} ({@code ASUM}: {@code probor}). */
    public static Optional<String> fisSNorm(String fcl) {
        return inverse(S_NORMS, fcl);
    }

    /** The FIS name of a defuzzifier fuzzylite's FCL calls {@code fcl} ({@code MM}: {@code mom}). */
    public static Optional<String> fisDefuzzifier(String fcl) {
        return inverse(DEFUZZIFIERS, fcl);
    }

    /**
     * The FIS membership function of fuzzylite's shape class {@code fuzzylite} ({@code Gaussian}: {@code gaussmf})
     * and the position each of the class's parameters is written at, as this reader reads them back.
     */
    public static Optional<Map.Entry<String, int[]>> fisShape(String fuzzylite) {
        return SHAPES.entrySet().stream().filter(e -> e.getValue().fuzzylite().equals(fuzzylite)
                && e.getValue().order() != null).findFirst().map(e -> Map.entry(e.getKey(), e.getValue().order().clone()));
    }

    /**
     * Where a sigmoid difference (fclcert's canonical parameters: left, rising, falling, right) has f2 &gt; f1, which
     * the Octave toolkit 0.4.6's dsigmf bounds to 0 (its dsigmf.m: max (0, min (1, f1 - f2))) while fuzzylite, and
     * this reader, take |f1 - f2|: {x, the largest f2 - f1}, {NaN, 0} where there is none. f2 &gt; f1 exactly where
     * falling·(x - right) &gt; rising·(x - left), a half-line unless the slopes are equal; both sigmoids are within
     * e^-40 of 0 or 1 farther than 40 / slope from their inflections, so the window searched (8000 steps) holds
     * every difference above 1e-17.
     */
    public static double[] dsigmfClamped(double[] q) {
        double slope = q.length == 4 ? Math.min(Math.abs(q[1]), Math.abs(q[2])) : Double.NaN;
        if (!(slope > 0) || !Double.isFinite(q[0]) || !Double.isFinite(q[3])) {
            return new double[] {Double.NaN, 0};
        }
        double lo = Math.min(q[0], q[3]) - 40 / slope;
        double hi = Math.max(q[0], q[3]) + 40 / slope;
        double[] first = {q[0], q[1]};
        double[] second = {q[3], q[2]};
        double[] worst = {Double.NaN, 0};
        for (int i = 0; i <= 8000; i++) {
            double x = lo + (hi - lo) * i / 8000;
            double d = ShapeKind.SIGMOID.degree(second, x) - ShapeKind.SIGMOID.degree(first, x);
            if (d > worst[1]) {
                worst[0] = x;
                worst[1] = d;
            }
        }
        return worst;
    }

    /**
     * The one wording of that difference for the reader's warning and the writer's finding: empty where the two
     * readings agree (the largest f2 - f1 at most 1e-9).
     */
    public static Optional<String> dsigmfDifference(double[] q) {
        double[] worst = dsigmfClamped(q);
        return worst[1] > 1e-9 ? Optional.of("where its second sigmoid exceeds its first (by up to "
                + String.format(Locale.ROOT, "%.3g", worst[1]) + " at " + String.format(Locale.ROOT, "%.4g", worst[0])
                + ") the Octave toolkit's dsigmf gives 0; fuzzylite and fclcert take |f1 - f2|") : Optional.empty();
    }

    private static Optional<String> inverse(Map<String, String> names, String fcl) {
        return names.entrySet().stream().filter(e -> e.getValue().equals(fcl)).map(Map.Entry::getKey).findFirst();
    }

    @Override
    public Dialect dialect() {
        return Dialect.FIS;
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return EngineText.read(sourceName, text, "FIS reader", FisReader::restate);
    }

    /** One variable of the file: its name and its terms' names, in order. */
    private record Variable(String name, List<String> terms, List<String> kinds, int line) {
    }

    private static String unquote(String v) {
        String s = v.strip();
        return s.length() >= 2 && s.startsWith("'") && s.endsWith("'") ? s.substring(1, s.length() - 1) : s;
    }

    static EngineText restate(String source, String text) {
        EngineText t = new EngineText(source, text);
        List<String> lines = t.lines();
        // first pass: sections, names and terms, the system's keys
        Map<String, String> system = new LinkedHashMap<>();
        List<Variable> inputs = new ArrayList<>();
        List<Variable> outputs = new ArrayList<>();
        String section = null;
        Variable current = null;
        for (int i = 0; i < lines.size(); i++) {
            String s = strip(lines.get(i));
            Matcher m = SECTION.matcher(s);
            if (m.matches()) {
                section = m.group(1);
                current = null;
                if (section.equals("Input") || section.equals("Output")) {
                    current = new Variable("", new ArrayList<>(), new ArrayList<>(), i);
                    (section.equals("Input") ? inputs : outputs).add(current);
                }
                continue;
            }
            int eq = s.indexOf('=');
            if (section == null || eq < 0 || section.equals("Rules")) {
                continue;
            }
            String key = s.substring(0, eq).strip();
            if (section.equals("System")) {
                system.put(key, unquote(s.substring(eq + 1)));
            } else if (key.equals("Name") && current != null) {
                (section.equals("Input") ? inputs : outputs).set((section.equals("Input") ? inputs : outputs)
                        .size() - 1, current = new Variable(unquote(s.substring(eq + 1)), current.terms(), current.kinds(), i));
            } else if (key.startsWith("MF") && current != null) {
                Matcher mf = MF.matcher(s);
                if (mf.matches()) {
                    current.terms().add(mf.group(2));
                    current.kinds().add(mf.group(3));
                }
            }
        }
        String type = system.getOrDefault("Type", "mamdani").toLowerCase(Locale.ROOT);
        // second pass: each line restated
        section = null;
        String close = "";
        int inputIndex = -1;
        int outputIndex = -1;
        int rules = 0;
        boolean sawSystem = false;
        Map<Integer, Map<Long, Integer>> concluded = new java.util.HashMap<>();
        Map<Integer, Integer> nameLines = new java.util.HashMap<>();
        for (int i = 0; i < lines.size(); i++) {
            String s = strip(lines.get(i));
            if (s.isEmpty()) {
                continue;
            }
            Matcher m = SECTION.matcher(s);
            if (m.matches()) {
                section = m.group(1);
                switch (section) {
                    case "System" -> {
                        sawSystem = true;
                        t.put(i, "FUNCTION_BLOCK " + EngineText.identifier(system.getOrDefault("Name", ""), "fis"));
                        // each declaration stands for the line that names the variable
                        int systemLine = i;
                        t.beforeNext("VAR_INPUT", systemLine);
                        inputs.forEach(v -> t.beforeNext(EngineText.identifier(v.name(), "input") + " : REAL;", v.line()));
                        t.beforeNext("END_VAR VAR_OUTPUT", systemLine);
                        outputs.forEach(v -> t.beforeNext(EngineText.identifier(v.name(), "output") + " : REAL;", v.line()));
                        t.beforeNext("END_VAR", systemLine);
                    }
                    case "Input" -> inputIndex++;
                    case "Output" -> outputIndex++;
                    default -> {
                        t.put(i, close, "RULEBLOCK rules");     // its name reads to the end of the line
                        close = "";
                        StringBuilder b = new StringBuilder();
                        setting(t, i, b, "AND", system.get("AndMethod"), T_NORMS, "AndMethod");
                        setting(t, i, b, "OR", system.get("OrMethod"), S_NORMS, "OrMethod");
                        setting(t, i, b, "ACT", system.get("ImpMethod"), T_NORMS, "ImpMethod");
                        if (b.length() > 0) {
                            t.beforeNext(b.toString().strip());
                        }
                        close = "END_RULEBLOCK ";
                    }
                }
                continue;
            }
            if (section == null) {
                t.error(i, DialectCode.SYNTAX, "expected '[System]' first (FIS), found '" + s + "'");
                section = "?";
                continue;
            }
            if (section.equals("Rules")) {
                rules++;
                rule(t, i, s, rules, inputs, outputs, concluded);
                continue;
            }
            int eq = s.indexOf('=');
            if (eq < 0) {
                t.error(i, DialectCode.SYNTAX, "expected 'Key=value' (FIS), found '" + s + "'");
                continue;
            }
            String key = s.substring(0, eq).strip();
            String value = unquote(s.substring(eq + 1));
            if (section.equals("System") || section.equals("?")) {
                if (key.equals("Type") && !List.of("mamdani", "sugeno", "tsukamoto", "hybrid").contains(type)) {
                    t.error(i, DialectCode.UNSUPPORTED, "Type '" + value + "': fclcert reads mamdani and sugeno FIS"
                            + " (and fuzzylite's tsukamoto and hybrid)");
                }
                continue;
            }
            boolean input = section.equals("Input");
            Variable v = input ? inputs.get(inputIndex) : outputs.get(outputIndex);
            String name = EngineText.identifier(v.name(), input ? "input" : "output");
            switch (key) {
                case "Name" -> {
                    if (!input) {
                        nameLines.put(outputIndex, i);
                    }
                    StringBuilder b = new StringBuilder(input ? "FUZZIFY " : "DEFUZZIFY ").append(name);
                    if (!input) {
                        outputSettings(t, i, b, v, type, system);
                    }
                    t.put(i, close, b.toString());
                    close = input ? "END_FUZZIFY " : "END_DEFUZZIFY ";
                }
                case "Range" -> {
                    t.range(i, value.replace("[", "").replace("]", "").strip().split("[\\s,]+"), "Range=[MIN MAX]");
                }
                case "NumMFs" -> { }
                case "Enabled" -> {
                    if (!value.equals("1")) {
                        t.error(i, DialectCode.UNSUPPORTED, "a disabled variable (Enabled=" + value + ") is not"
                                + " evaluated by fclcert");
                    }
                }
                case "LockRange" -> {
                    if (value.equals("1")) {
                        if (input) {
                            t.error(i, DialectCode.UNSUPPORTED, "LockRange=1 on an input (fuzzylite then clamps the"
                                    + " input's value to its range) is not evaluated by fclcert");
                        } else {
                            t.put(i, "LOCK : RANGE;");
                        }
                    }
                }
                case "LockPrevious" -> {
                    if (value.equals("1") && !input) {
                        t.put(i, "LOCK : PREVIOUS;");
                    }
                }
                case "Default" -> { }
                default -> {
                    if (key.startsWith("MF")) {
                        term(t, i, s, v.name());
                    } else {
                        t.error(i, DialectCode.SYNTAX, "'" + key + "' is no key of a FIS variable");
                    }
                }
            }
        }
        if (!sawSystem) {
            t.error(0, DialectCode.SYNTAX, "no '[System]' section: not a FIS file");
        }
        // Sugeno outputs: MATLAB and fuzzylite average every rule's value; Octave first aggregates by AggMethod the
        // rules that conclude one term
        String agg = system.getOrDefault("AggMethod", "max");
        for (int k = 0; k < outputs.size(); k++) {
            Variable v = outputs.get(k);
            boolean sugeno = !v.kinds().isEmpty() && v.kinds().stream().allMatch(x -> List.of("constant", "linear",
                    "function").contains(x));
            long repeated = concluded.getOrDefault(k, Map.of()).values().stream().filter(c -> c > 1).count();
            if (sugeno && repeated > 0 && !agg.equalsIgnoreCase("sum")) {
                t.warn(nameLines.getOrDefault(k, 0), DialectCode.FIS_SUM, "'" + v.name() + "' (Sugeno): read as MATLAB"
                        + " and fuzzylite read it, the weighted average of every rule's value; Octave first takes the"
                        + " AggMethod '" + agg + "' of the rules concluding one term (here " + repeated + " terms are"
                        + " concluded by several rules)");
            }
        }
        t.end(close + "END_FUNCTION_BLOCK");
        return t;
    }

    /** A line without its comment ({@code #} or {@code %}, outside quotes). */
    private static String strip(String line) {
        boolean quoted = false;
        for (int k = 0; k < line.length(); k++) {
            char c = line.charAt(k);
            if (c == '\'') {
                quoted = !quoted;
            } else if (!quoted && (c == '#' || c == '%')) {
                return line.substring(0, k).strip();
            }
        }
        return line.strip();
    }

    private static void setting(EngineText t, int i, StringBuilder b, String keyword, String value,
            Map<String, String> names, String key) {
        if (value == null || value.isEmpty()) {
            return;
        }
        String n = names.get(value.toLowerCase(Locale.ROOT));
        if (n == null) {
            t.error(i, DialectCode.SYNTAX, key + " '" + value + "' is none of " + String.join(", ",
                    names.keySet().stream().sorted().toList()));
        } else {
            b.append(' ').append(keyword).append(" : ").append(n).append(';');
        }
    }

    /**
     * METHOD, ACCU and DEFAULT of an output: an output of only constant, linear or function terms is a weighted
     * average (wtaver) or sum (wtsum) of them, whatever the file's AggMethod (as Octave and fuzzylite read Sugeno);
     * other outputs are defuzzified by DefuzzMethod after accumulation by AggMethod.
     */
    private static void outputSettings(EngineText t, int i, StringBuilder b, Variable v, String type,
            Map<String, String> system) {
        boolean sugeno = !v.kinds().isEmpty() && v.kinds().stream().allMatch(k -> List.of("constant", "linear",
                "function").contains(k));
        String method = system.getOrDefault("DefuzzMethod", "centroid").toLowerCase(Locale.ROOT);
        if (sugeno || method.equals("wtaver") || method.equals("wtsum")) {
            // a weighted average of fuzzy sets is fuzzylite's Tsukamoto's method (monotonic terms; the dialect checks)
            b.append(" METHOD : ").append(method.equals("wtsum") ? "COGSS" : "COGS").append(';');
        } else {
            String m = DEFUZZIFIERS.get(method);
            if (m == null) {
                t.error(i, DialectCode.SYNTAX, "DefuzzMethod '" + method + "' is none of " + String.join(", ",
                        DEFUZZIFIERS.keySet().stream().sorted().toList()));
            } else {
                b.append(" METHOD : ").append(m).append(';');
            }
            String agg = system.getOrDefault("AggMethod", "max");
            if (agg.equalsIgnoreCase("sum")) {
                t.warn(i, DialectCode.FIS_SUM, "AggMethod 'sum' of '" + v.name() + "': read as MATLAB and Octave add"
                        + " the rules' sets (ACCU SUM); fuzzylite 6 reads 'sum' as the algebraic sum (probor)");
            }
            String a = S_NORMS.get(agg.toLowerCase(Locale.ROOT));
            if (a == null) {
                t.error(i, DialectCode.SYNTAX, "AggMethod '" + agg + "' is none of " + String.join(", ",
                        S_NORMS.keySet().stream().sorted().toList()));
            } else {
                b.append(" ACCU : ").append(FuzzyliteDialect.accumulationWord(a)).append(';');
            }
        }
        b.append(" DEFAULT := nan;");
    }

    private static void term(EngineText t, int i, String s, String variable) {
        Matcher m = MF.matcher(s);
        if (!m.matches()) {
            t.error(i, DialectCode.SYNTAX, "expected MFn='name':'type',[parameters], found '" + s + "'");
            return;
        }
        Shape shape = SHAPES.get(m.group(3));
        if (shape == null) {
            t.error(i, DialectCode.UNKNOWN_SHAPE, "membership function '" + m.group(3) + "' of '" + variable
                    + "' is none of " + String.join(", ", SHAPES.keySet().stream().sorted().toList()));
            return;
        }
        String name = EngineText.identifier(m.group(2), "term" + m.group(1));
        String params = m.group(4).strip();
        if (shape.fuzzylite().equals("Function")) {
            t.put(i, "TERM " + name + " := Function " + params + ";");
            return;
        }
        String[] p = params.isEmpty() ? new String[0] : params.split("[\\s,]+");
        List<String> numbers = new ArrayList<>();
        for (String x : p) {
            Optional<String> n = EngineText.number(x);
            if (n.isEmpty()) {
                t.error(i, DialectCode.BAD_NUMBER, "'" + x + "' in the parameters of '" + m.group(2) + "' is no number");
                return;
            }
            numbers.add(n.get());
        }
        if (shape.order() != null && numbers.size() != shape.order().length) {
            t.error(i, DialectCode.SYNTAX, "'" + m.group(3) + "' takes " + shape.order().length + " parameters, '"
                    + m.group(2) + "' has " + numbers.size());
            return;
        }
        if (m.group(3).equals("dsigmf")) {
            double[] q = new double[4];
            for (int k = 0; k < 4; k++) {
                q[k] = Double.parseDouble(numbers.get(shape.order()[k]).replace("inf", "Infinity").replace("nan", "NaN"));
            }
            dsigmfDifference(q).ifPresent(d -> t.warn(i, DialectCode.FIS_DSIGMF, "dsigmf '" + m.group(2) + "' of '"
                    + variable + "' is read as fuzzylite reads it: " + d));
        }
        StringBuilder b = new StringBuilder("TERM ").append(name).append(" := ").append(shape.fuzzylite());
        for (int k = 0; k < numbers.size(); k++) {
            b.append(' ').append(numbers.get(shape.order() == null ? k : shape.order()[k]));
        }
        t.put(i, b.append(';').toString());
    }

    /** {@code a1 .. an , c1 .. cm (w) : 1|2}: the indices of the inputs' and the outputs' terms (0: none, < 0: not). */
    private static void rule(EngineText t, int i, String s, int number, List<Variable> inputs, List<Variable> outputs,
            Map<Integer, Map<Long, Integer>> concluded) {
        Matcher m = RULE.matcher(s);
        if (!m.matches()) {
            t.error(i, DialectCode.SYNTAX, "expected a rule 'i1 .. in, o1 .. om (weight) : 1|2', found '" + s + "'");
            return;
        }
        String[] ante = m.group(1).strip().split("\\s+");
        String[] cons = m.group(2).strip().split("\\s+");
        if (ante.length != inputs.size() || cons.length != outputs.size()) {
            t.error(i, DialectCode.SYNTAX, "a rule needs " + inputs.size() + " input and " + outputs.size()
                    + " output indices, this one has " + ante.length + " and " + cons.length);
            return;
        }
        String connective = m.group(4).strip();
        String join = switch (connective) {
            case "1", "1.000", "1.0" -> " and ";
            case "2", "2.000", "2.0" -> " or ";
            default -> null;
        };
        if (join == null) {
            t.error(i, DialectCode.SYNTAX, "a rule's connective is 1 (AND) or 2 (OR), not " + connective);
            return;
        }
        List<String> conditions = new ArrayList<>();
        for (int k = 0; k < ante.length; k++) {
            Optional<String> p = proposition(t, i, ante[k], inputs.get(k), true);
            if (p == null) {
                return;
            }
            p.ifPresent(conditions::add);
        }
        List<String> conclusions = new ArrayList<>();
        for (int k = 0; k < cons.length; k++) {
            Optional<String> p = proposition(t, i, cons[k], outputs.get(k), false);
            if (p == null) {
                return;
            }
            p.ifPresent(conclusions::add);
        }
        if (conditions.isEmpty() || conclusions.isEmpty()) {
            t.error(i, DialectCode.UNSUPPORTED, "a rule with no " + (conditions.isEmpty() ? "antecedent (every input"
                    + " index 0), which fuzzylite does not load" : "consequent (every output index 0)"));
            return;
        }
        Optional<String> weight = EngineText.number(m.group(3));
        if (weight.isEmpty()) {
            t.error(i, DialectCode.BAD_NUMBER, "a rule's weight '" + m.group(3).strip() + "' is no number");
            return;
        }
        for (int k = 0; k < cons.length; k++) {
            long term = Math.abs((long) Double.parseDouble(cons[k]));
            if (term > 0) {
                concluded.computeIfAbsent(k, x -> new java.util.HashMap<>()).merge(term, 1, Integer::sum);
            }
        }
        t.put(i, "RULE " + number + " : if " + String.join(join, conditions) + " then "
                + String.join(" and ", conclusions) + (Double.parseDouble(weight.get()) == 1 ? "" : " with "
                + weight.get()) + ";");
    }

    /** {@code variable is [hedges] term} of an index; empty for 0; null after an error. */
    private static Optional<String> proposition(EngineText t, int i, String index, Variable v, boolean input) {
        Optional<String> n = EngineText.number(index);
        if (n.isEmpty()) {
            t.error(i, DialectCode.BAD_NUMBER, "a rule's index '" + index + "' is no number");
            return null;
        }
        double x = Double.parseDouble(n.get());
        long whole = (long) Math.abs(x);
        int fraction = (int) Math.round((Math.abs(x) - whole) * 100);
        if (whole == 0 && fraction == 0) {
            return Optional.empty();
        }
        if (whole == 0 && fraction == 99 && input) {
            return Optional.of(EngineText.identifier(v.name(), "input") + " is any");
        }
        if (whole < 1 || whole > v.terms().size()) {
            t.error(i, DialectCode.SYNTAX, "index " + index + " names no term of '" + v.name() + "' (it has "
                    + v.terms().size() + ")");
            return null;
        }
        String hedge = fraction == 0 ? "" : HEDGES.get(fraction);
        if (hedge == null) {
            t.error(i, DialectCode.UNSUPPORTED, "index " + index + ": fclcert reads the hedges .05 (somewhat), .2 (very),"
                    + " .3 (extremely), .4 (very very) and 0.99 (any) only");
            return null;
        }
        if (fraction == 30 || !hedge.isEmpty() && !input) {
            t.warn(i, DialectCode.FIS_HEDGE, "index " + index + " of '" + v.name() + "': read as fuzzylite reads it"
                    + (input ? " (its 'extremely': 2x² below 0.5, 1 - 2(1 - x)² above); Octave raises the degree to the"
                    + " third power" : " (the hedge on the rule's degree); Octave hedges the output's term (Mamdani) or"
                    + " raises the degree to 1/hedge (Sugeno)"));
        }
        if (x < 0 && !input) {
            t.error(i, DialectCode.UNSUPPORTED, "a negated consequent (index " + index + ") is not evaluated by fclcert");
            return null;
        }
        String term = EngineText.identifier(v.terms().get((int) whole - 1), "term" + whole);
        return Optional.of(EngineText.identifier(v.name(), input ? "input" : "output") + " is "
                + (x < 0 ? "not " : "") + (hedge.isEmpty() ? "" : hedge + " ") + term);
    }

    @Override
    public List<Giveaway> giveaways(String text) {
        List<Giveaway> out = new ArrayList<>();
        List<String> lines = (text == null ? "" : text).lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            String s = lines.get(i).strip();
            if (s.equals("[System]")) {
                // the header of a whole-file format no FCL dialect has: decisive on its own
                out.add(new Giveaway("FIS section " + s, i + 1, 100));
            } else if (SECTION.matcher(s).matches()) {
                out.add(new Giveaway("FIS section " + s, i + 1, 6));
            } else if (MF.matcher(s).matches()) {
                out.add(new Giveaway("FIS membership function", i + 1, 6));
            }
        }
        return out;
    }
}
