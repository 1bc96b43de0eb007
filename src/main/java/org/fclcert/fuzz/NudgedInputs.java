package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.corpus.Tolerance;
import org.fclcert.eval.EvaluationException;

/**
 * A conservative fairness test on the reference alone: the step is evaluated again with each input, and then
 * all inputs together, moved by ±1 and ±16 ulps (at least 1e-15; see {@link #nudges}); if any output moves by more
 * than a quarter of what its tolerance class allows, the step is a knife edge and unfair. The factor of four
 * keeps steps whose result is merely steep (but continuous) out of doubt as well.
 */
public final class NudgedInputs implements FairnessJudge {
    private static final double SAFETY = 0.25;

    @Override
    public boolean fair(ReferenceProgram program, List<Map<String, Double>> before, Map<String, Double> step) {
        try {
            List<Map<String, Double>> steps = new ArrayList<>(before);
            steps.add(step);
            Map<String, Double> base = program.last(steps);
            for (Map<String, Double> nudged : nudges(step)) {
                steps.set(steps.size() - 1, nudged);
                Map<String, Double> got = program.last(steps);
                for (Map.Entry<String, Double> e : base.entrySet()) {
                    double want = e.getValue();
                    Double other = got.get(e.getKey());
                    double allowed = Tolerance.CONTINUOUS.allowed(want, program.scales().width(e.getKey()));
                    if (other == null || !(Math.abs(other - want) <= SAFETY * allowed)) {
                        return false;
                    }
                }
            }
            return true;
        } catch (EvaluationException e) {
            return false;
        }
    }

    /**
     * All inputs moved together, and each input with a short decimal value (a breakpoint, a midpoint, a round
     * number: where ties and jumps sit) moved alone. An input with a full-precision random value is no tie
     * but by a measure-zero chance, so it moves only with the others.
     */
    static List<Map<String, Double>> nudges(Map<String, Double> step) {
        List<Map<String, Double>> out = new ArrayList<>();
        for (int sign : new int[] {1, -1}) {
            for (int kind = 0; kind < 2; kind++) {
                Map<String, Double> all = new LinkedHashMap<>(step);
                for (String name : step.keySet()) {
                    double moved = move(step.get(name), sign, kind);
                    all.put(name, moved);
                    if (round(step.get(name)) && step.size() > 1) {
                        Map<String, Double> one = new LinkedHashMap<>(step);
                        one.put(name, moved);
                        out.add(one);
                    }
                }
                out.add(all);
            }
        }
        return out;
    }

    private static boolean round(double x) {
        return java.math.BigDecimal.valueOf(x).stripTrailingZeros().precision() <= 8;
    }

    private static double move(double x, int sign, int kind) {
        return kind == 0 ? x + sign * Math.ulp(x) : x + sign * Math.max(16 * Math.ulp(x), 1e-15);
    }
}
