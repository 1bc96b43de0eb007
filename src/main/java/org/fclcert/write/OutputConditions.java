package org.fclcert.write;

import org.fclcert.model.Condition;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Rule;
import org.fclcert.model.VariableKind;

/**
 * 'output IS term' in a condition, which the libraries read differently: fuzzylite as the degree the term has
 * reached so far in this evaluation (O-OUTPUT-CONDITION), jFuzzyLogic as the term's degree at the output's value
 * when the evaluation began (O-OUTPUT-VALUE-CONDITION), FFLL not at all. A writer whose library reads it otherwise
 * than the program was read reports each such subcondition as a loss (FCL-X109).
 */
final class OutputConditions {
    private OutputConditions() {
    }

    /** @param valueReading the library's reading: true jFuzzyLogic's, false fuzzylite's, null none (FFLL) */
    static void check(Program program, FunctionBlock fb, Findings findings, Boolean valueReading) {
        boolean programValue = program.dialectFeatures().stream()
                .anyMatch(u -> u.feature() == Feature.O_OUTPUT_VALUE_CONDITION);
        if (valueReading != null && valueReading == programValue) {
            return;
        }
        for (RuleBlock rb : fb.ruleBlocks()) {
            for (Rule r : rb.rules()) {
                walk(fb, r, r.condition(), findings, programValue);
            }
        }
    }

    private static void walk(FunctionBlock fb, Rule r, Condition c, Findings findings, boolean programValue) {
        if (c instanceof Condition.TermSubcondition t && !t.any() && fb.variables(VariableKind.OUTPUT).stream()
                .anyMatch(v -> org.fclcert.model.Names.same(v.name(), t.variable()))) {
            findings.lost(t.location(), WriterCode.RULE_FORM, "rule " + r.name() + " reads output '" + t.variable()
                    + "' in its condition (" + (programValue ? "at the output's value when the evaluation begins"
                    : "the degree its term has reached so far") + "), which " + findings.library() + " reads otherwise");
        } else if (c instanceof Condition.And a) {
            a.operands().forEach(x -> walk(fb, r, x, findings, programValue));
        } else if (c instanceof Condition.Or o) {
            o.operands().forEach(x -> walk(fb, r, x, findings, programValue));
        } else if (c instanceof Condition.Not n) {
            walk(fb, r, n.operand(), findings, programValue);
        } else if (c instanceof Condition.Parenthesized q) {
            walk(fb, r, q.inner(), findings, programValue);
        }
    }
}
