package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;

/** FCL-C020: METHOD CoA is not used with singleton terms (Table 1, note 3). */
public final class CoaNotOnSingletons implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C020", "Table 1 note 3",
            "an output defuzzified with CoA has no singleton terms");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.method().isEmpty() || d.method().get().value() != DefuzzificationMethod.COA) {
                continue;
            }
            d.terms().stream().filter(t -> (t.function() instanceof MembershipFunction.Singleton || t.function() instanceof MembershipFunction.Computed)).findFirst()
                    .ifPresent(t -> sink.report(finding(d.method().get().location(), "DEFUZZIFY " + d.variable()
                            + ": METHOD CoA does not apply to singletons, but term '" + t.name() + "' (line "
                            + t.location().line() + ") is a singleton; use CoGS for singleton terms"
                            + " (Table 1, note 3)")));
        }
    }
}
