package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;

/** FCL-C017: every DEFUZZIFY block gives a DEFAULT value or NC (the 5.4 production requires it). */
public final class DefaultDeclared implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C017", "5.2.3, 5.4",
            "every DEFUZZIFY block declares DEFAULT (a value or NC)");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.defaultValue().isEmpty()) {
                sink.report(finding(d.location(), "DEFUZZIFY " + d.variable()
                        + " has no DEFAULT; add 'DEFAULT := value;'"
                        + " or 'DEFAULT := NC;' for the output when no rule fires (5.2.3)"));
            }
        }
    }
}
