package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.function.IntToDoubleFunction;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Program;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/** A dialect program and its conversion to standard FCL, evaluated at the same inputs, give the same outputs. */
final class EvaluatesAlike {
    private EvaluatesAlike() {
    }

    /**
     * Evaluates the first function block of {@code a} and of {@code b} with a's first input at
     * {@code first(i)} and its second at {@code second(j)}, for i, j in 0 … points − 1, and asserts each of
     * a's outputs equal to the bit in both; returns the number of input pairs compared.
     */
    static int onGrid(Program a, Program b, int points, IntToDoubleFunction first, IntToDoubleFunction second)
            throws EvaluationException {
        FunctionBlockInstance x = Evaluator.load(a).newInstance();
        FunctionBlockInstance y = Evaluator.load(b).newInstance();
        List<Variable> inputs = a.functionBlocks().get(0).variables(VariableKind.INPUT);
        List<Variable> outputs = a.functionBlocks().get(0).variables(VariableKind.OUTPUT);
        int n = 0;
        for (int i = 0; i < points; i++) {
            for (int j = 0; j < points; j++) {
                double u = first.applyAsDouble(i);
                double v = second.applyAsDouble(j);
                for (FunctionBlockInstance z : List.of(x, y)) {
                    z.set(inputs.get(0).name(), u);
                    z.set(inputs.get(1).name(), v);
                    z.evaluate();
                }
                for (Variable o : outputs) {
                    assertEquals(x.get(o.name()), y.get(o.name()), 0.0, o.name() + " at " + u + ", " + v);
                }
                n++;
            }
        }
        return n;
    }
}
