package org.fclcert.check;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Located;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;

/**
 * FCL-C022: rule blocks that conclude the same output (with {@code IS}) declare the same ACCU: the
 * output's terms are accumulated into one fuzzy set, which cannot be done with two methods at once
 * (5.2.4, Table 5). Reported at the ACCU of each later block that differs from the first.
 */
public final class OneAccumulationPerOutput implements FunctionBlockRule {
    private record First(RuleBlock block, AccumulationMethod method) {
    }

    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C022", "5.2.4, Table 5",
            "all rule blocks concluding one output declare the same ACCU");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Map<String, First> first = new HashMap<>();
        for (RuleBlock rb : block.ruleBlocks()) {
            if (rb.accumulation().isEmpty()) {
                continue;
            }
            Located<AccumulationMethod> accu = rb.accumulation().get();
            for (String output : concludedOutputs(rb)) {
                First seen = first.putIfAbsent(Names.key(output), new First(rb, accu.value()));
                if (seen != null && seen.method() != accu.value()) {
                    sink.report(finding(accu.location(), "rule block '" + rb.name() + "' accumulates '" + output
                            + "' with ACCU: " + accu.value() + " but rule block '" + seen.block().name()
                            + "' accumulates it with ACCU: " + seen.method()
                            + "; blocks concluding one output must use one accumulation method (5.2.4)"));
                }
            }
        }
    }

    /** The variables this block concludes with IS, each once, in first-use order. */
    private static Iterable<String> concludedOutputs(RuleBlock rb) {
        Set<String> keys = new HashSet<>();
        java.util.List<String> out = new java.util.ArrayList<>();
        for (Rule rule : rb.rules()) {
            for (Subconclusion s : rule.conclusion()) {
                if (s.term().isPresent() && keys.add(Names.key(s.variable()))) {
                    out.add(s.variable());
                }
            }
        }
        return out;
    }
}
