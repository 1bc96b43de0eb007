package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Term;

/** FCL-C019: METHOD CoGS (centre of gravity for singletons, Table 1) is used only on singleton terms. */
public final class CogsOnlyOnSingletons implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C019", "Table 1",
            "an output defuzzified with CoGS has only singleton terms");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.method().isEmpty() || d.method().get().value() != DefuzzificationMethod.COGS
                    && d.method().get().value() != DefuzzificationMethod.COGSS) {
                continue;
            }
            d.terms().stream().filter(t -> !((t.function() instanceof MembershipFunction.Singleton || t.function() instanceof MembershipFunction.Computed))).findFirst()
                    .ifPresent(t -> report(d, t, sink));
        }
    }

    private void report(Defuzzification d, Term t, DiagnosticSink sink) {
        sink.report(finding(d.method().get().location(), "DEFUZZIFY " + d.variable() + ": METHOD "
                + d.method().get().value().keyword() + " needs singleton"
                + " terms, but term '" + t.name() + "' (line " + t.location().line() + ") is given by points;"
                + " use CoG for point terms (5.2.3, Table 1)"));
    }
}
