package org.fclcert.check;

import java.util.List;
import java.util.function.Supplier;
import org.fclcert.model.Condition;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableRef;

/** FCL-C001: every name used as a variable is declared in the function block (5.2.1). */
public final class NoUndefinedVariables implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C001", "5.2.1",
            "every variable named in FUZZIFY, DEFUZZIFY, rules, points, singletons and WITH is declared");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (Fuzzification f : block.fuzzifications()) {
            need(scope, f.variable(), f.location(), () -> "FUZZIFY " + f.variable(), "VAR_INPUT", sink);
        }
        for (Defuzzification d : block.defuzzifications()) {
            need(scope, d.variable(), d.location(), () -> "DEFUZZIFY " + d.variable(), "VAR_OUTPUT", sink);
        }
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                checkRule(scope, rule, sink);
            }
        }
        for (OperandUse use : scope.operandUses()) {
            if (use.operand() instanceof VariableRef ref && !scope.declared(ref.name())) {
                need(scope, ref.name(), ref.location(), use::where, "VAR_INPUT", sink);
            }
        }
    }

    private void checkRule(Scope scope, Rule rule, DiagnosticSink sink) {
        // the message's pieces are made only for an undeclared name (most rules of a large block have none)
        for (Condition c : scope.subconditions(rule)) {
            String variable = c instanceof Condition.TermSubcondition t
                    ? t.variable() : ((Condition.VariableSubcondition) c).variable();
            if (!scope.declared(variable)) {
                need(scope, variable, c.location(), () -> Describe.subcondition(c), "VAR_INPUT", sink);
            }
        }
        for (Subconclusion s : rule.conclusion()) {
            if (!scope.declared(s.variable())) {
                need(scope, s.variable(), s.location(), () -> Describe.subconclusion(s), "VAR_OUTPUT", sink);
            }
        }
    }

    private void need(Scope scope, String name, SourceLocation at, Supplier<String> element, String section,
            DiagnosticSink sink) {
        if (scope.declared(name)) {
            return;
        }
        List<String> declared = scope.block().variables().stream().map(Variable::name).toList();
        String known = declared.isEmpty() ? "it declares no variables"
                : "its variables: " + Describe.names(declared);
        String hint = scope.suggestVariable(name).map(v -> "did you mean '" + v + "'? ").orElse("");
        sink.report(finding(at, element.get() + ": '" + name + "' is not a declared variable of function block '"
                + scope.block().name() + "'; " + hint + "(" + known + "); "
                + (hint.isEmpty() ? "declare it in " + section + " (5.2.1)" : "or declare it in " + section + " (5.2.1)")));
    }
}
