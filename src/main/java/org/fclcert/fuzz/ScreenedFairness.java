package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.DoubleUnaryOperator;
import org.fclcert.corpus.Tolerance;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.NumberReading;
import org.fclcert.eval.Trace;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * The exact judge ({@link ExactFairness}) behind a cheap screen, so that the exact judge runs only near decision
 * points. Most generated steps are far from any tie, jump or rounding boundary; for those the screen decides
 * "fair" from two exact evaluations (fclcert's reading and the binary reading of numbers) and a handful of
 * double-arithmetic ones, where the exact judge needs {@code 2·inputs + 3} exact evaluations.
 *
 * <p>The screen passes a step when all of these agree within a sixteenth of the tolerance (so that, added up,
 * they stay within the exact judge's quarter): the exact value under each reading, the double path, and the double
 * path with the inputs moved by one ulp and by δ = 1e-9·max(1, |x|) — each input alone up and down, then all
 * together — in every step of the sequence; and no rule fires with a degree (or an activated degree) below
 * 1e-12. Every perturbation the exact judge applies (an ulp of an input, the other reading of a literal) is far
 * smaller than δ, so an output that moves under it has a jump within δ of the step, which a δ move crosses, or a
 * tie of constants, which the readings show — unless the jump sits at one isolated point (a degree that touches 0
 * there, as {@code x IS t AND NOT (x IS t)} does at t's feet): the ulp moves land on such a point as the exact
 * judge's do, and a rule firing with a degree that small is left to the exact judge. Whatever the screen does
 * not pass goes to the exact judge, which decides; the screen never makes a step unfair ({@code
 * ScreenedFairnessTest} checks it against the exact judge alone). Programs with an integer output (rounding at a
 * half-integer) or that the exact path computes in floating point go to the exact judge directly.
 */
public final class ScreenedFairness implements FairnessJudge {
    private static final double SHARE = 1.0 / 16;
    private static final double DELTA = 1e-9;
    private static final double TINY_DEGREE = 1e-12;

    private final FairnessJudge exact;
    private long screened;
    private long judged;

    public ScreenedFairness() {
        this(new ExactFairness());
    }

    ScreenedFairness(FairnessJudge exact) {
        this.exact = exact;
    }

    @Override
    public boolean fair(ReferenceProgram program, List<Map<String, Double>> before, Map<String, Double> step) {
        List<Map<String, Double>> steps = new ArrayList<>(program.stateful() ? before : List.of());
        steps.add(step);
        if (passes(program, steps)) {
            count(true);
            return true;
        }
        count(false);
        return exact.fair(program, before, step);
    }

    private synchronized void count(boolean byScreen) {
        if (byScreen) {
            screened++;
        } else {
            judged++;
        }
    }

    /** Steps the screen passed, and steps the exact judge decided (for the throughput notes). */
    public synchronized long[] counts() {
        return new long[] {screened, judged};
    }

    /** True when the last of {@code steps} is clearly fair. */
    static boolean passes(ReferenceProgram program, List<Map<String, Double>> steps) {
        if (program.block().variables().stream().map(Variable::type).anyMatch(t -> t.isInteger())) {
            return false;
        }
        try {
            Map<String, Double> decimal = exactLast(program, steps, NumberReading.DECIMAL);
            if (decimal == null) {
                return false;
            }
            Map<String, Double> binary = exactLast(program, steps, NumberReading.BINARY);
            if (binary == null || !close(program, decimal, binary)) {
                return false;
            }
            Map<String, Double> fast = fastLast(program, steps, null, v -> v);
            if (fast == null || !close(program, decimal, fast)) {
                return false;
            }
            List<String> inputs = program.block().variables(VariableKind.INPUT).stream().map(Variable::name).toList();
            List<DoubleUnaryOperator> moves = List.of(Math::nextUp, Math::nextDown,
                    v -> v + DELTA * Math.max(1, Math.abs(v)), v -> v - DELTA * Math.max(1, Math.abs(v)));
            for (DoubleUnaryOperator move : moves) {
                for (String in : inputs) {
                    if (!close(program, fast, fastLast(program, steps, in, move))) {
                        return false;
                    }
                }
                if (inputs.size() > 1 && !close(program, fast, fastLast(program, steps, "", move))) {
                    return false;
                }
            }
            return true;
        } catch (EvaluationException | RuntimeException e) {
            return false;
        }
    }

    /** The last step's outputs on the exact path; null when that path is not exact for this program. */
    private static Map<String, Double> exactLast(ReferenceProgram program, List<Map<String, Double>> steps,
            NumberReading reading) throws EvaluationException {
        ExactInstance fb = program.loaded().newExactInstance(null, reading);
        if (!fb.exact()) {
            return null;
        }
        for (Map<String, Double> step : steps) {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                fb.set(e.getKey(), e.getValue());
            }
            fb.evaluate();
        }
        return fb.outputs();
    }

    /**
     * The last step's outputs on the double path, with input {@code moved} ({@code ""}: every input; null: none)
     * moved by {@code move} in every step; null when, unmoved, a rule fires with a degree below {@link #TINY_DEGREE}.
     */
    private static Map<String, Double> fastLast(ReferenceProgram program, List<Map<String, Double>> steps, String moved,
            DoubleUnaryOperator move) throws EvaluationException {
        FunctionBlockInstance fb = program.loaded().newDoubleInstance(null);
        for (Map<String, Double> step : steps) {
            for (Map.Entry<String, Double> e : step.entrySet()) {
                double v = e.getValue();
                boolean apply = moved != null && (moved.isEmpty() || moved.equals(e.getKey()));
                fb.set(e.getKey(), apply ? move.applyAsDouble(v) : v);
            }
            if (moved == null) {
                Trace trace = new Trace();
                fb.evaluate(trace);
                if (trace.ruleDegrees().stream().anyMatch(d -> tiny(d.degree()))
                        || trace.activations().stream().anyMatch(a -> tiny(a.activatedDegree()))) {
                    return null;
                }
            } else {
                fb.evaluate();
            }
        }
        return new LinkedHashMap<>(fb.outputs());
    }

    private static boolean tiny(double degree) {
        return degree > 0 && degree < TINY_DEGREE;
    }

    private static boolean close(ReferenceProgram program, Map<String, Double> a, Map<String, Double> b) {
        for (Map.Entry<String, Double> e : a.entrySet()) {
            double x = e.getValue();
            Double y = b.get(e.getKey());
            if (y == null || Double.isNaN(x) != Double.isNaN(y)) {
                return false;
            }
            if (!Double.isNaN(x) && !(Math.abs(x - y) <= SHARE * Tolerance.CONTINUOUS.allowed(x,
                    program.scales().width(e.getKey())))) {
                return false;
            }
        }
        return true;
    }
}
