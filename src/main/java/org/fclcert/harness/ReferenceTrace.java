package org.fclcert.harness;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.stream.Collectors;
import org.fclcert.eval.Trace;

/**
 * What fclcert's reference evaluator did at the step where a positive case went wrong: the degree of every rule
 * (a rule fired when its degree is above 0) with what it concludes, and for every output how it got its value and
 * its accumulated set. The reports put it beside expected and actual ({@link #lines()}: "no rule fired → DEFAULT
 * applies"), report.html draws the set; {@code reference} in results.jsonl and report.json.
 *
 * @param step    the 1-based step, evaluated after the steps before it on one instance (as the harness ran them)
 * @param rules   every rule in program order
 * @param outputs every output of the function block
 */
public record ReferenceTrace(int step, List<RuleDegree> rules, List<OutputValue> outputs) {

    /** How many fired rules the lines name before "and N more". */
    static final int RULES_NAMED = 8;

    public ReferenceTrace {
        rules = List.copyOf(rules);
        outputs = List.copyOf(outputs);
    }

    /**
     * One rule: its block, name, degree (its condition's degree of accomplishment) and subconclusions as written
     * ({@code valve IS closed WITH 0.8}).
     */
    public record RuleDegree(String ruleBlock, String rule, double degree, List<String> conclusions) {
        public RuleDegree {
            Objects.requireNonNull(rule, "rule");
            conclusions = conclusions == null ? List.of() : List.copyOf(conclusions);
        }

        boolean fired() {
            return degree > 0;
        }
    }

    /**
     * One output: its value, how it got it ({@code defuzzified}, {@code default}, {@code no change}, {@code assigned}),
     * and its accumulated set as {@code [u, degree]} points: one per output term for singletons (its value and
     * accumulated degree), else the vertices of the set over the defuzzification interval, left to right.
     */
    public record OutputValue(String variable, double value, String outcome, boolean singletons,
            List<List<Double>> set,
            @com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL)
            Double computed) {
        public OutputValue {
            Objects.requireNonNull(variable, "variable");
            set = set == null ? List.of() : set.stream().map(List::copyOf).toList();
        }

        public OutputValue(String variable, double value, String outcome, boolean singletons, List<List<Double>> set) {
            this(variable, value, outcome, singletons, set, null);
        }

        /** True when the output's data type changed the value (an integer type rounds half away from zero). */
        boolean converted() {
            return computed != null && Double.isFinite(computed) && computed.doubleValue() != value;
        }
    }

    /** The trace of one evaluation as recorded by the evaluator. */
    static ReferenceTrace of(int step, Trace t) {
        Map<String, List<String>> conclusions = new LinkedHashMap<>();
        for (Trace.Activation a : t.activations()) {
            conclusions.computeIfAbsent(a.ruleBlock() + "\u0000" + a.rule(), k -> new ArrayList<>())
                    .add(a.variable() + a.term().map(term -> " IS " + term).orElse("")
                            + (a.weight() == 1 ? "" : " WITH " + number(a.weight())));
        }
        List<RuleDegree> rules = t.ruleDegrees().stream().map(r -> new RuleDegree(r.ruleBlock(), r.rule(), r.degree(),
                conclusions.getOrDefault(r.ruleBlock() + "\u0000" + r.rule(), List.of()))).toList();
        List<OutputValue> outputs = new ArrayList<>();
        for (Trace.Result r : t.results()) {
            Trace.AccumulatedSet set = t.accumulatedSet(r.variable()).orElse(null);
            outputs.add(new OutputValue(r.variable(), r.value(), r.outcome().name().toLowerCase(Locale.ROOT)
                    .replace('_', ' '), set != null && set.singletons(), set == null ? List.of()
                    : set.breakpoints().stream().map(b -> List.of(b.u(), b.degree())).toList(),
                    r.computed() != r.value() && Double.isFinite(r.computed()) ? r.computed() : null));
        }
        return new ReferenceTrace(step, rules, outputs);
    }

    /** The output of this name (letter case ignored), or null. */
    public OutputValue output(String name) {
        return outputs.stream().filter(o -> o.variable().equalsIgnoreCase(name)).findFirst().orElse(null);
    }

    /**
     * The trace in a few plain lines: which rules fired with which degrees and which did not, then how each output
     * got its value ("no rule fired → DEFAULT applies: y = 0").
     */
    public List<String> lines() {
        List<String> lines = new ArrayList<>();
        boolean severalBlocks = rules.stream().map(RuleDegree::ruleBlock).distinct().count() > 1;
        List<RuleDegree> fired = rules.stream().filter(RuleDegree::fired).toList();
        List<RuleDegree> idle = rules.stream().filter(r -> !r.fired()).toList();
        if (fired.isEmpty()) {
            lines.add("no rule fired (" + rules.size() + " rule" + (rules.size() == 1 ? "" : "s") + ", every degree 0)");
        } else {
            String named = fired.stream().limit(RULES_NAMED).map(r -> name(r, severalBlocks) + " at "
                    + number(r.degree()) + (r.conclusions().isEmpty() ? "" : " → " + String.join(", ", r.conclusions())))
                    .collect(Collectors.joining("; "));
            lines.add("rules fired: " + named + (fired.size() > RULES_NAMED ? "; and " + (fired.size() - RULES_NAMED)
                    + " more" : ""));
            if (!idle.isEmpty()) {
                lines.add("not fired (degree 0): " + idle.stream().limit(RULES_NAMED).map(r -> name(r, severalBlocks))
                        .collect(Collectors.joining(", ")) + (idle.size() > RULES_NAMED ? " and " + (idle.size()
                        - RULES_NAMED) + " more" : ""));
            }
        }
        for (OutputValue o : outputs) {
            lines.add(outcome(o, fired.isEmpty()));
        }
        return lines;
    }

    private static String outcome(OutputValue o, boolean nothingFired) {
        String line = outcomeBeforeConversion(o, nothingFired);
        return o.converted() ? line + "; that is " + number(o.computed()) + ", rounded half away from zero to the"
                + " output's integer type: " + o.variable() + " = " + number(o.value()) : line;
    }

    private static String outcomeBeforeConversion(OutputValue o, boolean nothingFired) {
        String none = nothingFired ? "no rule fired" : "no rule concluding " + o.variable() + " fired";
        return switch (o.outcome()) {
            case "default" -> none + " → DEFAULT applies: " + o.variable() + " = " + number(o.value());
            case "no change" -> none + " → DEFAULT NC keeps the previous value: " + o.variable() + " = "
                    + number(o.value());
            case "assigned" -> o.variable() + " = " + number(o.value()) + ", assigned by a rule";
            default -> o.variable() + " = " + number(o.value()) + ", defuzzified from "
                    + (o.singletons() ? "the singletons " + o.set().stream().filter(p -> p.get(1) > 0)
                            .map(p -> number(p.get(0)) + " (degree " + number(p.get(1)) + ")")
                            .collect(Collectors.joining(", "))
                            : "the accumulated set over [" + number(o.set().isEmpty() ? Double.NaN : o.set().get(0).get(0))
                            + ", " + number(o.set().isEmpty() ? Double.NaN : o.set().get(o.set().size() - 1).get(0)) + "]");
        };
    }

    private static String name(RuleDegree r, boolean withBlock) {
        return "RULE " + r.rule() + (withBlock ? " of " + r.ruleBlock() : "");
    }

    /** Six significant digits: enough to see which rule dominates, short enough to read. */
    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        String s = String.format(Locale.ROOT, "%.6g", v);
        if (s.contains("e")) {
            return s.replaceAll("\\.?0+e", "e");
        }
        return s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
    }
}
