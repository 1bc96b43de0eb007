package org.fclcert.harness;

import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Vector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;

/**
 * The export check done with fclcert's own strict reader (Open Level reading: a MoM program exports as MoM), checks and reference evaluator (its exact judging path): the exported text
 * is compared with the case's expected outputs (which the reference evaluator reproduces for the original
 * program, as corpus lint guarantees), step by step on one instance, within the case's tolerance.
 */
public final class ReferenceExportCheck implements ExportCheck {

    @Override
    public Verdict check(String exportedFcl, RunCase c) {
        Analysis analysis = Analysis.analyze(StrictReader.openLevel(), c.id() + " (exported)", exportedFcl);
        if (analysis.program().isEmpty()) {
            String first = analysis.diagnostics().stream().filter(Diagnostic::isError).findFirst()
                    .map(Diagnostic::toString).orElse("no program");
            // a library that exports its own dialect (jfuzzylite, jFuzzyLogic): say so, since that is the reason
            org.fclcert.syntax.dialect.DialectReaders.Choice dialect = org.fclcert.syntax.dialect.DialectReaders.auto(exportedFcl);
            String which = dialect.dialect() == org.fclcert.syntax.dialect.Dialect.STRICT ? ""
                    : " (it is written in the " + dialect.dialect().displayName() + " dialect, not standard FCL: "
                            + dialect.explanation() + ")";
            return failed("the exported FCL does not read back: " + first + which);
        }
        try {
            return evaluateLikeOriginal(analysis.program().get(), c);
        } catch (EvaluationException e) {
            return failed("the exported FCL cannot be evaluated: " + e.getMessage());
        }
    }

    private static Verdict evaluateLikeOriginal(Program program, RunCase c) throws EvaluationException {
        LoadedProgram loaded = Evaluator.load(program);
        ExactInstance fb = loaded.newExactInstance(c.block().orElse(null), NumberReading.DECIMAL);
        for (int i = 0; i < c.vectors().size(); i++) {
            Vector v = c.vectors().get(i);
            for (Map.Entry<String, Double> in : v.in().entrySet()) {
                fb.set(in.getKey(), in.getValue());
            }
            if (v.refused()) {
                String refused = EvaluationException.refusalOf(fb::evaluate);
                if (!v.error().get().equals(refused)) {
                    return failed("the exported FCL " + (refused == null ? "evaluates step " + (i + 1) + " to "
                            + fb.outputs() : "refuses step " + (i + 1) + " with " + refused) + ", where the original"
                            + " refuses it with " + v.error().get());
                }
                continue;
            }
            fb.evaluate();
            for (Map.Entry<String, Double> out : v.out().entrySet()) {
                double got = fb.get(out.getKey());
                if (!c.tolerance().accepts(out.getKey(), out.getValue(), got)) {
                    return failed("the exported FCL evaluates differently: step " + (i + 1) + ": " + out.getKey()
                            + " = " + got + " where " + out.getValue() + " is expected");
                }
            }
        }
        return new Verdict(ExportStatus.PASSED, "reads back strictly and evaluates like the original");
    }

    private static Verdict failed(String why) {
        return new Verdict(ExportStatus.FAILED, why);
    }
}
