package org.fclcert.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.function.ToIntFunction;
import org.fclcert.model.Condition;

/**
 * A rule condition compiled to postfix code, so that aggregation (A.2.3) walks two int arrays with
 * a preallocated stack instead of a tree. Operator priority (Table 6) is already resolved in the
 * model: an And node's operands are combined before any Or above it.
 */
final class ConditionCode {
    static final int TERM = 0;
    static final int TERM_NOT = 1;
    static final int VARIABLE = 2;
    static final int NOT = 3;
    static final int AND = 4;
    static final int OR = 5;
    /** A hedge (dialects) applied to the top of the stack; arg is its Hedge ordinal. */
    static final int HEDGE = 6;
    /** {@code x is any} (dialects): degree 1. */
    static final int ONE = 7;

    final int[] ops;
    final int[] args;
    final int maxStack;
    /**
     * The number of operands when the code is one term (negated or not) or one AND or OR of terms (the usual
     * rule: {@code TERM… AND n}), which the evaluator folds without the stack; else 0.
     */
    final int flatTerms;

    private ConditionCode(int[] ops, int[] args, int maxStack) {
        this.ops = ops;
        this.args = args;
        this.maxStack = maxStack;
        this.flatTerms = flatTerms(ops, args);
    }

    private static int flatTerms(int[] ops, int[] args) {
        int n = ops.length == 1 ? 1 : ops.length - 1;
        if (ops.length == 0 || ops.length > 1 && (ops[n] != AND && ops[n] != OR || args[n] != n)) {
            return 0;
        }
        for (int i = 0; i < n; i++) {
            if (ops[i] != TERM && ops[i] != TERM_NOT) {
                return 0;
            }
        }
        return n;
    }

    /**
     * @param termIndex index of the fuzzified degree of {@code variable IS term}
     * @param slot      slot of a variable used directly as a subcondition
     */
    static ConditionCode compile(Condition condition, TermIndex termIndex, ToIntFunction<String> slot) {
        Builder b = new Builder();
        b.emit(condition, termIndex, slot);
        int[] ops = b.ops.stream().mapToInt(Integer::intValue).toArray();
        int[] args = b.args.stream().mapToInt(Integer::intValue).toArray();
        return new ConditionCode(ops, args, b.max);
    }

    /** Finds the fuzzified degree of a term of an input variable. */
    interface TermIndex {
        int of(String variable, String term);
    }

    private static final class Builder {
        final List<Integer> ops = new ArrayList<>();
        final List<Integer> args = new ArrayList<>();
        int depth;
        int max;

        void emit(Condition c, TermIndex termIndex, ToIntFunction<String> slot) {
            if (c instanceof Condition.TermSubcondition t && !t.hedges().isEmpty()) {
                if (t.any()) {
                    push(ONE, 0, 1);
                } else {
                    push(TERM, termIndex.of(t.variable(), t.term()), 1);
                    for (int i = t.hedges().size() - 1; i >= 0; i--) {
                        push(HEDGE, t.hedges().get(i).ordinal(), 0);
                    }
                }
                if (t.negated()) {
                    push(NOT, 0, 0);
                }
            } else if (c instanceof Condition.TermSubcondition t) {
                push(t.negated() ? TERM_NOT : TERM, termIndex.of(t.variable(), t.term()), 1);
            } else if (c instanceof Condition.VariableSubcondition v) {
                push(VARIABLE, slot.applyAsInt(v.variable()), 1);
            } else if (c instanceof Condition.Not n) {
                emit(n.operand(), termIndex, slot);
                push(NOT, 0, 0);
            } else if (c instanceof Condition.Parenthesized p) {
                emit(p.inner(), termIndex, slot);
            } else if (c instanceof Condition.And a) {
                a.operands().forEach(o -> emit(o, termIndex, slot));
                push(AND, a.operands().size(), 1 - a.operands().size());
            } else if (c instanceof Condition.Or o) {
                o.operands().forEach(x -> emit(x, termIndex, slot));
                push(OR, o.operands().size(), 1 - o.operands().size());
            } else {
                throw new IllegalArgumentException("unknown condition " + c);
            }
        }

        private void push(int op, int arg, int stackChange) {
            ops.add(op);
            args.add(arg);
            depth += stackChange;
            max = Math.max(max, depth);
        }
    }
}
