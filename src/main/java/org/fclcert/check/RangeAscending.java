package org.fclcert.check;

import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Range;

/** FCL-C023: a RANGE's minimum is less than its maximum (5.2.3). */
public final class RangeAscending implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C023", "5.2.3",
            "every RANGE has its minimum below its maximum");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Defuzzification d : block.defuzzifications()) {
            if (d.range().isEmpty()) {
                continue;
            }
            Range r = d.range().get();
            if (!(r.min().value() < r.max().value())) {
                sink.report(finding(r.location(), "DEFUZZIFY " + d.variable() + ": RANGE ("
                        + Describe.number(r.min().value())
                        + " .. " + Describe.number(r.max().value()) + ") is empty; the minimum must be less than the"
                        + " maximum (5.2.3)"));
            }
        }
    }
}
