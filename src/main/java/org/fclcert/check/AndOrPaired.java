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

    /**
     * A rule block where a dialect reader recorded {@code O-UNPAIRED-OPERATORS} (fuzzylite evaluates any AND
     * with any OR, and the reader has warned) is that library's Open Level reading, not a mistake.
     */
    @Override
    public void check(org.fclcert.model.Program program, DiagnosticSink sink) {
        java.util.Set<org.fclcert.model.SourceLocation> tolerated = new java.util.TreeSet<>();   // by place: equals ignores it
        program.dialectFeatures().stream().filter(u -> u.feature() == org.fclcert.model.Feature.O_UNPAIRED_OPERATORS)
                .forEach(u -> tolerated.add(u.location()));
        for (FunctionBlock fb : program.functionBlocks()) {
            check(fb, tolerated, sink);
        }
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        check(block, java.util.Set.of(), sink);
    }

    private void check(FunctionBlock block, java.util.Set<org.fclcert.model.SourceLocation> tolerated,
            DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            if (rb.and().isEmpty() || rb.or().isEmpty() || tolerated.contains(rb.location())) {
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
