package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;

/** FCL-C016: every DEFUZZIFY block names its defuzzification METHOD (5.2.3, 5.4). */
public final class MethodDeclared implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C016", "5.2.3, 5.4",
            "every DEFUZZIFY block declares METHOD");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.method().isEmpty()) {
                sink.report(finding(d.location(), "DEFUZZIFY " + d.variable()
                        + " has no METHOD; add one of 'METHOD: CoG;', 'CoGS', 'CoA', 'LM' or 'RM' (5.2.3, Table 1)"));
            }
        }
    }
}
