package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.junit.jupiter.api.Test;

/**
 * The evaluator's shortcuts (issue 24 speed) give what the general steps give: MIN with an exact 0 operand is an
 * exact 0, and MAX-accumulated contributions on one term merged at the larger level make the same set.
 */
class HotPathShortcutsTest {
    @Test
    void minWithAnExactZeroOperandIsAnExactZero() {
        // min(0, y) = 0 for every degree y, however uncertain y is, even when y is below its own bound
        assertEquals(0.0, Norms.andError(AndAlgorithm.MIN, 0.0, 0.0, 0.3, 1e-3, 0.0));
        assertEquals(0.0, Norms.andError(AndAlgorithm.MIN, 1e-17, 1e-16, 0.0, 0.0, 0.0));
        // an operand of 0 that is not exact keeps the bound
        assertEquals(1e-16, Norms.andError(AndAlgorithm.MIN, 0.0, 1e-16, 0.5, 0.0, 0.0));
    }

    @Test
    void contributionsOnOneTermMergeUnderMaxIntoTheSameSet() {
        Shape small = new Shape(false, new double[] {0, 20, 40}, new int[] {-1, -1, -1},
                new double[] {0, 1, 0}, new int[] {-1, -1, -1});
        Shape medium = new Shape(false, new double[] {30, 50, 70}, new int[] {-1, -1, -1},
                new double[] {0, 1, 0}, new int[] {-1, -1, -1});
        Shape[] shapes = {small, medium};
        double[][] x = {small.sortedX, medium.sortedX};
        double[][] y = {small.sortedY, medium.sortedY};
        for (ActivationMethod act : new ActivationMethod[] {ActivationMethod.MIN, ActivationMethod.PROD}) {
            SetBuilder separate = new SetBuilder();
            separate.act.add(0, 0.3, 1.0, act);
            separate.act.add(0, 0.6, 1.0, act);
            separate.act.add(1, 0.2, 1.0, act);
            separate.build(AccumulationMethod.MAX, 0, 100, x, y, shapes);
            SetBuilder merged = new SetBuilder();
            merged.act.addUnderMax(0, 0.3, 1.0, act);
            merged.act.addUnderMax(0, 0.6, 1.0, act);
            merged.act.addUnderMax(1, 0.2, 1.0, act);
            assertEquals(2, merged.act.n, "the two contributions on 'small' are one");
            assertEquals(0.6, merged.act.level[0]);
            merged.build(AccumulationMethod.MAX, 0, 100, x, y, shapes);
            for (int k = 0; k <= 1000; k++) {
                double u = k * 0.1;
                assertEquals(degree(separate, u), degree(merged, u), 1e-15, act + " at " + u);
            }
            // by hand. MIN: 'small' clipped at 0.6 has area 40·0.6 − 20·0.6² = 16.8, 'medium' at 0.2 has 7.2; their
            // overlap on [30, 40] is 0.4 + 0.4 + 0.4 (rising to 0.2 on [30, 34], flat to 36, 'small' falling to 40):
            // 22.8. PROD: 12 + 4, less the overlap of 0.03·(40 − u) and 0.01·(u − 30), crossing at 37.5: 0.375.
            double want = act == ActivationMethod.MIN ? 22.8 : 15.625;
            assertEquals(want, Defuzzifier.area(merged.px, merged.py, merged.np), 1e-12, act.toString());
            assertEquals(want, Defuzzifier.area(separate.px, separate.py, separate.np), 1e-12, act.toString());
        }
    }

    /** The set's degree at u, from its vertices (the largest at a jump). */
    private static double degree(SetBuilder s, double u) {
        return Pwl.degree(s.px, s.py, s.np, u);
    }
}
