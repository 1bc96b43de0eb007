package org.fclcert.check;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.Term;

/**
 * FCL-C025: an output defuzzified with CoG, CoA, LM or RM (or the Open Level MoM) and no RANGE has no point term with a
 * non-zero constant degree at its first or last point. Such a term keeps that degree out to the
 * ends of the axis (5.2.2), so without a RANGE the accumulated set reaches the limits of the data
 * type (5.2.3) and the defuzzified value is meaningless. Variable degrees are not judged: their
 * value is only known at run time.
 */
public final class BoundedOutputSets implements FunctionBlockRule {
    private static final Set<DefuzzificationMethod> NEED_BOUNDS = EnumSet.of(
            DefuzzificationMethod.COG, DefuzzificationMethod.COA, DefuzzificationMethod.LM, DefuzzificationMethod.RM,
            DefuzzificationMethod.MOM);

    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C025", "5.2.2, 5.2.3",
            "an output using CoG, CoA, LM or RM without RANGE has no term that is non-zero at an outer end"
                    + " (and no smooth named shape)");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.range().isPresent() || d.method().isEmpty() || !NEED_BOUNDS.contains(d.method().get().value())) {
                continue;
            }
            for (Term t : d.terms()) {
                if (t.function() instanceof MembershipFunction.Points p && !p.points().isEmpty()) {
                    check(d, t, p.points(), sink);
                } else if (t.function() instanceof MembershipFunction.NamedShape shape) {
                    java.util.Optional<List<Point>> points = shape.points();
                    if (points.isPresent()) {
                        check(d, t, points.get(), sink);
                    } else if (shape.parameters().size() == shape.kind().arity()) {
                        sink.report(finding(t.location(), "DEFUZZIFY " + d.variable() + ": term '" + t.name()
                                + "' is a " + shape.kind() + " shape, which fclcert integrates only over a RANGE;"
                                + " add a finite RANGE (5.2.3)"));
                    }
                }
            }
        }
    }

    private void check(Defuzzification d, Term t, List<Point> points, DiagnosticSink sink) {
        boolean left = nonZero(points.get(0).degree());
        boolean right = nonZero(points.get(points.size() - 1).degree());
        if (!left && !right) {
            return;
        }
        String side = left && right ? "both ends" : left ? "its first point" : "its last point";
        sink.report(finding(t.location(), "DEFUZZIFY " + d.variable() + ": term '" + t.name() + "' is non-zero at "
                + side + ", so it extends without bound and METHOD " + d.method().get().value().keyword()
                + " has no finite set to work on; add a RANGE (5.2.3) or end the term with degree 0"));
    }

    private static boolean nonZero(Operand degree) {
        return degree instanceof Literal l && l.value() != 0;
    }
}
