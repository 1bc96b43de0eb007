package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.VariableKind;

/**
 * FCL-C024: no subconclusion names a VAR_INPUT variable: a rule writes outputs (or, with a bare
 * variable, a local variable), never the inputs the function block receives (5.2.4).
 */
public final class ConclusionsOnOutputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C024", "5.2.4",
            "no subconclusion names an input variable");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Subconclusion s : rule.conclusion()) {
                    if (scope.is(s.variable(), VariableKind.INPUT)) {
                        sink.report(finding(s.location(), Describe.subconclusion(s) + ": '" + s.variable()
                                + "' is an input (VAR_INPUT); a conclusion can only set an output (VAR_OUTPUT)"
                                + " or, as a bare variable, a local variable (VAR) (5.2.4)"));
                    }
                }
            }
        }
    }
}
