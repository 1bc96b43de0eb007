package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.VariableKind;

/** FCL-C008: FUZZIFY names a VAR_INPUT variable (5.2.2). Undeclared names are FCL-C001's. */
public final class FuzzifyOnlyInputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C008", "5.2.2",
            "every FUZZIFY block is for a VAR_INPUT variable");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (Fuzzification f : block.fuzzifications()) {
            scope.variable(f.variable()).filter(v -> v.kind() != VariableKind.INPUT).ifPresent(v ->
                    sink.report(finding(f.location(), "FUZZIFY " + f.variable() + ": " + Describe.variable(v)
                            + " is declared in " + v.kind().keyword()
                            + "; only VAR_INPUT variables are fuzzified (5.2.2)")));
        }
    }
}
