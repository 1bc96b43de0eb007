package org.fclcert.model;

import java.util.List;

/**
 * The condition of a rule (5.2.4, 5.4): subconditions combined with AND, OR and NOT, with
 * parentheses. AND and OR are n-ary (a chain {@code a AND b AND c} is one node with three operands,
 * so that long chains do not make deep trees); operator priority (Table 6) is already resolved by
 * the reader: an {@link Or} never appears directly as an operand of an {@link And} or a {@link Not}
 * unless wrapped in {@link Parenthesized}.
 */
public sealed interface Condition {
    SourceLocation location();

    /**
     * {@code variable IS term} or {@code variable IS NOT term}; in the fuzzylite dialect with hedges
     * written before the term (outermost first; NOT, when it is the standard's IS NOT, is {@code negated},
     * applied after the hedges). {@code x is any} (hedge ANY alone) names no term: {@code term} is empty.
     */
    record TermSubcondition(String variable, String term, boolean negated, List<Hedge> hedges, SourceLocation location)
            implements Condition {
        public TermSubcondition {
            hedges = List.copyOf(hedges);
        }

        /** A standard subcondition, without hedges. */
        public TermSubcondition(String variable, String term, boolean negated, SourceLocation location) {
            this(variable, term, negated, List.of(), location);
        }

        /** True for {@code x is any}: no term, degree 1. */
        public boolean any() {
            return hedges.contains(Hedge.ANY);
        }
    }

    /** A bare input variable whose value is used as a degree of membership (5.2.4, Table 9). */
    record VariableSubcondition(String variable, SourceLocation location) implements Condition {
    }

    /** {@code NOT x}: 1 - x (Table 9). */
    record Not(Condition operand, SourceLocation location) implements Condition {
    }

    /** {@code a AND b AND ...}, two or more operands, evaluated left to right. */
    record And(List<Condition> operands, SourceLocation location) implements Condition {
        public And {
            operands = List.copyOf(operands);
        }
    }

    /** {@code a OR b OR ...}, two or more operands, evaluated left to right. */
    record Or(List<Condition> operands, SourceLocation location) implements Condition {
        public Or {
            operands = List.copyOf(operands);
        }
    }

    /** {@code ( condition )}, kept so that feature detection and the writer see the parentheses. */
    record Parenthesized(Condition inner, SourceLocation location) implements Condition {
    }
}
