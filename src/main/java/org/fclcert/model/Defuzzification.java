package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/**
 * {@code DEFUZZIFY variable ... END_DEFUZZIFY}: the linguistic terms of an output variable, its
 * optional RANGE, its METHOD and its DEFAULT (5.2.3). METHOD and DEFAULT are required by the
 * standard; the model keeps them optional so that a check can report their absence precisely.
 */
public record Defuzzification(
        String variable,
        Optional<Range> range,
        List<Term> terms,
        Optional<Located<DefuzzificationMethod>> method,
        Optional<DefaultValue> defaultValue,
        SourceLocation location) {

    public Defuzzification {
        terms = List.copyOf(terms);
    }

    public Optional<Term> term(String name) {
        return terms.stream().filter(t -> Names.same(t.name(), name)).findFirst();
    }
}
