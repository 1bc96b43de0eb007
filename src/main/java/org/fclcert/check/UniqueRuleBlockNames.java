package org.fclcert.check;

import java.util.HashMap;
import java.util.Map;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.RuleBlock;

/** FCL-C006: each rule block of a function block has a unique name (5.2.4); case does not count. */
public final class UniqueRuleBlockNames implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C006", "5.2.4",
            "each rule block name is used once per function block, ignoring case");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Map<String, RuleBlock> seen = new HashMap<>();
        for (RuleBlock rb : block.ruleBlocks()) {
            RuleBlock first = seen.putIfAbsent(Names.key(rb.name()), rb);
            if (first != null) {
                sink.report(finding(rb.location(), "rule block '" + rb.name()
                        + "' has the same name as the rule block '"
                        + first.name() + "' at line " + first.location().line()
                        + "; each rule block needs a unique name (5.2.4)"));
            }
        }
    }
}
