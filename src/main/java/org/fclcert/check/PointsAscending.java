package org.fclcert.check;

import java.util.List;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Term;

/**
 * FCL-C010: the constant x values of a term's points never decrease (5.2.2). Equal x values are
 * allowed: two points at one x make a vertical step. Each constant point is compared with the
 * constant points before it; variable points are skipped, as their values are only known at run
 * time (5.2.2 notes they may then be out of sequence).
 */
public final class PointsAscending implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C010", "5.2.2",
            "the constant x values of every term's points are in ascending order");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        block.fuzzifications().forEach(f -> f.terms().forEach(t -> check(t, f.variable(), sink)));
        block.defuzzifications().forEach(d -> d.terms().forEach(t -> check(t, d.variable(), sink)));
    }

    private void check(Term term, String variable, DiagnosticSink sink) {
        if (!(term.function() instanceof MembershipFunction.Points points)) {
            return;
        }
        List<Point> list = points.points();
        Literal previous = null;
        for (int i = 0; i < list.size(); i++) {
            if (!(list.get(i).x() instanceof Literal x)) {
                continue;
            }
            if (previous != null && x.value() < previous.value()) {
                sink.report(finding(list.get(i).location(), "term '" + term.name() + "' of '" + variable + "': point "
                        + (i + 1) + " has x = " + Describe.number(x.value()) + ", less than the x = "
                        + Describe.number(previous.value())
                        + " before it; give points in ascending order of x (5.2.2)"));
                return;
            }
            previous = x;
        }
    }
}
