package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/** {@code FUZZIFY variable ... END_FUZZIFY}: the linguistic terms of an input variable (5.2.2). */
public record Fuzzification(String variable, List<Term> terms, SourceLocation location) {
    public Fuzzification {
        terms = List.copyOf(terms);
    }

    public Optional<Term> term(String name) {
        return terms.stream().filter(t -> Names.same(t.name(), name)).findFirst();
    }
}
