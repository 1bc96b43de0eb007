package org.fclcert.eval;

import java.util.Arrays;

/**
 * The activated contributions to one output's accumulated set (A.15): per contribution the shape
 * index, the activation level, the rule weight and whether it is activated by PROD (else MIN). Shared
 * by {@link SetBuilder} and {@link SmoothSet}, whose loops read the arrays directly. The arrays grow on
 * demand and are reused, so the steady state allocates nothing.
 */
final class Activations {
    /** Number of contributions added since {@link #clear}. */
    int n;
    int[] shape = new int[4];
    double[] level = new double[4];
    double[] weight = new double[4];
    boolean[] prod = new boolean[4];

    void clear() {
        n = 0;
    }

    /** Adds the activated set w · ACT(level, μ_shape); callers skip contributions with w · level = 0. */
    void add(int shapeIndex, double activationLevel, double ruleWeight, boolean byProd) {
        if (n == shape.length) {
            int c = 2 * n;
            shape = Arrays.copyOf(shape, c);
            level = Arrays.copyOf(level, c);
            weight = Arrays.copyOf(weight, c);
            prod = Arrays.copyOf(prod, c);
        }
        shape[n] = shapeIndex;
        level[n] = activationLevel;
        weight[n] = ruleWeight;
        prod[n] = byProd;
        n++;
    }

    /** A.15 with Table 4: contribution j at membership degree mu; the weight multiplies the result of activation. */
    double activate(int j, double mu) {
        double l = level[j];
        return weight[j] * (prod[j] ? l * mu : Math.min(l, mu));
    }
}
