package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;

/** FCL-C011: a constant membership degree of a point lies in [0, 1] (5.2.2). */
public final class DegreesWithinUnitInterval implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C011", "5.2.2",
            "every constant membership degree of a point is between 0 and 1");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (OperandUse use : Scope.of(block).operandUses()) {
            if (use.role() == OperandUse.Role.DEGREE && use.operand() instanceof Literal d
                    && !(d.value() >= 0 && d.value() <= 1)) {
                sink.report(finding(d.location(), use.where() + " is " + Describe.number(d.value())
                        + "; a degree of membership must be between 0 and 1 (5.2.2)"));
            }
        }
    }
}
