package org.fclcert.check;

import java.util.List;
import java.util.stream.Collectors;
import org.fclcert.model.Condition;
import org.fclcert.model.Literal;
import org.fclcert.model.Operand;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/** Wording shared by the check messages, so that every message names elements the same way. */
final class Describe {
    /** Lists longer than this are cut in messages ("... and 12 more"). */
    private static final int MAX_LISTED = 12;

    private Describe() {
    }

    static String kind(VariableKind kind) {
        return switch (kind) {
            case INPUT -> "input";
            case OUTPUT -> "output";
            case LOCAL -> "local variable";
        };
    }

    static String variable(Variable v) {
        return kind(v.kind()) + " '" + v.name() + "'";
    }

    static String names(List<String> names) {
        if (names.size() <= MAX_LISTED) {
            return String.join(", ", names);
        }
        return String.join(", ", names.subList(0, MAX_LISTED)) + " and " + (names.size() - MAX_LISTED) + " more";
    }

    static String termNames(List<Term> terms) {
        return names(terms.stream().map(Term::name).collect(Collectors.toList()));
    }

    /** A number as written in FCL: integers without a fraction, others in Java's shortest form. */
    static String number(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }

    static String operand(Operand operand) {
        if (operand instanceof Literal literal) {
            return number(literal.value());
        }
        return ((VariableRef) operand).name();
    }

    /** The subcondition as written, e.g. {@code temp IS NOT hot} or {@code w}. */
    static String subcondition(Condition c) {
        if (c instanceof Condition.TermSubcondition t) {
            return t.variable() + " IS " + (t.negated() ? "NOT " : "") + t.term();
        }
        if (c instanceof Condition.VariableSubcondition v) {
            return v.variable();
        }
        return "condition";
    }

    /** The subconclusion as written, without its weighting factor. */
    static String subconclusion(Subconclusion s) {
        return s.term().map(t -> s.variable() + " IS " + t).orElse(s.variable());
    }
}
