package org.fclcert.eval;

import java.util.Arrays;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;

/**
 * The activated contributions to one output's accumulated set (A.15): per contribution the shape
 * index, the activation level, the rule weight and whether it is activated by PROD (else MIN), or by one
 * of the dialects' other t-norms ({@code norm}, null for Table 4). Shared by {@link SetBuilder} (Table 4 only)
 * and {@link SmoothSet}, whose loops read the arrays directly. The arrays grow on demand and are reused, so the
 * steady state allocates nothing.
 */
final class Activations {
    /** Number of contributions added since {@link #clear}. */
    int n;
    int[] shape = new int[4];
    double[] level = new double[4];
    double[] weight = new double[4];
    boolean[] prod = new boolean[4];
    /** The t-norm of an activation outside Table 4 (O-ACT-OTHER-NORM), else null. */
    AndAlgorithm[] norm = new AndAlgorithm[4];

    void clear() {
        n = 0;
    }

    /** Adds the activated set w · ACT(level, μ_shape); callers skip contributions with w · level = 0. */
    void add(int shapeIndex, double activationLevel, double ruleWeight, boolean byProd) {
        add(shapeIndex, activationLevel, ruleWeight, byProd, null);
    }

    /** Adds the activated set w · T(level, μ_shape), T the activation's t-norm. */
    void add(int shapeIndex, double activationLevel, double ruleWeight, ActivationMethod activation) {
        add(shapeIndex, activationLevel, ruleWeight, activation == ActivationMethod.PROD,
                activation.standard() ? null : activation.tNorm());
    }

    private void add(int shapeIndex, double activationLevel, double ruleWeight, boolean byProd, AndAlgorithm tNorm) {
        if (n == shape.length) {
            int c = 2 * n;
            shape = Arrays.copyOf(shape, c);
            level = Arrays.copyOf(level, c);
            weight = Arrays.copyOf(weight, c);
            prod = Arrays.copyOf(prod, c);
            norm = Arrays.copyOf(norm, c);
        }
        shape[n] = shapeIndex;
        level[n] = activationLevel;
        weight[n] = ruleWeight;
        prod[n] = byProd;
        norm[n] = tNorm;
        n++;
    }

    /**
     * Adds as {@link #add(int, double, double, ActivationMethod)}, or, for MIN or PROD activation, raises the level of
     * a contribution already added on the same shape with the same activation and weight. Only for MAX
     * accumulation: there w·min(a, μ) max w·min(b, μ) = w·min(max(a, b), μ), and the same with PROD, exactly in
     * doubles too (each rounding is monotonic), so the set is the same with fewer contributions.
     */
    void addUnderMax(int shapeIndex, double activationLevel, double ruleWeight, ActivationMethod activation) {
        if (activation.standard()) {
            boolean byProd = activation == ActivationMethod.PROD;
            for (int j = 0; j < n; j++) {
                if (shape[j] == shapeIndex && norm[j] == null && prod[j] == byProd && weight[j] == ruleWeight) {
                    level[j] = Math.max(level[j], activationLevel);
                    return;
                }
            }
        }
        add(shapeIndex, activationLevel, ruleWeight, activation);
    }

    /** A.15 with Table 4: contribution j at membership degree mu; the weight multiplies the result of activation. */
    double activate(int j, double mu) {
        double l = level[j];
        if (norm[j] != null) {
            return weight[j] * Norms.and(norm[j], l, mu);
        }
        return activate(weight[j], l, prod[j], mu);
    }

    /** A.15 with Table 4's MIN or PROD: w · min(level, μ), or w · (level · μ). */
    static double activate(double w, double level, boolean byProd, double mu) {
        return w * (byProd ? level * mu : Math.min(level, mu));
    }

    /**
     * The term degrees at which contribution j's activation has a kink or a jump (MIN: its level; bounded
     * difference: 1 − level; nilpotent minimum: both), for the integration's split points.
     */
    double[] kinkDegrees(int j) {
        if (norm[j] == null) {
            return prod[j] ? new double[0] : new double[] {level[j]};
        }
        return switch (norm[j]) {
            case BDIF -> new double[] {1 - level[j]};
            case NMIN -> new double[] {level[j], 1 - level[j]};
            default -> new double[0];
        };
    }
}
