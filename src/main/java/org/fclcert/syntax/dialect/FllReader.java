package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fclcert.syntax.ReadResult;

/**
 * Reads fuzzylite's FLL ({@code .fll}, fuzzylite 5 and 6): one {@code key: value} per line under the sections
 * {@code Engine}, {@code InputVariable}, {@code OutputVariable} and {@code RuleBlock}; {@code #} starts a comment.
 * Each line is restated as the fuzzylite FCL statement that means the same and read as fuzzylite's FCL
 * ({@link EngineText}): the shapes, norms, defuzzifiers, hedges and rules of FLL are fuzzylite's, so they mean what
 * docs/dialects.md says for fuzzylite. A key or a name fuzzylite would not read is a located FCL-S305 / S307.
 */
public final class FllReader implements DialectReader {
    /** FLL's t-norm class names and their fuzzylite FCL names. */
    public static final Map<String, String> T_NORMS = Map.of("Minimum", "MIN", "AlgebraicProduct", "PROD",
            "BoundedDifference", "BDIF", "DrasticProduct", "DPROD", "EinsteinProduct", "EPROD",
            "HamacherProduct", "HPROD", "NilpotentMinimum", "NMIN");
    /** FLL's s-norm class names and their fuzzylite FCL names. */
    public static final Map<String, String> S_NORMS = Map.of("Maximum", "MAX", "AlgebraicSum", "ASUM",
            "BoundedSum", "BSUM", "DrasticSum", "DSUM", "EinsteinSum", "ESUM", "HamacherSum", "HSUM",
            "NilpotentMaximum", "NMAX", "NormalizedSum", "NSUM", "UnboundedSum", "SUM");
    /** FLL's defuzzifier class names and their fuzzylite FCL METHOD. */
    public static final Map<String, String> DEFUZZIFIERS = Map.of("Centroid", "COG", "Bisector", "COA",
            "SmallestOfMaximum", "LM", "LargestOfMaximum", "RM", "MeanOfMaximum", "MM",
            "WeightedAverage", "COGS", "WeightedSum", "COGSS");
    private static final List<String> SECTIONS = List.of("Engine", "InputVariable", "OutputVariable", "RuleBlock");

    @Override
    public Dialect dialect() {
        return Dialect.FLL;
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return EngineText.read(sourceName, text, "FLL reader", FllReader::restate);
    }

    private record Line(int index, String key, String value) {
    }

    /** The file's lines as key and value, comments and blank lines left out. */
    private static List<Line> lines(EngineText t) {
        List<Line> out = new ArrayList<>();
        for (int i = 0; i < t.lines().size(); i++) {
            String s = t.lines().get(i);
            int hash = s.indexOf('#');
            s = (hash >= 0 ? s.substring(0, hash) : s).strip();
            if (s.isEmpty()) {
                continue;
            }
            int colon = s.indexOf(':');
            if (colon < 0) {
                t.error(i, DialectCode.SYNTAX, "expected 'key: value' (FLL), found '" + s + "'");
                continue;
            }
            out.add(new Line(i, s.substring(0, colon).strip(), s.substring(colon + 1).strip()));
        }
        return out;
    }

