package org.fclcert.check;

import java.util.HashMap;
import java.util.Map;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;

/**
 * FCL-C007: the rules of a rule block have distinct numbers (or names) (5.2.4). The reader already
 * normalises numbers, so {@code RULE 01} and {@code RULE 1} are the same rule name here.
 */
public final class UniqueRuleNames implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C007", "5.2.4",
            "each rule number or name is used once per rule block");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            Map<String, Rule> seen = new HashMap<>();
            for (Rule rule : rb.rules()) {
                Rule first = seen.putIfAbsent(Names.key(rule.name()), rule);
                if (first != null) {
                    sink.report(finding(rule.location(), "RULE " + rule.name() + " in rule block '" + rb.name()
                            + "' repeats the number of the rule at line " + first.location().line()
                            + "; each rule needs a unique number in its rule block (5.2.4)"));
                }
            }
        }
    }
}
