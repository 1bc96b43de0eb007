package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.RuleBlock;

/** FCL-W002 (warning): every rule block has at least one rule; an empty block is never used. */
public final class NoEmptyRuleBlocks implements FunctionBlockRule {
    @Override
    public String code() {
        return "FCL-W002";
    }

    @Override
    public String asserts() {
        return "every rule block contains a rule";
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
