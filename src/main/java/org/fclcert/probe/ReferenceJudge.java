package org.fclcert.probe;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.check.Analysis;
import org.fclcert.check.AnalysisMemo;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.model.Diagnostic;
import org.fclcert.syntax.ReaderOptions;

/** The expected outputs of a probe program: the reference evaluator's exact path run on the same sequence of vectors. */
final class ReferenceJudge {
    private ReferenceJudge() {
    }

    /** The reference's answer: the outputs after each vector, or why it cannot judge the program. */
    record Expected(Optional<List<Map<String, Double>>> outputs, String whyNot) {
    }

    static Expected expected(ProbeProgram p) {
        // the reference implementation's reader and source name: when the implementation under test is the
        // in-process reference, its load of the same text is served by this one read (AnalysisMemo)
        Analysis analysis = AnalysisMemo.analyze(ReaderOptions.OPEN_LEVEL, "<iut>", p.expectedFrom());
        if (analysis.program().isEmpty()) {
            String why = analysis.diagnostics().stream().filter(Diagnostic::isError).findFirst()
                    .map(d -> d.code() + ": " + d.message()).orElse("the program could not be read");
            return new Expected(Optional.empty(), why);
        }
        try {
            ExactInstance instance = Evaluator.load(analysis.program().get()).newExactInstance();
            List<Map<String, Double>> out = new ArrayList<>();
            for (Map<String, Double> v : p.vectors()) {
                for (Map.Entry<String, Double> in : v.entrySet()) {
                    instance.set(in.getKey(), in.getValue());
                }
                instance.evaluate();
                out.add(new LinkedHashMap<>(instance.outputs()));
            }
            return new Expected(Optional.of(out), "");
        } catch (EvaluationException e) {
            return new Expected(Optional.empty(), e.getMessage());
        }
    }

    /** Empty when {@code actual} has every expected output within 1e-6 (relative above 1); else what differs. */
    static Optional<String> compare(Map<String, Double> expected, Map<String, Double> actual) {
        Map<String, Double> byKey = new LinkedHashMap<>();
        actual.forEach((k, v) -> byKey.put(k.toLowerCase(java.util.Locale.ROOT), v));
        for (Map.Entry<String, Double> e : expected.entrySet()) {
            Double a = byKey.get(e.getKey().toLowerCase(java.util.Locale.ROOT));
            double want = e.getValue();
            if (a == null) {
                return Optional.of("output " + e.getKey() + " is missing (expected " + want + ")");
            }
            if (!(Math.abs(a - want) <= 1e-6 * Math.max(1, Math.abs(want)))) {
                return Optional.of(e.getKey() + " = " + a + " where " + want + " is right");
            }
        }
        return Optional.empty();
    }
}
