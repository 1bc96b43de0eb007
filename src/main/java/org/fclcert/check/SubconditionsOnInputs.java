package org.fclcert.check;

import org.fclcert.model.Condition;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * FCL-C027: a subcondition reads a variable that can be read in a condition (5.2.4). {@code v IS t}
 * needs a VAR_INPUT variable with a FUZZIFY block (its terms); a bare variable {@code v} needs a
 * VAR_INPUT variable or a local variable (VAR, written by an earlier rule block), never a VAR_OUTPUT.
 * Undeclared names are FCL-C001's.
 */
public final class SubconditionsOnInputs implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C027", "5.2.2, 5.2.4",
            "'v IS t' names a fuzzified input, and a bare-variable subcondition an input or local variable");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    /**
     * A subcondition where a dialect reader recorded {@code O-OUTPUT-CONDITION} (fuzzylite: the degree the
     * output's term has reached so far) or {@code O-OUTPUT-VALUE-CONDITION} (jFuzzyLogic: its degree at the
     * output's value when the evaluation begins) is that library's Open Level reading, not a mistake.
     */
    @Override
    public void check(org.fclcert.model.Program program, DiagnosticSink sink) {
        java.util.Set<org.fclcert.model.SourceLocation> tolerated = new java.util.TreeSet<>();   // by place: equals ignores it
        program.dialectFeatures().stream().filter(u -> u.feature() == org.fclcert.model.Feature.O_OUTPUT_CONDITION
                || u.feature() == org.fclcert.model.Feature.O_OUTPUT_VALUE_CONDITION).forEach(u -> tolerated.add(u.location()));
        for (FunctionBlock fb : program.functionBlocks()) {
            check(fb, tolerated.isEmpty() ? null : c -> !tolerated.contains(c.location()), sink);
        }
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        check(block, null, sink);
    }

    /** {@code judged}: null when every subcondition is judged. */
    private void check(FunctionBlock block, java.util.function.Predicate<Condition> judged, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Condition c : scope.subconditions(rule)) {
                    if (judged == null || judged.test(c)) {
                        check(scope, c, sink);
                    }
                }
            }
        }
    }

    private void check(Scope scope, Condition c, DiagnosticSink sink) {
        if (c instanceof Condition.TermSubcondition t) {
            Variable v = scope.declaredVariable(t.variable());
            if (v != null && (v.kind() != VariableKind.INPUT || !scope.fuzzified(v.name()))) {
                checkTerm(scope, t, v, sink);
            }
        } else if (c instanceof Condition.VariableSubcondition bare) {
            scope.variable(bare.variable()).filter(v -> v.kind() == VariableKind.OUTPUT).ifPresent(v ->
                    sink.report(finding(c.location(), bare.variable() + ": " + Describe.variable(v)
                            + " cannot be read as a degree of membership in a condition; a bare variable in a"
                            + " condition must be an input (VAR_INPUT) or a local variable (VAR) (5.2.4)")));
        }
    }

    private void checkTerm(Scope scope, Condition.TermSubcondition t, Variable v, DiagnosticSink sink) {
        if (v.kind() != VariableKind.INPUT) {
            sink.report(finding(t.location(), Describe.subcondition(t) + ": " + Describe.variable(v) + " is not an input; 'IS' in a condition"
                    + " needs an input (VAR_INPUT) with a FUZZIFY block (5.2.2, 5.2.4)"));
        } else if (scope.fuzzification(v.name()).isEmpty()) {
            sink.report(finding(t.location(), Describe.subcondition(t) + ": " + Describe.variable(v) + " has no FUZZIFY block, so it has no"
                    + " terms; add 'FUZZIFY " + v.name() + "' with its terms (5.2.2)"));
        }
    }
}
