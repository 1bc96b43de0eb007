package org.fclcert.check;

import java.util.HashSet;
import java.util.Set;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * FCL-W003 (warning): every output (VAR_OUTPUT) is concluded by some rule, with {@code IS} or as a
 * bare variable; otherwise it only ever holds its default or initial value.
 */
public final class NoUnconcludedOutputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.warning("FCL-W003", "—",
            "every output is concluded by some rule");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = new Scope(block);
        Set<String> concluded = new HashSet<>();
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Subconclusion s : rule.conclusion()) {
                    // a misspelt output is FCL-C001's, as a typo of the output it most likely means
                    concluded.add(Names.key(scope.suggestVariable(s.variable()).orElse(s.variable())));
                }
            }
        }
        for (Variable v : block.variables(VariableKind.OUTPUT)) {
            if (!concluded.contains(Names.key(v.name()))) {
                sink.report(finding(v.location(), "output '" + v.name() + "' is never concluded by any rule, so no rule"
                        + " ever sets it"));
            }
        }
    }
}
