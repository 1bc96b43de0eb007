package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Collectors;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.check.FeatureReport;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Trace;
import org.fclcert.model.Feature;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;

/**
 * Writes a finding's minimal case as a corpus case file ({@code conformance/README.md}): the metadata with
 * the detected level and features, the isolated feature as {@code tests}, the reference's values as the
 * vectors and a derivation read off the reference's trace (degrees, rule degrees, activations, the
 * accumulated set, the result), with what the implementation answered; then the program in a compact layout.
 */
public final class CaseFiles {
    private static final CanonicalWriter WRITER = new CanonicalWriter();

    private CaseFiles() {
    }

    /** The id prefix of a finding's case: {@code E-ACCU-NSUM}. */
    static String prefix(Finding f) {
        FeatureReport report = new FeatureDetector().detect(f.minimal().program());
        String level = report.level().word().toUpperCase(Locale.ROOT).substring(0, 1);
        String feature = f.feature().id().substring(2);
        return level + "-" + feature;
    }

    /** The whole case file (with where the text as sent is, when the run presented it in a library's layout). */
    static String text(Finding f, String id, String iutName, Optional<Presentation.Sent> sent, Optional<String> sentAs)
            throws EvaluationException {
        Shrinker.Case c = f.minimal();
        Program program = c.program();
        FeatureReport report = new FeatureDetector().detect(program);
        ReferenceProgram ref = new ReferenceProgram(program);
        List<ReferenceProgram.Step> steps = ref.run(c.steps());
        boolean continuous = program.functionBlocks().get(0).defuzzifications().stream()
                .anyMatch(d -> d.terms().stream().anyMatch(t -> t.function() instanceof MembershipFunction.Points));
        boolean stateful = ref.stateful() && steps.size() > 1;
        StringBuilder out = new StringBuilder("(*---\n");
        out.append("id: ").append(id).append('\n');
        out.append("title: Found by fclcert fuzz, ").append(plain(iutName)).append(" gives ")
                .append(f.kind().word().replace('-', ' ')).append(" on ").append(f.feature().id()).append(" (seed ")
                .append(f.programSeed()).append(")\n");
        out.append("level: ").append(report.level().word()).append('\n');
        out.append("features: [").append(report.features().stream().map(Feature::id).collect(Collectors.joining(", ")))
                .append("]\n");
        out.append("tests: [").append(f.feature().id()).append("]\n");
        out.append("tolerance: ").append(continuous ? "continuous" : "exact").append('\n');
        List<String> flags = new ArrayList<>();
        if (stateful) {
            flags.add("stateful");
        }
        if (Isolation.verticalEdgeUnderAnInput(c).isPresent()) {
            flags.add("\"interpretation:1\"");      // the degree at a vertical edge is fclcert's reading (semantics.md 1)
        }
        out.append("flags: [").append(String.join(", ", flags)).append("]\n");
        out.append("derivation: |\n");
        for (String line : derivation(f, steps, iutName, sent, sentAs)) {
            out.append("  ").append(line).append('\n');
        }
        out.append("vectors:\n");
        for (ReferenceProgram.Step s : steps) {
            out.append("  - in: ").append(map(s.inputs())).append('\n');
            out.append("    out: ").append(map(s.outputs())).append('\n');
        }
        out.append("---*)\n");
        out.append(compact(program));
        return out.toString();
    }

    /** Program lines of a finding's case as written (the size the issue bounds). */
    static int programLines(Program program) {
        return (int) compact(program).lines().count();
    }

