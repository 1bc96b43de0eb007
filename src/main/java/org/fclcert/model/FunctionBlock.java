package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/**
 * A fuzzy function block (5.2.1, 5.4): its variables, the FUZZIFY blocks of its inputs, the
 * DEFUZZIFY blocks of its outputs, its rule blocks and its OPTIONS blocks. The lists keep textual
 * order; the standard fixes the order of the block kinds, so the model need not keep it.
 */
public record FunctionBlock(
        String name,
        List<Variable> variables,
        List<Fuzzification> fuzzifications,
        List<Defuzzification> defuzzifications,
        List<RuleBlock> ruleBlocks,
        List<OptionsBlock> options,
        SourceLocation location) {

    public FunctionBlock {
        variables = List.copyOf(variables);
        fuzzifications = List.copyOf(fuzzifications);
        defuzzifications = List.copyOf(defuzzifications);
        ruleBlocks = List.copyOf(ruleBlocks);
        options = List.copyOf(options);
    }

    public Optional<Variable> variable(String name) {
        return variables.stream().filter(v -> Names.same(v.name(), name)).findFirst();
    }

    public List<Variable> variables(VariableKind kind) {
        return variables.stream().filter(v -> v.kind() == kind).toList();
    }

    public Optional<Fuzzification> fuzzification(String variable) {
        return fuzzifications.stream().filter(f -> Names.same(f.variable(), variable)).findFirst();
    }

    public Optional<Defuzzification> defuzzification(String variable) {
        return defuzzifications.stream().filter(d -> Names.same(d.variable(), variable)).findFirst();
    }

    public Optional<RuleBlock> ruleBlock(String name) {
        return ruleBlocks.stream().filter(b -> Names.same(b.name(), name)).findFirst();
    }
}
