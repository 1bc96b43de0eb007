package org.fclcert.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.LongStream;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.junit.jupiter.api.Test;

/**
 * Issue 24: the reference evaluator (filtered exact evaluation) and the exact path agree on the fuzzer's own
 * programs — 10 000 of {@link ProgramGenerator}'s open-level programs (every Table 8/9 row, many points,
 * fractional and variable degrees, MoM, numbers on coarse grids so that ties, plateaus and shared breakpoints
 * occur), each with {@link VectorGenerator}'s candidate steps <em>unjudged</em> (knife edges included: they never
 * excuse the reference) and each step again with one input one ulp off. Every error code and every integer output
 * must be the same, every REAL output within the reference's {@code bound} plus the exact value's rounding. A
 * stateful program is compared on its first step only (later steps start from the reference's double state,
 * which the exact path does not share; FastExactAgreementTest compares those from the same state).
 */
class GeneratedProgramsAgreementTest {
    private static final CanonicalWriter WRITER = new CanonicalWriter();

    @Test
    void referenceAndExactPathAgreeOnGeneratedPrograms() {
        ProgramGenerator generator = new ProgramGenerator(FuzzSettings.open());
        VectorGenerator candidates = new VectorGenerator((p, before, step) -> true);
        long programs = Long.getLong("fclcert.agreement.generated", 10_000);
        List<String> wrong = new CopyOnWriteArrayList<>();
        AtomicLong steps = new AtomicLong();
        AtomicLong evaluations = new AtomicLong();
        AtomicLong fallbacks = new AtomicLong();
        LongStream.range(0, programs).parallel().forEach(seed -> {
            try {
                Program generated = generator.generate(Fuzzer.programSeed(24, seed));
                Program program = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", WRITER.write(generated))
                        .program().orElseThrow();
                ReferenceProgram ref = new ReferenceProgram(program);
                Random r = new Random(seed);
                List<Map<String, Double>> sequence = new ArrayList<>();
                for (Map<String, Double> step : candidates.steps(ref, r)) {
                    sequence.add(step);
                    sequence.add(ScreenedFairnessTest.oneUlpOff(step, r));
                }
                FunctionBlockInstance reference = ref.loaded().newInstance();
                ExactInstance exact = ref.loaded().newExactInstance();
                try {
                    for (Map<String, Double> step : sequence) {
                        String problem = compare(reference, exact, step);
                        steps.incrementAndGet();
                        if (problem != null) {
                            wrong.add("seed " + seed + ", step " + step + ": " + problem + "\n" + WRITER.write(program));
                            return;
                        }
                        if (ref.stateful()) {
                            return;
                        }
                    }
                } finally {
                    evaluations.addAndGet(reference.evaluations());
                    fallbacks.addAndGet(reference.fallbacks());
                }
            } catch (RuntimeException e) {
                wrong.add("seed " + seed + ": " + e);
            }
        });
        System.out.printf("generated agreement: %d programs, %d steps compared, %d evaluations, %d fell back to exact"
                + " arithmetic%n", programs, steps.get(), evaluations.get(), fallbacks.get());
        assertEquals(List.of(), wrong.stream().limit(3).toList(), wrong.size() + " disagreements");
        assertTrue(steps.get() >= programs, "steps compared: " + steps);
        assertTrue(fallbacks.get() > 0, "no step reached a decision the bounds could not settle: the test cannot tell");
    }

    /** One step on both; null when they agree, else what differs. */
    private static String compare(FunctionBlockInstance reference, ExactInstance exact, Map<String, Double> step) {
        String referenceError = null;
        String exactError = null;
        try {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                reference.set(e.getKey(), e.getValue());
            }
            reference.evaluate();
        } catch (EvaluationException e) {
            referenceError = e.code();
        }
        try {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                exact.set(e.getKey(), e.getValue());
            }
            exact.evaluate();
        } catch (EvaluationException e) {
            exactError = e.code();
        }
        if (referenceError != null || exactError != null) {
            return Objects.equals(referenceError, exactError) ? null
                    : "reference error " + referenceError + ", exact error " + exactError;
        }
        try {
            for (Map.Entry<String, Double> o : reference.outputs().entrySet()) {
                double want = exact.get(o.getKey());
                double got = o.getValue();
                double bound = reference.bound(o.getKey()) + Math.ulp(want);
                if (!(Math.abs(got - want) <= bound) && !(Double.isNaN(got) && Double.isNaN(want))) {
                    return o.getKey() + ": reference " + got + ", exact " + want + ", bound "
                            + reference.bound(o.getKey());
                }
            }
        } catch (EvaluationException e) {
            return e.toString();
        }
        return null;
    }
}
