package org.fclcert.check;

import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;

/**
 * FCL-C015: a rule block whose rules use AND or OR declares an operator algorithm. Declaring one of
 * the two is enough: the other is its Table 3 pair.
 */
public final class OperatorDeclaredWhenUsed implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C015", "5.2.4, Table 3",
            "a rule block whose rules use AND or OR declares 'AND:' or 'OR:'");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            if (rb.and().isPresent() || rb.or().isPresent()) {
                continue;
            }
            for (Rule rule : rb.rules()) {
                Optional<Condition> use = firstOperator(rule.condition());
                if (use.isPresent()) {
                    String op = use.get() instanceof Condition.And ? "AND" : "OR";
                    sink.report(finding(use.get().location(), "rule " + rule.name() + " uses " + op
                            + " but rule block '"
                            + rb.name() + "' declares no operator algorithm; add for example 'AND: MIN;'"
                            + " (its pair OR: MAX follows from Table 3) (5.2.4)"));
                    break;
                }
            }
        }
    }

    static Optional<Condition> firstOperator(Condition condition) {
        return Conditions.nodes(condition).stream().map(Conditions.Node::condition)
                .filter(c -> c instanceof Condition.And || c instanceof Condition.Or).findFirst();
    }
}
