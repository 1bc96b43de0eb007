package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;

/** FCL-C011: a constant membership degree of a point lies in [0, 1] (5.2.2). */
public final class DegreesWithinUnitInterval implements FunctionBlockRule {
    @Override
    public String code() {
        return "FCL-C011";
    }

    @Override
    public String asserts() {
        return "every constant membership degree of a point is between 0 and 1";
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (OperandUse use : OperandUse.all(block)) {
            if (use.role() == OperandUse.Role.DEGREE && use.operand() instanceof Literal d
                    && !(d.value() >= 0 && d.value() <= 1)) {
                sink.report(finding(d.location(), use.where() + " is " + Describe.number(d.value())
                        + "; a degree of membership must be between 0 and 1 (5.2.2)"));
            }
        }
    }
}
