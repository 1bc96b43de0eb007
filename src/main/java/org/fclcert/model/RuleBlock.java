package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/**
 * {@code RULEBLOCK name ... END_RULEBLOCK} (5.2.4): the operator definitions for AND and OR, the
 * activation method, the accumulation method and the rules. Each setting is optional in the model
 * so that checks can report exactly what is missing; the Table 3 pairing of AND/OR is applied by
 * the evaluator, not stored here.
 */
public record RuleBlock(
        String name,
        Optional<Located<AndAlgorithm>> and,
        Optional<Located<OrAlgorithm>> or,
        Optional<Located<ActivationMethod>> activation,
        Optional<Located<AccumulationMethod>> accumulation,
        List<Rule> rules,
        SourceLocation location) {

    public RuleBlock {
        rules = List.copyOf(rules);
    }
}
