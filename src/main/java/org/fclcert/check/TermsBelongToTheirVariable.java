package org.fclcert.check;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Term;

/**
 * FCL-C003: a term used after {@code IS} is not a term of another variable of the same role (5.2.4:
 * the term of a subcondition or subconclusion belongs to its own linguistic variable). Catches the
 * slip of naming a real term on the wrong variable: another input's term in a condition, another
 * output's term in a conclusion. A term defined only for the other role is FCL-C002's (see
 * {@link NoUndefinedTerms}).
 */
public final class TermsBelongToTheirVariable implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C003", "5.2.4",
            "a term named after 'variable IS' is not a term of another input (condition) or output (conclusion)");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        for (TermUse use : scope.termUses()) {
            check(scope, use, sink);
        }
    }

    private void check(Scope scope, TermUse use, DiagnosticSink sink) {
        Optional<List<Term>> terms = use.terms();
        String term = use.term();
        if (terms.isEmpty() || terms.get().isEmpty() || Scope.hasTerm(terms.get(), term)) {
            return;
        }
        List<String> owners = scope.ownersOfTerm(term, use.variable(), use.inCondition());
        if (owners.isEmpty()) {
            return;
        }
        String ownedBy = String.join(" and ", owners.stream().map(scope::describe).toList());
        sink.report(finding(use.location(), use.element().get() + ": '" + term + "' is a term of " + ownedBy + ", not of "
                + scope.describe(use.variable()) + " (its terms: " + Describe.termNames(terms.get()) + ")"));
    }
}
