package org.fclcert.check;

import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Located;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.RuleBlock;

/**
 * FCL-C014: when a rule block declares both AND and OR, the two algorithms form one of the De Morgan
 * pairs of Table 3 (MIN/MAX, PROD/ASUM, BDIF/BSUM). Reported at whichever declaration comes second.
 */
public final class AndOrPaired implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C014", "5.2.4, Table 3",
            "a rule block declaring both AND and OR uses a Table 3 pair of algorithms");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            if (rb.and().isEmpty() || rb.or().isEmpty()) {
                continue;
            }
            Located<AndAlgorithm> and = rb.and().get();
            Located<OrAlgorithm> or = rb.or().get();
            if (and.value().pair() == or.value()) {
                continue;
            }
            var later = and.location().compareTo(or.location()) > 0 ? and.location() : or.location();
            sink.report(finding(later, "rule block '" + rb.name() + "': AND: " + and.value() + " and OR: " + or.value()
                    + " are not a pair of Table 3; with AND: " + and.value() + " use OR: " + and.value().pair()
                    + ", or with OR: " + or.value() + " use AND: " + or.value().pair() + " (5.2.4)"));
        }
    }
}
