package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.Condition.And;
import org.fclcert.model.Condition.Not;
import org.fclcert.model.Condition.Or;
import org.fclcert.model.Condition.Parenthesized;
import org.fclcert.model.Condition.TermSubcondition;
import org.fclcert.model.Condition.VariableSubcondition;
import org.fclcert.model.OrAlgorithm;

/**
 * A rule condition in the only form FFLL has: an AND of one subcondition per input. The condition is put in
 * disjunctive normal form and each conjunction becomes a rule of its own. That is exact where it is used:
 * splitting an OR into rules needs OR MAX and ACCU MAX (every t-norm of Table 3 and both activations are
 * monotone, so they distribute over MAX); pushing a NOT through an AND or OR needs the pair of Table 3
 * (De Morgan). A negated subcondition and an input the conjunction does not name are left to the writer
 * (complement terms, a term of degree 1).
 */
final class FfllRules {
    static final int MAX_CONJUNCTIONS = 64;

    private FfllRules() {
    }

    /** A subcondition {@code variable IS [NOT] term}. */
    record Literal(String variable, String term, boolean negated, TermSubcondition at) {
    }

    /** Why a condition has no FFLL form. */
    static final class Unsayable extends Exception {
        Unsayable(String why) {
            super(why, null, false, false);
        }
    }

    /**
     * The conjunctions whose disjunction is the condition.
     *
     * @throws Unsayable with the reason when FFLL's rules cannot state it exactly
     */
    static List<List<Literal>> dnf(Condition c, AndAlgorithm and, OrAlgorithm or, AccumulationMethod accu)
            throws Unsayable {
        return dnf(c, false, and, or, accu);
    }

    private static List<List<Literal>> dnf(Condition c, boolean negate, AndAlgorithm and, OrAlgorithm or,
            AccumulationMethod accu) throws Unsayable {
        if (c instanceof VariableSubcondition v) {
            throw new Unsayable("it uses the variable '" + v.variable() + "' as a subcondition (Table 9)");
        }
        if (c instanceof TermSubcondition t) {
            if (t.any() && t.hedges().size() == 1 && !t.negated() && !negate) {
                List<List<Literal>> always = new ArrayList<>();
                always.add(List.of());   // 'x is any' is 1: the input gets the term of degree 1
                return always;
            }
            if (!t.hedges().isEmpty()) {
                throw new Unsayable("FFLL has no hedges");
            }
            List<List<Literal>> one = new ArrayList<>();
            one.add(List.of(new Literal(t.variable(), t.term(), t.negated() != negate, t)));
            return one;
        }
        if (c instanceof Parenthesized p) {
            return dnf(p.inner(), negate, and, or, accu);
        }
        if (c instanceof Not n) {
            return dnf(n.operand(), !negate, and, or, accu);
        }
        boolean isAnd = c instanceof And;
        List<Condition> operands = isAnd ? ((And) c).operands() : ((Or) c).operands();
        if (negate && (and != AndAlgorithm.MIN || (or != null && or != OrAlgorithm.MAX))) {
            throw new Unsayable("a NOT over an AND or OR is pushed down by De Morgan's law, exact in floating point"
                    + " for AND MIN with OR MAX only");
        }
        boolean conjunction = isAnd != negate;
        if (!conjunction) {
            if ((or != null ? or : and == null ? null : and.pair()) != OrAlgorithm.MAX || accu != AccumulationMethod.MAX) {
                throw new Unsayable("FFLL has no OR; an OR is written as one rule per operand only with OR MAX and"
                        + " ACCU MAX");
            }
            List<List<Literal>> union = new ArrayList<>();
            for (Condition o : operands) {
                union.addAll(dnf(o, negate, and, or, accu));
                if (union.size() > MAX_CONJUNCTIONS) {
                    throw new Unsayable("it expands into more than " + MAX_CONJUNCTIONS + " FFLL rules");
                }
            }
            return union;
        }
        List<List<Literal>> product = new ArrayList<>();
        product.add(List.of());
        for (Condition o : operands) {
            List<List<Literal>> next = new ArrayList<>();
            for (List<Literal> left : product) {
                for (List<Literal> right : dnf(o, negate, and, or, accu)) {
                    List<Literal> both = new ArrayList<>(left);
                    both.addAll(right);
                    next.add(both);
                    if (next.size() > MAX_CONJUNCTIONS) {
                        throw new Unsayable("it expands into more than " + MAX_CONJUNCTIONS + " FFLL rules");
                    }
                }
            }
            product = next;
        }
        return product;
    }
}
