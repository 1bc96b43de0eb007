package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * FCL-C013: a variable used as a point's x or degree, a singleton value or a weighting factor is
 * declared in VAR_INPUT: these are parameters set from outside the function block (5.2.2, 5.2.4).
 */
public final class ParameterVariablesAreInputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C013", "5.2.2, 5.2.4",
            "variables used as points, degrees, singletons or WITH factors are VAR_INPUT variables");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (OperandUse use : scope.operandUses()) {
            if (use.operand() instanceof VariableRef ref) {
                scope.variable(ref.name()).filter(v -> v.kind() != VariableKind.INPUT).ifPresent(v ->
                        sink.report(finding(ref.location(), use.where() + " is " + Describe.variable(v)
                                + ", declared in " + v.kind().keyword() + "; a variable used as "
                                + use.role().words() + " must be declared in VAR_INPUT (5.2.2, 5.2.4)")));
            }
        }
    }
}
