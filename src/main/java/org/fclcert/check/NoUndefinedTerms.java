package org.fclcert.check;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;

/**
 * FCL-C002: the term after {@code IS} is defined with TERM for that variable (5.2.4). Also reports
 * {@code IS} on a variable whose FUZZIFY or DEFUZZIFY block defines no terms at all. A term that
 * belongs to another variable is FCL-C003's; {@code IS} on a variable with no such block at all is
 * FCL-C027's (conditions) or FCL-C031's (conclusions).
 */
public final class NoUndefinedTerms implements FunctionBlockRule {
    @Override
    public String code() {
        return "FCL-C002";
    }

    @Override
    public String asserts() {
        return "the term of every 'variable IS term' is defined for that variable";
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = new Scope(block);
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Condition c : Conditions.subconditions(rule.condition())) {
                    if (c instanceof Condition.TermSubcondition t) {
                        check(scope, scope.conditionTerms(t.variable()), t.variable(), t.term(),
                                Describe.subcondition(t), t.location(), sink);
                    }
                }
                for (Subconclusion s : rule.conclusion()) {
                    if (s.term().isPresent()) {
                        check(scope, scope.conclusionTerms(s.variable()), s.variable(), s.term().get(),
                                Describe.subconclusion(s), s.location(), sink);
                    }
                }
            }
        }
    }

    private void check(Scope scope, Optional<List<Term>> terms, String variable, String term, String element,
            SourceLocation at, DiagnosticSink sink) {
        if (terms.isEmpty()) {
            return;
        }
        String described = scope.describe(variable);
        if (terms.get().isEmpty()) {
            sink.report(finding(at, element + ": " + described + " has no terms; define '" + term
                    + "' with TERM in its block (5.2.2, 5.2.3)"));
            return;
        }
        boolean defined = terms.get().stream().anyMatch(x -> Names.same(x.name(), term));
        if (!defined && scope.ownersOfTerm(term, variable).isEmpty()) {
            sink.report(finding(at, element + ": '" + term + "' is not a term of " + described
                    + " (its terms: " + Describe.termNames(terms.get()) + ")"));
        }
    }
}
