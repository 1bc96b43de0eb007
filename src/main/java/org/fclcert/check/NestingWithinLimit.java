package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Limits;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;

/**
 * FCL-C026: parentheses in a condition are nested at most {@link Limits#MAX_NESTING_DEPTH} deep.
 * Table 11 lets every system state its own nesting limit; this is fclcert's. Reported once per rule,
 * at the first parenthesis beyond the limit.
 */
public final class NestingWithinLimit implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C026", "Table 11",
            "no condition nests parentheses deeper than " + Limits.MAX_NESTING_DEPTH);

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                if (Conditions.parenthesisDepth(rule.condition()) <= Limits.MAX_NESTING_DEPTH) {
                    continue;    // most rules: no node to find, without listing them all
                }
                Conditions.nodes(rule.condition()).stream()
                        .filter(n -> n.parenthesisDepth() > Limits.MAX_NESTING_DEPTH).findFirst()
                        .ifPresent(n -> sink.report(finding(n.condition().location(), "rule " + rule.name()
                                + " of rule block '" + rb.name() + "' nests parentheses deeper than fclcert's limit of "
                                + Limits.MAX_NESTING_DEPTH + " (Table 11 lets each system state its nesting depth);"
                                + " simplify the condition")));
            }
        }
    }
}
