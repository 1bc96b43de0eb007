package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.Program;
import org.junit.jupiter.api.Test;

/**
 * Issue 24, on the corpus: every vector of every positive case, in order on one instance, gives on the reference
 * evaluator (what {@code eval} and {@code certify --iut reference} run) the exact path's integer outputs and error
 * codes, and REAL outputs within the reference's bound plus the exact value's rounding; the vectors flagged as
 * knife edges included (they never excuse the reference). The number of steps redone exactly is printed for
 * docs/performance.md.
 */
class CorpusReferenceAgreementTest {
    @Test
    void theReferenceGivesTheExactPathsAnswerOnEveryCorpusVector() throws Exception {
        Corpus corpus = Corpus.load(Path.of("conformance"));
        List<String> wrong = new ArrayList<>();
        long steps = 0;
        long fallbacks = 0;
        int withoutExactPath = 0;
        for (CorpusCase c : corpus.cases()) {
            if (c.expectReject()) {
                continue;
            }
            Program program = Analysis.analyze(c.reader(), c.id(), c.programText()).program().orElseThrow();
            LoadedProgram loaded = Evaluator.load(program);
            if (!VectorReplay.exactPathEvaluates(loaded, c)) {
                // a dialect case of Takagi-Sugeno terms, Tsukamoto's method or hedged conclusions: no exact path exists
                assertTrue(c.inDialect(), c.id() + ": a standard case the exact path refuses");
                withoutExactPath++;
                continue;
            }
            FunctionBlockInstance reference = c.block().isPresent() ? loaded.newInstance(c.block().get())
                    : loaded.newInstance();
            ExactInstance exact = loaded.newExactInstance(c.block().orElse(null), NumberReading.DECIMAL);
            for (Vector v : c.vectors()) {
                steps++;
                String a = run(reference::set, reference::evaluate, v);
                String b = run(exact::set, exact::evaluate, v);
                if (a != null || b != null) {
                    if (!java.util.Objects.equals(a, b)) {
                        wrong.add(c.id() + " " + v.in() + ": reference " + a + ", exact " + b);
                    }
                    break;
                }
                for (Map.Entry<String, Double> o : reference.outputs().entrySet()) {
                    double want = exact.get(o.getKey());
                    double bound = reference.bound(o.getKey()) + Math.ulp(want);
                    if (!(Math.abs(o.getValue() - want) <= bound) && !o.getValue().equals(want)) {
                        wrong.add(c.id() + " " + v.in() + ": " + o.getKey() + " reference " + o.getValue() + ", exact "
                                + want + ", bound " + reference.bound(o.getKey()));
                    }
                }
            }
            fallbacks += reference.fallbacks();
        }
        System.out.printf("corpus agreement: %d steps, %d redone in exact arithmetic; %d dialect cases without an exact"
                + " path%n", steps, fallbacks, withoutExactPath);
        assertEquals(List.of(), wrong);
        assertTrue(steps > 300, "steps: " + steps);
    }

    interface Setter {
        void set(String name, double value) throws EvaluationException;
    }

    interface Step {
        void run() throws EvaluationException;
    }

    private static String run(Setter set, Step evaluate, Vector v) {
        try {
            for (Map.Entry<String, Double> in : v.in().entrySet()) {
                set.set(in.getKey(), in.getValue());
            }
            evaluate.run();
            return null;
        } catch (EvaluationException e) {
            return e.code();
        }
    }
}
