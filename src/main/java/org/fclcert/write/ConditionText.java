package org.fclcert.write;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import org.fclcert.model.Condition;
import org.fclcert.model.Condition.And;
import org.fclcert.model.Condition.Not;
import org.fclcert.model.Condition.Or;
import org.fclcert.model.Condition.Parenthesized;
import org.fclcert.model.Condition.TermSubcondition;
import org.fclcert.model.Condition.VariableSubcondition;

/**
 * Writes a rule's condition on one line. The work list is explicit rather than recursive so that
 * arbitrarily deep models (long chains, deep parentheses built by tools) cannot overflow the stack.
 *
 * <p>A model read from text keeps its parentheses as {@link Parenthesized} nodes, and the writer
 * emits exactly those. A model built by a tool may nest operators that the text could only express
 * with parentheses (an OR under an AND, an AND under an AND, anything but a subcondition under a
 * NOT); the writer then adds the parentheses, so the meaning is kept, although reading the text back
 * gives the same tree with explicit {@link Parenthesized} nodes.
 */
final class ConditionText {
    private ConditionText() {
    }

    static String of(Condition condition) {
        StringBuilder out = new StringBuilder();
        Deque<Object> work = new ArrayDeque<>();
        work.push(condition);
        while (!work.isEmpty()) {
            Object item = work.pop();
            if (item instanceof String text) {
                out.append(text);
            } else {
                expand((Condition) item, out, work);
            }
        }
        return out.toString();
    }

    /** Writes a leaf directly; pushes the parts of a compound node, last part first. */
    private static void expand(Condition c, StringBuilder out, Deque<Object> work) {
        if (c instanceof TermSubcondition t) {
            if (!t.hedges().isEmpty()) {
                throw new IllegalArgumentException("the hedges " + t.hedges() + " on '" + t.variable()
                        + "' are not expressible in standard FCL; convert the program first");
            }
            out.append(CanonicalWriter.name(t.variable())).append(t.negated() ? " IS NOT " : " IS ").append(CanonicalWriter.name(t.term()));
        } else if (c instanceof VariableSubcondition v) {
            out.append(CanonicalWriter.name(v.variable()));
        } else if (c instanceof Parenthesized p) {
            work.push(")");
            work.push(p.inner());
            out.append('(');
        } else if (c instanceof Not n) {
            pushOperand(c, n.operand(), work);
            out.append("NOT ");
        } else if (c instanceof And a) {
            pushOperands(c, a.operands(), " AND ", work);
        } else if (c instanceof Or o) {
            pushOperands(c, o.operands(), " OR ", work);
        }
    }

    private static void pushOperands(Condition parent, List<Condition> operands, String separator, Deque<Object> work) {
        for (int i = operands.size() - 1; i >= 0; i--) {
            pushOperand(parent, operands.get(i), work);
            if (i > 0) {
                work.push(separator);
            }
        }
    }

    private static void pushOperand(Condition parent, Condition operand, Deque<Object> work) {
        if (needsParentheses(parent, operand)) {
            work.push(")");
            work.push(operand);
            work.push("(");
        } else {
            work.push(operand);
        }
    }

    /** True when writing {@code operand} bare inside {@code parent} would be read back differently (Table 6). */
    static boolean needsParentheses(Condition parent, Condition operand) {
        boolean compound = operand instanceof And || operand instanceof Or;
        if (parent instanceof Not) {
            return compound || operand instanceof Not;
        }
        if (parent instanceof And) {
            return compound;
        }
        return parent instanceof Or && operand instanceof Or;
    }
}
