package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;

/** FCL-C012: a constant weighting factor after WITH lies in [0, 1] (5.2.4). */
public final class WeightsWithinUnitInterval implements FunctionBlockRule {
    @Override
    public String code() {
        return "FCL-C012";
    }

    @Override
    public String asserts() {
        return "every constant weighting factor (WITH) is between 0 and 1";
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (OperandUse use : OperandUse.all(block)) {
            if (use.role() == OperandUse.Role.WEIGHT && use.operand() instanceof Literal w
                    && !(w.value() >= 0 && w.value() <= 1)) {
                sink.report(finding(w.location(), "WITH " + Describe.number(w.value()) + ": " + use.where()
                        + " must be between 0.0 and 1.0 (5.2.4)"));
            }
        }
    }
}
