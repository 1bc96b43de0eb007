package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;

/** FCL-C012: a constant weighting factor after WITH lies in [0, 1] (5.2.4). */
public final class WeightsWithinUnitInterval implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C012", "5.2.4",
            "every constant weighting factor (WITH) is between 0 and 1");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (OperandUse use : Scope.of(block).operandUses()) {
            if (use.role() == OperandUse.Role.WEIGHT && use.operand() instanceof Literal w
                    && !(w.value() >= 0 && w.value() <= 1)) {
                sink.report(finding(w.location(), "WITH " + Describe.number(w.value()) + ": " + use.where()
                        + " must be between 0.0 and 1.0 (5.2.4)"));
            }
        }
    }
}
