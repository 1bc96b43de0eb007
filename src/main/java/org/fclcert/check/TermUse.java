package org.fclcert.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import org.fclcert.model.Condition;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;

/**
 * One {@code variable IS term} of a rule (a subcondition or a subconclusion), with the terms that variable
 * may name there. The rules about term names ({@link NoUndefinedTerms}, {@link TermsBelongToTheirVariable})
 * judge the same uses from two sides, so the walk over the rules is here once.
 *
 * @param variable    the variable before {@code IS}
 * @param term        the term after it
 * @param inCondition whether the use is a subcondition (else a subconclusion)
 * @param terms       the terms the variable may name for this use; empty when another rule reports the use
 * @param element     the use described for a message, built only when one is reported
 * @param location    where the use stands
 */
record TermUse(String variable, String term, boolean inCondition, Optional<List<Term>> terms,
        Supplier<String> element, SourceLocation location) {

    /** Every named-term use of the scope's block, rule by rule in source order ({@code x IS ANY} names no term). */
    static List<TermUse> of(Scope scope) {
        List<TermUse> uses = new ArrayList<>();
        for (RuleBlock rb : scope.block().ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Condition c : scope.subconditions(rule)) {
                    if (c instanceof Condition.TermSubcondition t && !t.any()) {
                        uses.add(new TermUse(t.variable(), t.term(), true, scope.conditionTerms(t.variable()),
                                () -> Describe.subcondition(t), t.location()));
                    }
                }
                for (Subconclusion s : rule.conclusion()) {
                    if (s.term().isPresent()) {
                        uses.add(new TermUse(s.variable(), s.term().get(), false, scope.conclusionTerms(s.variable()),
                                () -> Describe.subconclusion(s), s.location()));
                    }
                }
            }
        }
        return uses;
    }
}
