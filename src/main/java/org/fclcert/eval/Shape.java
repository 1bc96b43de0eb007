package org.fclcert.eval;

/**
 * A compiled linguistic term: its singleton value or its points, each coordinate either a constant
 * or the slot of an input variable (5.2.2 on-line adaptation). Constant points are sorted once at
 * load; points with variables are re-read and stably sorted at each evaluation (5.2.2 NOTE: they
 * may be out of sequence at run time).
 */
final class Shape {
    final boolean singleton;
    final int n;
    final double[] xConst;
    final int[] xSlot;
    final double[] yConst;
    final int[] ySlot;
    /** True when no coordinate comes from a variable. */
    final boolean constant;
    /** The sorted points of a constant shape (shared, never written after construction). */
    final double[] sortedX;
    final double[] sortedY;
    /** A smooth named shape (dialects): its kind and parameters; null for points and singletons. */
    final org.fclcert.model.ShapeKind kind;
    final double[] params;
    /** A Takagi–Sugeno term (dialects): its value from the variables' values; null for the others. */
    final java.util.function.ToDoubleFunction<double[]> computed;

    /** A smooth named shape: degrees from its formula (no points). */
    Shape(org.fclcert.model.ShapeKind kind, double[] params) {
        this.singleton = false;
        this.n = 0;
        this.xConst = new double[0];
        this.xSlot = new int[0];
        this.yConst = new double[0];
        this.ySlot = new int[0];
        this.constant = true;
        this.sortedX = new double[0];
        this.sortedY = new double[0];
        this.kind = kind;
        this.params = params.clone();
        this.computed = null;
    }

    /** A Takagi–Sugeno term: a singleton at a value computed from the variables at each evaluation. */
    Shape(java.util.function.ToDoubleFunction<double[]> computed) {
        this.singleton = true;
        this.n = 1;
        this.xConst = new double[] {0};
        this.xSlot = new int[] {-1};
        this.yConst = new double[] {1};
        this.ySlot = new int[] {-1};
        this.constant = false;
        this.sortedX = new double[1];
        this.sortedY = new double[1];
        this.kind = null;
        this.params = null;
        this.computed = computed;
    }

    Shape(boolean singleton, double[] xConst, int[] xSlot, double[] yConst, int[] ySlot) {
        this.singleton = singleton;
        this.n = xConst.length;
        this.xConst = xConst;
        this.xSlot = xSlot;
        this.yConst = yConst;
        this.ySlot = ySlot;
        this.kind = null;
        this.params = null;
        this.computed = null;
        boolean c = true;
        for (int i = 0; i < n; i++) {
            c &= xSlot[i] < 0 && ySlot[i] < 0;
        }
        this.constant = c;
        this.sortedX = new double[n];
        this.sortedY = new double[n];
        if (c) {
            resolve(null, sortedX, sortedY);
        }
    }

    /** Fills {@code x}/{@code y} with the current points, degrees clamped to [0, 1], stably sorted by x. */
    void resolve(double[] values, double[] x, double[] y) {
        if (computed != null) {
            x[0] = computed.applyAsDouble(values);
            y[0] = 1.0;
            return;
        }
        for (int i = 0; i < n; i++) {
            x[i] = xSlot[i] < 0 ? xConst[i] : values[xSlot[i]];
            double d = ySlot[i] < 0 ? yConst[i] : values[ySlot[i]];
            y[i] = Math.max(0.0, Math.min(1.0, d));
        }
        if (!singleton) {
            Pwl.sortStably(x, y, n);
        }
    }
}