    static EngineText restate(String source, String text) {
        EngineText t = new EngineText(source, text);
        List<Line> lines = lines(t);
        List<Line> inputs = new ArrayList<>();
        List<Line> outputs = new ArrayList<>();
        for (Line l : lines) {
            if (l.key.equals("InputVariable")) {
                inputs.add(l);
            } else if (l.key.equals("OutputVariable")) {
                outputs.add(l);
            }
        }
        String section = null;
        String close = "";
        int ruleBlocks = 0;
        int rules = 0;
        boolean engine = false;
        for (Line l : lines) {
            if (SECTIONS.contains(l.key)) {
                if (l.key.equals("Engine")) {
                    if (engine || section != null) {
                        t.error(l.index, DialectCode.SYNTAX, "'Engine:' must come once, first (FLL)");
                        continue;
                    }
                    engine = true;
                    // fuzzylite reads a block's name to the end of its line: the declarations go on the next
                    t.put(l.index, "FUNCTION_BLOCK " + EngineText.identifier(l.value, "engine"));
                    // each declaration stands for the line that declares the variable
                    t.beforeNext("VAR_INPUT", l.index);
                    inputs.forEach(n -> t.beforeNext(n.value + " : REAL;", n.index));
                    t.beforeNext("END_VAR VAR_OUTPUT", l.index);
                    outputs.forEach(n -> t.beforeNext(n.value + " : REAL;", n.index));
                    t.beforeNext("END_VAR", l.index);
                    section = "Engine";
                    continue;
                }
                if (!engine) {
                    t.error(l.index, DialectCode.SYNTAX, "'" + l.key + ":' before 'Engine:' (FLL starts with it)");
                    engine = true;
                }
                if (l.value.isEmpty() && !l.key.equals("RuleBlock")) {
                    t.error(l.index, DialectCode.SYNTAX, "'" + l.key + ":' without a name");
                }
                String open = switch (l.key) {
                    case "InputVariable" -> "FUZZIFY " + l.value;
                    case "OutputVariable" -> "DEFUZZIFY " + l.value;
                    default -> "RULEBLOCK " + (l.value.isEmpty() ? "ruleblock" + (ruleBlocks + 1)
                            : EngineText.identifier(l.value, "ruleblock" + (ruleBlocks + 1)));
                };
                if (l.key.equals("RuleBlock")) {
                    ruleBlocks++;
                    rules = 0;
                }
                t.put(l.index, close, open);
                close = switch (l.key) {
                    case "InputVariable" -> "END_FUZZIFY ";
                    case "OutputVariable" -> "END_DEFUZZIFY ";
                    default -> "END_RULEBLOCK ";
                };
                section = l.key;
                continue;
            }
            if (section == null) {
                t.error(l.index, DialectCode.SYNTAX, "'" + l.key + ":' before 'Engine:' (FLL starts with it)");
                continue;
            }
            String key = l.key;
            String v = l.value;
            if (key.equals("description")) {
                continue;
            }
            switch (section + "." + key) {
                case "InputVariable.enabled", "OutputVariable.enabled", "RuleBlock.enabled" -> {
                    if (!v.equals("true")) {
                        t.put(l.index, "ENABLED : " + v.toUpperCase(Locale.ROOT) + ";");
                    }
                }
                case "InputVariable.range", "OutputVariable.range" -> {
                    t.range(l.index, v.split("\\s+"), "range: MIN MAX");
                }
                case "InputVariable.lock-range" -> {
                    if (l.value.equals("true")) {
                        t.error(l.index, DialectCode.UNSUPPORTED, "lock-range on an input (fuzzylite then clamps the"
                                + " input's value to its range) is not evaluated by fclcert");
                    } else {
                        flag(t, l, "");
                    }
                }
                case "OutputVariable.lock-range" -> flag(t, l, "LOCK : RANGE;");
                case "OutputVariable.lock-previous", "OutputVariable.lock-valid" -> flag(t, l, "LOCK : PREVIOUS;");
                case "InputVariable.term" -> term(t, l, false);
                case "OutputVariable.term" -> term(t, l, true);
                case "OutputVariable.aggregation", "OutputVariable.accumulation" -> {
                    if (!v.equals("none")) {
                        named(t, l, S_NORMS, "ACCU", "an s-norm");
                    }
                }
                case "OutputVariable.defuzzifier" -> {
                    if (!v.equals("none")) {
                        String[] w = v.split("\\s+");
                        String m = DEFUZZIFIERS.get(w[0]);
                        if (m == null) {
                            t.error(l.index, DialectCode.SYNTAX, "'" + w[0] + "' is no defuzzifier of fuzzylite ("
                                    + String.join(", ", DEFUZZIFIERS.keySet().stream().sorted().toList()) + ")");
                        } else {
                            t.put(l.index, "METHOD : " + m + ";");
                        }
                    }
                }
                case "OutputVariable.default" -> {
                    Optional<String> d = EngineText.number(v);
                    if (d.isEmpty()) {
                        t.error(l.index, DialectCode.SYNTAX, "expected a number or nan after 'default:', found '"
                                + v + "'");
                    } else {
                        t.put(l.index, "DEFAULT := " + d.get() + ";");
                    }
                }
                case "RuleBlock.conjunction" -> norm(t, l, T_NORMS, "AND", "a t-norm");
                case "RuleBlock.disjunction" -> norm(t, l, S_NORMS, "OR", "an s-norm");
                case "RuleBlock.implication" -> norm(t, l, T_NORMS, "ACT", "a t-norm");
                case "RuleBlock.activation" -> {
                    if (T_NORMS.containsKey(v)) {                // fuzzylite 5: the t-norm of activation
                        norm(t, l, T_NORMS, "ACT", "a t-norm");
                    } else if (!v.equals("General") && !v.equals("none") && !v.isEmpty()) {
                        t.error(l.index, DialectCode.UNSUPPORTED, "activation '" + v + "' (fuzzylite activates only"
                                + " some rules by it) is not evaluated by fclcert; it evaluates every rule, fuzzylite's"
                                + " General activation");
                    }
                }
                case "RuleBlock.rule" -> {
                    rules++;
                    t.put(l.index, "RULE " + rules + " : " + v + (v.endsWith(";") ? "" : ";"));
                }
                default -> t.error(l.index, DialectCode.SYNTAX, "'" + key + ":' is no key of an FLL "
                        + section + " (fuzzylite 6)");
            }
        }
        if (!engine) {
            t.error(0, DialectCode.SYNTAX, "no 'Engine:' line: not an FLL engine");
        }
        t.end(close + "END_FUNCTION_BLOCK");
        return t;
    }

