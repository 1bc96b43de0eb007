package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.VariableKind;

/** FCL-C009: DEFUZZIFY names a VAR_OUTPUT variable (5.2.3). Undeclared names are FCL-C001's. */
public final class DefuzzifyOnlyOutputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C009", "5.2.3",
            "every DEFUZZIFY block is for a VAR_OUTPUT variable");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (Defuzzification d : block.defuzzifications()) {
            scope.variable(d.variable()).filter(v -> v.kind() != VariableKind.OUTPUT).ifPresent(v ->
                    sink.report(finding(d.location(), "DEFUZZIFY " + d.variable() + ": " + Describe.variable(v)
                            + " is declared in " + v.kind().keyword()
                            + "; only VAR_OUTPUT variables are defuzzified (5.2.3)")));
        }
    }
}
