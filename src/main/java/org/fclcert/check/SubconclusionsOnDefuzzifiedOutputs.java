package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * FCL-C031: a subconclusion {@code v IS t} names an output (VAR_OUTPUT) that has a DEFUZZIFY block,
 * where its terms are defined (5.2.3, 5.2.4). A local variable can only be concluded as a bare
 * variable. Undeclared names are FCL-C001's, inputs FCL-C024's.
 */
public final class SubconclusionsOnDefuzzifiedOutputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C031", "5.2.3, 5.2.4",
            "'v IS t' in a conclusion names an output with a DEFUZZIFY block");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Subconclusion s : rule.conclusion()) {
                    if (s.term().isPresent()) {
                        scope.variable(s.variable()).ifPresent(v -> check(scope, s, v, sink));
                    }
                }
            }
        }
    }

    private void check(Scope scope, Subconclusion s, Variable v, DiagnosticSink sink) {
        if (v.kind() == VariableKind.LOCAL) {
            String element = Describe.subconclusion(s) + ": ";
            sink.report(finding(s.location(), element + Describe.variable(v) + " has no terms; conclude it as a bare"
                    + " variable ('THEN " + v.name() + "') or use an output with a DEFUZZIFY block (5.2.4)"));
        } else if (v.kind() == VariableKind.OUTPUT && scope.defuzzification(v.name()).isEmpty()) {
            String element = Describe.subconclusion(s) + ": ";
            sink.report(finding(s.location(), element + Describe.variable(v) + " has no DEFUZZIFY block, so it has no"
                    + " terms; add 'DEFUZZIFY " + v.name() + "' with its terms, METHOD and DEFAULT (5.2.3)"));
        }
    }
}