    private static void flag(EngineText t, Line l, String whenTrue) {
        if (l.value.equals("true")) {
            t.put(l.index, whenTrue);
        } else if (!l.value.equals("false")) {
            t.error(l.index, DialectCode.SYNTAX, "expected true or false after '" + l.key + ":', found '"
                    + l.value + "'");
        }
    }

    private static void norm(EngineText t, Line l, Map<String, String> names, String keyword, String what) {
        if (!l.value.equals("none") && !l.value.isEmpty()) {
            named(t, l, names, keyword, what);
        }
    }

    private static void named(EngineText t, Line l, Map<String, String> names, String keyword, String what) {
        String n = names.get(l.value);
        if (n == null) {
            t.error(l.index, DialectCode.SYNTAX, "'" + l.value + "' is not " + what + " of fuzzylite ("
                    + String.join(", ", names.keySet().stream().sorted().toList()) + ")");
        } else {
            t.put(l.index, keyword + " : " + (keyword.equals("ACCU") ? FuzzyliteDialect.accumulationWord(n) : n) + ";");
        }
    }

    /**
     * {@code term: NAME Class parameters...}: fuzzylite FCL writes the same class and parameters, but for an output's
     * {@code Constant}, which fuzzylite's FCL writes as the bare number ({@code TERM t := v;}, read by fuzzylite as
     * this same Constant): so fclcert reads it as the singleton it is, evaluated exactly like one written in FCL.
     */
    private static void term(EngineText t, Line l, boolean output) {
        String[] w = l.value.split("\\s+", 3);
        if (w.length < 2 || w[0].isEmpty()) {
            t.error(l.index, DialectCode.SYNTAX, "expected 'term: NAME Class parameters...', found '" + l.value + "'");
            return;
        }
        String params = w.length > 2 ? w[2] : "";
        if (!ShapeNames.FUZZYLITE.known(w[1])) {
            t.error(l.index, DialectCode.UNKNOWN_SHAPE, "'" + w[1] + "' is no term class of fuzzylite");
            return;
        }
        if (output && w[1].equals("Constant") && EngineText.number(params).filter(n -> !n.equals("nan")
                && !n.contains("inf")).isPresent()) {
            t.put(l.index, "TERM " + w[0] + " := " + EngineText.number(params).get() + ";");
            return;
        }
        t.put(l.index, "TERM " + w[0] + " := " + w[1] + (params.isEmpty() ? "" : " " + params) + ";");
    }

    @Override
    public List<Giveaway> giveaways(String text) {
        List<Giveaway> out = new ArrayList<>();
        List<String> lines = (text == null ? "" : text).lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            String s = lines.get(i).strip();
            for (String key : List.of("Engine:", "InputVariable:", "OutputVariable:", "RuleBlock:", "term:", "rule:",
                    "range:", "defuzzifier:", "aggregation:", "conjunction:", "implication:")) {
                if (s.startsWith(key)) {
                    // 'Engine:' heads a whole-file format no FCL dialect has: decisive on its own
                    out.add(new Giveaway("FLL '" + key + "'", i + 1, key.equals("Engine:") ? 100 : 6));
                }
            }
        }
        return out;
    }
}
