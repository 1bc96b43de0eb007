package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.RuleBlock;

/** FCL-C018: every rule block names its accumulation method with ACCU (5.2.4, 5.4). */
public final class AccumulationDeclared implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C018", "5.2.4, 5.4",
            "every rule block declares ACCU");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            if (rb.accumulation().isEmpty()) {
                sink.report(finding(rb.location(), "rule block '" + rb.name()
                        + "' has no ACCU; add one of 'ACCU: MAX;', 'BSUM' or 'NSUM' (5.2.4, Table 5)"));
            }
        }
    }
}
