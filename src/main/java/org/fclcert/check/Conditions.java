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

    /**
     * The largest {@link Node#parenthesisDepth} of the condition's nodes, without making the nodes (a large block asks
     * this of every rule, and most rules nest no parentheses at all).
     */
    static int parenthesisDepth(Condition root) {
        if (isSubcondition(root)) {
            return 0;
        }
        int deepest = 0;
        Deque<Condition> stack = new ArrayDeque<>();
        Deque<Integer> depths = new ArrayDeque<>();
        stack.push(root);
        depths.push(0);
        while (!stack.isEmpty()) {
            Condition c = stack.pop();
            int depth = depthOf(c, depths.pop());
            deepest = Math.max(deepest, depth);
            for (Condition child : children(c)) {
                if (!isSubcondition(child)) {     // a subcondition is as deep as its parent
                    stack.push(child);
                    depths.push(depth);
                }
            }
        }
        return deepest;
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
        // the order of nodes(root), without making a node for each
        List<Condition> out = new ArrayList<>();
        Deque<Condition> stack = new ArrayDeque<>();
        stack.push(root);
        while (!stack.isEmpty()) {
            Condition c = stack.pop();
            if (isSubcondition(c)) {
                out.add(c);
                continue;
            }
            List<Condition> children = children(c);
            for (int i = children.size() - 1; i >= 0; i--) {
                stack.push(children.get(i));
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
