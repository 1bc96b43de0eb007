package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.RuleBlock;

/** FCL-W002 (warning): every rule block has at least one rule; an empty block is never used. */
public final class NoEmptyRuleBlocks implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.warning("FCL-W002", "—",
            "every rule block contains a rule");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            if (rb.rules().isEmpty()) {
                sink.report(finding(rb.location(), "rule block '" + rb.name()
                        + "' has no rules, so it never contributes to any output"));
            }
        }
    }
}
