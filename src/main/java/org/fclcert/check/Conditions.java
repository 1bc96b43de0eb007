package org.fclcert.check;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import org.fclcert.model.Condition;
import org.fclcert.model.Rule;

/**
 * Walks condition trees without recursion: a reader may hand over conditions nested many thousands
 * deep (the robustness tests use 100 000 parentheses), and the checker must not overflow the stack.
 */
final class Conditions {
    private Conditions() {
    }

    /** A node of a condition and the number of parentheses that enclose it (itself included). */
    record Node(Condition condition, int parenthesisDepth) {
    }

    /** Every node of the condition in source order (pre-order, operands left to right). */
    static List<Node> nodes(Condition root) {
        List<Node> out = new ArrayList<>();
        Deque<Node> stack = new ArrayDeque<>();
        stack.push(new Node(root, depthOf(root, 0)));
        while (!stack.isEmpty()) {
            Node node = stack.pop();
            out.add(node);
            List<Condition> children = children(node.condition());
            for (int i = children.size() - 1; i >= 0; i--) {
                Condition child = children.get(i);
                stack.push(new Node(child, depthOf(child, node.parenthesisDepth())));
            }
        }
        return out;
    }

    /** The subconditions ({@code v IS t} and bare variables) of the condition, in source order. */
    static List<Condition> subconditions(Condition root) {
        if (isSubcondition(root)) {
            return List.of(root);       // the usual shapes without a walk: one subcondition,
        }
        List<Condition> operands = root instanceof Condition.And and ? and.operands()
                : root instanceof Condition.Or or ? or.operands() : null;
        if (operands != null && operands.stream().allMatch(Conditions::isSubcondition)) {
            return operands;            // or one AND (OR) over subconditions
        }
        List<Condition> out = new ArrayList<>();
        for (Node node : nodes(root)) {
            if (isSubcondition(node.condition())) {
                out.add(node.condition());
            }
        }
        return out;
    }

    private static boolean isSubcondition(Condition c) {
        return c instanceof Condition.TermSubcondition || c instanceof Condition.VariableSubcondition;
    }

    /** The subconditions of all rules, in source order. */
    static List<Condition> subconditions(List<Rule> rules) {
        List<Condition> out = new ArrayList<>();
        for (Rule rule : rules) {
            out.addAll(subconditions(rule.condition()));
        }
        return out;
    }

    private static int depthOf(Condition c, int parentDepth) {
        return c instanceof Condition.Parenthesized ? parentDepth + 1 : parentDepth;
    }

    private static List<Condition> children(Condition c) {
        if (c instanceof Condition.And and) {
            return and.operands();
        }
        if (c instanceof Condition.Or or) {
            return or.operands();
        }
        if (c instanceof Condition.Not not) {
            return List.of(not.operand());
        }
        if (c instanceof Condition.Parenthesized p) {
            return List.of(p.inner());
        }
        return List.of();
    }
}
