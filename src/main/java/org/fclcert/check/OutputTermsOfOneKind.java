package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Term;

/**
 * FCL-C021: the terms of one output are all singletons or all point terms: no defuzzification method
 * of Table 1 is defined over a mixture. Reported at the first term whose kind differs from the first term's.
 */
public final class OutputTermsOfOneKind implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C021", "5.2.3, Table 1",
            "an output's terms are all singletons or all given by points");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.terms().isEmpty()) {
                continue;
            }
            Term first = d.terms().get(0);
            boolean singletons = isSingleton(first);
            d.terms().stream().filter(t -> isSingleton(t) != singletons).findFirst().ifPresent(t ->
                    sink.report(finding(t.location(), "DEFUZZIFY " + d.variable() + ": term '" + t.name() + "' is "
                            + kind(!singletons) + " but term '" + first.name() + "' is " + kind(singletons)
                            + "; the terms of one output must all be singletons or all points (5.2.3, Table 1)")));
        }
    }

    private static boolean isSingleton(Term t) {
        return t.function() instanceof MembershipFunction.Singleton || t.function() instanceof MembershipFunction.Computed;
    }

    private static String kind(boolean singleton) {
        return singleton ? "a singleton" : "given by points";
    }
}
