package org.fclcert.cli;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.fclcert.eval.Trace;

/** The stages of one evaluation ({@code eval --trace}) as text lines or as JSON-ready maps. */
final class TracePrinter {
    private TracePrinter() {
    }

    static String text(Trace t) {
        StringBuilder sb = new StringBuilder();
        t.termDegrees().forEach(d -> sb.append("fuzzification ").append(d.variable()).append(" IS ")
                .append(d.term()).append(" = ").append(d.degree()).append('\n'));
        t.ruleDegrees().forEach(r -> sb.append("aggregation ").append(r.ruleBlock()).append(" RULE ")
                .append(r.rule()).append(" = ").append(r.degree()).append('\n'));
        t.activations().forEach(a -> sb.append("activation ").append(a.ruleBlock()).append(" RULE ")
                .append(a.rule()).append(' ').append(a.variable())
                .append(a.term().map(term -> " IS " + term).orElse(""))
                .append(" weight ").append(a.weight()).append(" = ").append(a.activatedDegree()).append('\n'));
        t.accumulatedSets().forEach(s -> sb.append("accumulation ").append(s.variable())
                .append(s.singletons() ? " singletons " : " set ").append(points(s.breakpoints())).append('\n'));
        t.results().forEach(r -> sb.append("result ").append(r.variable()).append(" = ").append(r.value())
                .append(" (").append(r.outcome().name().toLowerCase(java.util.Locale.ROOT).replace('_', ' '))
                .append(")\n"));
        return sb.toString();
    }

    private static String points(List<Trace.Breakpoint> bps) {
        return bps.stream().map(b -> "(" + b.u() + ", " + b.degree() + ")").collect(Collectors.joining(" "));
    }

    static Map<String, Object> json(Trace t) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("termDegrees", t.termDegrees());
        m.put("ruleDegrees", t.ruleDegrees());
        m.put("activations", t.activations().stream().map(a -> {
            Map<String, Object> x = new LinkedHashMap<>();
            x.put("ruleBlock", a.ruleBlock());
            x.put("rule", a.rule());
            x.put("variable", a.variable());
            x.put("term", a.term().orElse(null));
            x.put("weight", a.weight());
            x.put("activatedDegree", a.activatedDegree());
            return x;
        }).toList());
        m.put("accumulatedSets", t.accumulatedSets().stream().map(s -> {
            Map<String, Object> x = new LinkedHashMap<>();
            x.put("variable", s.variable());
            x.put("singletons", s.singletons());
            x.put("breakpoints", s.breakpoints().stream().map(b -> List.of(b.u(), b.degree())).toList());
            return x;
        }).toList());
        m.put("results", t.results());
        return m;
    }
}
