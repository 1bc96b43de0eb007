package org.fclcert.model;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * {@link FunctionBlock#variable}, {@link FunctionBlock#fuzzification} and {@link FunctionBlock#defuzzification}
 * by hash instead of a walk of the list, for code that looks up every name of a large block (a block may
 * declare 100 000 variables, and a walk per name is quadratic). The first of two declarations differing only in
 * case wins, as the walks find it. Built in time linear in the block; the block is immutable, so it stays true.
 */
public final class BlockIndex {
    private final Map<String, Variable> variables = new HashMap<>();
    private final Map<String, Fuzzification> fuzzifications = new HashMap<>();
    private final Map<String, Defuzzification> defuzzifications = new HashMap<>();

    private BlockIndex(FunctionBlock fb) {
        fb.variables().forEach(v -> variables.putIfAbsent(Names.key(v.name()), v));
        fb.fuzzifications().forEach(f -> fuzzifications.putIfAbsent(Names.key(f.variable()), f));
        fb.defuzzifications().forEach(d -> defuzzifications.putIfAbsent(Names.key(d.variable()), d));
    }

    public static BlockIndex of(FunctionBlock fb) {
        return new BlockIndex(fb);
    }

    public Optional<Variable> variable(String name) {
        return Optional.ofNullable(variables.get(Names.key(name)));
    }

    public Optional<Fuzzification> fuzzification(String variable) {
        return Optional.ofNullable(fuzzifications.get(Names.key(variable)));
    }

    public Optional<Defuzzification> defuzzification(String variable) {
        return Optional.ofNullable(defuzzifications.get(Names.key(variable)));
    }
}
