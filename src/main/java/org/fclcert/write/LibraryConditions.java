package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.Condition.And;
import org.fclcert.model.Condition.Not;
import org.fclcert.model.Condition.Or;
import org.fclcert.model.Condition.Parenthesized;
import org.fclcert.model.Condition.TermSubcondition;
import org.fclcert.model.Condition.VariableSubcondition;
import org.fclcert.model.Hedge;
import org.fclcert.model.OrAlgorithm;

/**
 * Rule conditions as fuzzylite and jFuzzyLogic write them. Both get every operand that is itself an AND or an
 * OR in parentheses: jFuzzyLogic gives AND and OR one priority (left to right), and writing the grouping out
 * leaves no reader to guess. fuzzylite has no NOT operator, so a NOT is pushed down to the subconditions
 * (De Morgan, exact for the pairs of Table 3) and written as {@code is not}.
 */
final class LibraryConditions {
    private LibraryConditions() {
    }

    /**
     * The condition without what the library cannot say — bare-variable subconditions (Table 9), and hedges
     * unless {@code hedges} — each reported as lost; empty when nothing is left.
     */
    static Optional<Condition> clean(Condition c, boolean hedges, BlockContext cx, String rule) {
        if (c instanceof VariableSubcondition v) {
            cx.findings.lost(v.location(), WriterCode.BARE_VARIABLE, "rule " + rule + " uses the variable '"
                    + v.variable() + "' as a subcondition (its value as a degree); " + cx.findings.library()
                    + " takes only 'variable IS term': the subcondition is left out");
            return Optional.empty();
        }
        if (c instanceof TermSubcondition t) {
            if (t.hedges().isEmpty() || hedges) {
                return Optional.of(t);
            }
            cx.findings.lost(t.location(), WriterCode.HEDGE, "rule " + rule + ": " + cx.findings.library()
                    + " has no hedges (" + t.hedges().stream().map(Hedge::word).toList() + " on '" + t.variable()
                    + "'): " + (t.any() ? "the subcondition is" : "the hedges are") + " left out");
            return t.any() ? Optional.empty()
                    : Optional.of(new TermSubcondition(t.variable(), t.term(), t.negated(), List.of(), t.location()));
        }
        if (c instanceof Parenthesized p) {
            return clean(p.inner(), hedges, cx, rule).map(inner -> new Parenthesized(inner, p.location()));
        }
        if (c instanceof Not n) {
            return clean(n.operand(), hedges, cx, rule).map(inner -> new Not(inner, n.location()));
        }
        boolean and = c instanceof And;
        List<Condition> operands = and ? ((And) c).operands() : ((Or) c).operands();
        List<Condition> kept = new ArrayList<>();
        for (Condition o : operands) {
            if (and && o instanceof TermSubcondition t && t.any() && t.hedges().size() == 1 && !t.negated()) {
                continue;   // 'x is any' is 1, the unit of MIN, PROD and BDIF: leaving it out is exact
            }
            clean(o, hedges, cx, rule).ifPresent(kept::add);
        }
        if (kept.isEmpty()) {
            return Optional.empty();
        }
        if (kept.size() == 1) {
            return Optional.of(kept.get(0));
        }
        return Optional.of(and ? new And(kept, c.location()) : new Or(kept, c.location()));
    }

    /** fuzzylite: lower-case keywords, hedges, NOT pushed down; {@code and}/{@code or} as the block declares. */
    static String fuzzylite(Condition c, BlockContext cx, AndAlgorithm and, OrAlgorithm or, String rule) {
        return write(c, false, cx, and, or, rule, true);
    }

    /** jFuzzyLogic: upper-case keywords, {@code IS NOT}, {@code NOT (...)}. */
    static String jfuzzylogic(Condition c, BlockContext cx, String rule) {
        return write(c, false, cx, null, null, rule, false);
    }

    private static String write(Condition c, boolean negate, BlockContext cx, AndAlgorithm and, OrAlgorithm or,
            String rule, boolean fuzzylite) {
        if (c instanceof TermSubcondition t) {
            boolean negated = t.negated() != negate;
            StringBuilder out = new StringBuilder(cx.variable(t.variable())).append(fuzzylite ? " is " : " IS ");
            if (negated) {
                out.append(fuzzylite ? "not " : "NOT ");
            }
            for (Hedge h : t.hedges()) {
                out.append(h.word()).append(' ');
            }
            if (!t.any()) {
                out.append(cx.term(t.variable(), t.term()));
            }
            return out.toString().strip();
        }
        if (c instanceof Parenthesized p) {
            String inner = write(p.inner(), negate, cx, and, or, rule, fuzzylite);
            return p.inner() instanceof And || p.inner() instanceof Or ? "(" + inner + ")" : inner;
        }
        if (c instanceof Not n) {
            Condition operand = n.operand();
            while (operand instanceof Parenthesized p) {
                operand = p.inner();
            }
            if (fuzzylite || operand instanceof TermSubcondition || negate) {
                return write(n.operand(), !negate, cx, and, or, rule, fuzzylite);
            }
            String inner = write(n.operand(), false, cx, and, or, rule, false);
            return inner.startsWith("(") && inner.endsWith(")") && balanced(inner) ? "NOT " + inner : "NOT (" + inner + ")";
        }
        boolean isAnd = c instanceof And;
        List<Condition> operands = isAnd ? ((And) c).operands() : ((Or) c).operands();
        boolean writtenAnd = isAnd != negate;
        if (negate && (and != AndAlgorithm.MIN || or != OrAlgorithm.MAX)) {
            // 1 − max(a, b) = min(1 − a, 1 − b) holds bit for bit; for PROD/ASUM and BDIF/BSUM De Morgan holds in
            // real numbers only, and a degree that rounds to 0 on one side and not on the other decides a DEFAULT
            cx.findings.lost(c.location(), WriterCode.OPERATOR, "rule " + rule + ": fuzzylite has no NOT over an "
                    + (isAnd ? "AND" : "OR") + "; it is written by De Morgan's law, which is exact in floating point"
                    + " for AND MIN with OR MAX only, not for AND " + and + " with OR " + or);
        }
        String separator = fuzzylite ? (writtenAnd ? " and " : " or ") : (writtenAnd ? " AND " : " OR ");
        StringBuilder out = new StringBuilder();
        for (Condition o : operands) {
            if (!out.isEmpty()) {
                out.append(separator);
            }
            String text = write(o, negate, cx, and, or, rule, fuzzylite);
            boolean compound = compound(o, negate, fuzzylite);
            out.append(compound && !(text.startsWith("(") && balanced(text)) ? "(" + text + ")" : text);
        }
        return out.toString();
    }

    /** Whether an operand is written as an AND or an OR chain (and so needs parentheses inside another). */
    private static boolean compound(Condition o, boolean negate, boolean fuzzylite) {
        if (o instanceof And || o instanceof Or) {
            return true;
        }
        if (o instanceof Parenthesized p) {
            return compound(p.inner(), negate, fuzzylite);
        }
        if (o instanceof Not n && (fuzzylite || negate)) {
            return compound(n.operand(), !negate, fuzzylite);
        }
        return false;
    }

    /** Whether the text's first '(' closes at its last character. */
    private static boolean balanced(String text) {
        int depth = 0;
        for (int i = 0; i < text.length(); i++) {
            char ch = text.charAt(i);
            if (ch == '(') {
                depth++;
            } else if (ch == ')') {
                depth--;
                if (depth == 0 && i < text.length() - 1) {
                    return false;
                }
            }
        }
        return depth == 0 && text.startsWith("(");
    }
}
