package org.fclcert.check;

import java.util.List;
import java.util.function.Supplier;
import java.util.Optional;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Term;

/**
 * FCL-C002: the term after {@code IS} is defined with TERM for that variable (5.2.4). Also reports
 * {@code IS} on a variable whose FUZZIFY or DEFUZZIFY block defines no terms at all.
 *
 * <p>Division of labour: a term that another variable of the same role defines (another input's
 * term in a condition, another output's term in a conclusion) is FCL-C003's, a mix-up of variables.
 * A term only a variable of the other role defines (an input's term in a conclusion, as in rule 2 of
 * Annex C, Figure C.16) is undefined for this use and reported here, naming where it is defined.
 * {@code IS} on a variable with no such block at all is FCL-C027's (conditions) or FCL-C031's
 * (conclusions).
 */
public final class NoUndefinedTerms implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C002", "5.2.4",
            "the term of every 'variable IS term' is defined for that variable");

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
        String variable = use.variable();
        String term = use.term();
        boolean inCondition = use.inCondition();
        SourceLocation at = use.location();
        Supplier<String> element = use.element();
        if (terms.isEmpty()) {
            return;
        }
        if (terms.get().isEmpty()) {
            sink.report(finding(at, element.get() + ": " + scope.describe(variable) + " has no terms; define '" + term
                    + "' with TERM in its block (5.2.2, 5.2.3)"));
            return;
        }
        boolean defined = Scope.hasTerm(terms.get(), term);
        if (defined || !scope.ownersOfTerm(term, variable, inCondition).isEmpty()) {
            return;
        }
        List<String> elsewhere = scope.ownersOfTerm(term, variable, !inCondition);
        String note = elsewhere.isEmpty() ? "" : "; '" + term + "' is a term of "
                + String.join(" and ", elsewhere.stream().map(scope::describe).toList())
                + (inCondition ? ", and a condition tests only inputs" : ", and a conclusion sets only outputs");
        // a name another variable defines is a mix-up, not a typo: no guess then
        String hint = elsewhere.isEmpty()
                ? Scope.suggestTerm(term, terms.get()).map(t -> "; did you mean '" + t + "'?").orElse("") : "";
        sink.report(finding(at, element.get() + ": '" + term + "' is not a term of " + scope.describe(variable)
                + hint + " (its terms: " + Describe.termNames(terms.get()) + ")" + note));
    }
}