    private static List<String> derivation(Finding f, List<ReferenceProgram.Step> steps, String iutName,
            Optional<Presentation.Sent> sent, Optional<String> sentAs) {
        List<String> lines = new ArrayList<>();
        lines.add("Reference values from fclcert's reference evaluator, step by step from its trace; review them by hand");
        lines.add("before the case joins the corpus. " + plain(iutName) + " deviates: " + f.deviation().message() + ".");
        sent.flatMap(Presentation.Sent::layout).ifPresent(l -> lines.add("It got the program in " + l.displayName()
                + "'s layout" + sentAs.map(a -> " (" + a + ")").orElse("") + "."));
        for (org.fclcert.model.Diagnostic d : sent.map(Presentation.Sent::differences).orElse(List.of())) {
            lines.add("The writer notes (" + d.code() + "): " + d.message() + ".");
        }
        for (int i = 0; i < steps.size(); i++) {
            ReferenceProgram.Step s = steps.get(i);
            Trace t = s.trace();
            lines.add("step " + (i + 1) + ": " + s.inputs().entrySet().stream().map(e -> e.getKey() + " = " + num(e.getValue()))
                    .collect(Collectors.joining(", ")));
            if (!t.termDegrees().isEmpty()) {
                lines.add("  fuzzification: " + t.termDegrees().stream().map(d -> d.variable() + " IS " + d.term() + " = "
                        + num(d.degree())).collect(Collectors.joining(", ")));
            }
            if (!t.ruleDegrees().isEmpty()) {
                lines.add("  rule degrees: " + t.ruleDegrees().stream().map(d -> d.ruleBlock() + " rule " + d.rule() + " = "
                        + num(d.degree())).collect(Collectors.joining(", ")));
            }
            if (!t.activations().isEmpty()) {
                lines.add("  activation: " + t.activations().stream().map(a -> a.variable() + a.term().map(x -> " IS " + x).orElse("")
                        + " at " + num(a.activatedDegree()) + (a.weight() != 1 ? " (weight " + num(a.weight()) + ")" : ""))
                        .collect(Collectors.joining(", ")));
            }
            for (Trace.AccumulatedSet set : t.accumulatedSets()) {
                lines.add("  accumulated " + set.variable() + (set.singletons() ? " (singletons u:degree): " : " (vertices u:degree): ")
                        + set.breakpoints().stream().map(b -> num(b.u()) + ":" + num(b.degree())).collect(Collectors.joining(" ")));
            }
            for (Trace.Result r : t.results()) {
                String how = switch (r.outcome()) {
                    case DEFUZZIFIED -> "defuzzified";
                    case DEFAULT -> "nothing fired, DEFAULT";
                    case NO_CHANGE -> "nothing fired, NC keeps the previous value";
                    case ASSIGNED -> "assigned by a bare conclusion";
                };
                lines.add("  " + r.variable() + " = " + num(r.value()) + " (" + how + ")");
            }
            if (i == f.deviation().step()) {
                lines.add("  " + plain(iutName) + " gives " + f.deviation().actualOutputs().entrySet().stream()
                        .map(e -> e.getKey() + " = " + num(e.getValue())).collect(Collectors.joining(", ")));
            }
        }
        return lines;
    }

    /** The canonical text with short blocks on one line; checked to read back as the same program. */
    static String compact(Program program) {
        String canonical = WRITER.write(program);
        StringBuilder out = new StringBuilder();
        List<String> pending = new ArrayList<>();
        String open = null;
        for (String raw : canonical.split("\n")) {
            String line = raw.strip();
            if (line.isEmpty()) {
                continue;
            }
            if (open == null && (line.startsWith("VAR") || line.startsWith("FUZZIFY ") || line.startsWith("DEFUZZIFY ")
                    || line.startsWith("RULEBLOCK "))) {
                open = line;
                pending.clear();
                continue;
            }
            if (open == null) {
                out.append(line).append('\n');
                continue;
            }
            if (line.startsWith("END_")) {
                block(out, open, pending, line);
                open = null;
                continue;
            }
            pending.add(line);
        }
        String text = out.toString();
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", text);
        return a.program().filter(program::equals).isPresent() ? text : canonical;
    }

    private static void block(StringBuilder out, String open, List<String> body, String end) {
        if (open.startsWith("VAR") || open.startsWith("FUZZIFY") && body.size() <= 2) {
            out.append(open).append(' ').append(String.join(" ", body)).append(' ').append(end).append('\n');
            return;
        }
        out.append(open).append('\n');
        List<String> lines = new ArrayList<>();
        List<String> group = new ArrayList<>();
        for (String line : body) {
            boolean setting = line.matches("(AND|OR|ACT|ACCU|METHOD|DEFAULT) .*");
            boolean term = line.startsWith("TERM ");
            if (line.startsWith("RULE ") || line.startsWith("RANGE")) {
                flush(lines, group);
                lines.add(line);
            } else if (!setting && !term && !lines.isEmpty()) {
                lines.set(lines.size() - 1, lines.get(lines.size() - 1) + " " + line);     // a rule's next subconclusion
            } else {
                if (!group.isEmpty() && (group.get(0).startsWith("TERM ") != term || term && group.size() == 3)) {
                    flush(lines, group);
                }
                group.add(line);
            }
        }
        flush(lines, group);
        lines.forEach(l -> out.append("    ").append(l).append('\n'));
        out.append(end).append('\n');
    }

    private static void flush(List<String> lines, List<String> group) {
        if (!group.isEmpty()) {
            lines.add(String.join(" ", group));
            group.clear();
        }
    }

    private static String map(Map<String, Double> values) {
        return "{" + values.entrySet().stream().map(e -> e.getKey() + ": " + num(e.getValue())).collect(Collectors.joining(", ")) + "}";
    }

    /** Shortest text that reads back as the same double, in the corpus's plain decimal form. */
    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v) + ".0";
        }
        return Double.toString(v);
    }

    private static String plain(String s) {
        return s.replaceAll("[^A-Za-z0-9 ._()+-]", "_");
    }
}
