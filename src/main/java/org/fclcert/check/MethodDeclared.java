package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;

/** FCL-C016: every DEFUZZIFY block names its defuzzification METHOD (5.2.3, 5.4). */
public final class MethodDeclared implements FunctionBlockRule {
    @Override
    public String code() {
        return "FCL-C016";
    }

    @Override
    public String asserts() {
        return "every DEFUZZIFY block declares METHOD";
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
