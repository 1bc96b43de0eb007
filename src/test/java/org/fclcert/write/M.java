package org.fclcert.write;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.VariableRef;

/** Short constructors for model elements in tests (locations are irrelevant to equality). */
final class M {
    static final SourceLocation AT = SourceLocation.UNKNOWN;

    private M() {
    }

    static Literal i(long v) {
        return new Literal(v, true, AT);
    }

    static Literal r(double v) {
        return new Literal(v, false, AT);
    }

    static VariableRef v(String name) {
        return new VariableRef(name, AT);
    }

    static Point p(Operand x, Operand degree) {
        return new Point(x, degree, AT);
    }

    static Term points(String name, Point... points) {
        return new Term(name, new MembershipFunction.Points(List.of(points)), AT);
    }

    static Term singleton(String name, Operand value) {
        return new Term(name, new MembershipFunction.Singleton(value), AT);
    }

    static Condition is(String variable, String term) {
        return new Condition.TermSubcondition(variable, term, false, AT);
    }

    static Condition isNot(String variable, String term) {
        return new Condition.TermSubcondition(variable, term, true, AT);
    }

    static Condition bare(String variable) {
        return new Condition.VariableSubcondition(variable, AT);
    }

    static Condition and(Condition... operands) {
        return new Condition.And(List.of(operands), AT);
    }

    static Condition or(Condition... operands) {
        return new Condition.Or(List.of(operands), AT);
    }

    static Condition not(Condition operand) {
        return new Condition.Not(operand, AT);
    }

    static Condition par(Condition inner) {
        return new Condition.Parenthesized(inner, AT);
    }

    static Subconclusion then(String variable, String term) {
        return new Subconclusion(variable, Optional.of(term), Optional.empty(), AT);
    }

    static Subconclusion then(String variable, String term, Operand weight) {
        return new Subconclusion(variable, Optional.of(term), Optional.of(weight), AT);
    }

    static Subconclusion thenVariable(String variable) {
        return new Subconclusion(variable, Optional.empty(), Optional.empty(), AT);
    }
}
