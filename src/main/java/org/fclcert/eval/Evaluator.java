package org.fclcert.eval;

import java.util.List;
import org.fclcert.model.Program;

/**
 * The reference evaluator of fclcert: computes what IEC 61131-7 defines, exactly (closed-form
 * defuzzification, no sampling), reading the unclear places as {@code docs/semantics.md} says.
 */
public final class Evaluator {
    private Evaluator() {
    }

    /**
     * Compiles a program that passed all checks (no error diagnostics) for evaluation.
     *
     * @throws IllegalArgumentException when the program has an error the checks would report
     *                                  (undeclared names, no METHOD, CoA on singletons, ...)
     */
    public static LoadedProgram load(Program checkedProgram) {
        // 'output IS term' in a condition: fuzzylite's reading (the degree reached so far) unless the jFuzzyLogic
        // reader recorded its own (the degree at the output's value when the evaluation begins)
        boolean valueConditions = checkedProgram.dialectFeatures().stream()
                .anyMatch(u -> u.feature() == org.fclcert.model.Feature.O_OUTPUT_VALUE_CONDITION);
        List<BlockPlan> plans = checkedProgram.functionBlocks().stream()
                .map(fb -> BlockCompiler.compile(fb, valueConditions)).toList();
        if (plans.isEmpty()) {
            throw new IllegalArgumentException("the program has no function block");
        }
        return new LoadedProgram(plans);
    }
}
