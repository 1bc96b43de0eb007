package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Term;

/** FCL-C029: a term given by points has at least two points (5.2.2); one value alone is a singleton. */
public final class AtLeastTwoPoints implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C029", "5.2.2",
            "every term given by points has at least two points");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        block.fuzzifications().forEach(f -> f.terms().forEach(t -> check(t, f.variable(), sink)));
        block.defuzzifications().forEach(d -> d.terms().forEach(t -> check(t, d.variable(), sink)));
    }

    private void check(Term t, String variable, DiagnosticSink sink) {
        if (t.function() instanceof MembershipFunction.Points p && p.points().size() < 2) {
            sink.report(finding(t.location(), "term '" + t.name() + "' of '" + variable + "' has " + p.points().size()
                    + (p.points().size() == 1 ? " point" : " points") + "; a membership function needs at least two"
                    + " points (5.2.2)"));
        }
    }
}
