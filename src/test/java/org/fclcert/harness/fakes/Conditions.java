package org.fclcert.harness.fakes;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;

/** Condition rewrites for the fakes. */
final class Conditions {
    private Conditions() {
    }

    /**
     * Re-reads a condition as if AND and OR had the same precedence and combined left to right: the
     * operands and operators outside parentheses, in text order, folded from the left.
     */
    static Condition leftToRight(Condition c) {
        List<Condition> operands = new ArrayList<>();
        List<Boolean> ands = new ArrayList<>();
        flatten(c, operands, ands);
        Condition acc = operands.get(0);
        for (int i = 1; i < operands.size(); i++) {
            acc = ands.get(i - 1) ? new Condition.And(List.of(acc, operands.get(i)), c.location())
                    : new Condition.Or(List.of(acc, operands.get(i)), c.location());
        }
        return acc;
    }

    private static void flatten(Condition c, List<Condition> operands, List<Boolean> ands) {
        if (c instanceof Condition.And and) {
            sequence(and.operands(), true, operands, ands);
        } else if (c instanceof Condition.Or or) {
            sequence(or.operands(), false, operands, ands);
        } else if (c instanceof Condition.Parenthesized p) {
            operands.add(new Condition.Parenthesized(leftToRight(p.inner()), p.location()));
        } else if (c instanceof Condition.Not n) {
            operands.add(new Condition.Not(leftToRight(n.operand()), n.location()));
        } else {
            operands.add(c);
        }
    }

    private static void sequence(List<Condition> items, boolean and, List<Condition> operands, List<Boolean> ands) {
        for (int i = 0; i < items.size(); i++) {
            if (i > 0) {
                ands.add(and);
            }
            flatten(items.get(i), operands, ands);
        }
    }

    /** Where the program first negates a subcondition (NOT or IS NOT), if it does. */
    static Optional<SourceLocation> firstNegation(Program p) {
        for (FunctionBlock fb : p.functionBlocks()) {
            for (RuleBlock rb : fb.ruleBlocks()) {
                for (Rule r : rb.rules()) {
                    Optional<SourceLocation> at = negation(r.condition());
                    if (at.isPresent()) {
                        return at;
                    }
                }
            }
        }
        return Optional.empty();
    }

    private static Optional<SourceLocation> negation(Condition c) {
        if (c instanceof Condition.Not n) {
            return Optional.of(n.location());
        }
        if (c instanceof Condition.TermSubcondition t && t.negated()) {
            return Optional.of(t.location());
        }
        List<Condition> children = c instanceof Condition.And a ? a.operands()
                : c instanceof Condition.Or o ? o.operands()
                : c instanceof Condition.Parenthesized p ? List.of(p.inner()) : List.of();
        return children.stream().map(Conditions::negation).flatMap(Optional::stream).findFirst();
    }
}
