package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;

/** FCL-W004 (warning): no subconclusion has the constant weighting factor 0, which disables it. */
public final class NoZeroWeights implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.warning("FCL-W004", "5.2.4",
            "no constant weighting factor is 0");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (OperandUse use : Scope.of(block).operandUses()) {
            if (use.role() == OperandUse.Role.WEIGHT && use.operand() instanceof Literal w && w.value() == 0) {
                sink.report(finding(w.location(), "WITH 0: " + use.where()
                        + " is 0, so the subconclusion never has any effect; remove it or use a positive factor"));
            }
        }
    }
}
