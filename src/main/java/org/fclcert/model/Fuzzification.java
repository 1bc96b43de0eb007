package org.fclcert.model;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * {@code FUZZIFY variable ... END_FUZZIFY}: the linguistic terms of an input variable (5.2.2).
 *
 * @param declaredRange the input's RANGE where a dialect writes one in FUZZIFY (jFuzzyLogic, fuzzylite; Open
 *                      Level O-INPUT-RANGE), finite; always empty for the strict reader (the standard has no
 *                      input range). It has no effect on evaluation, so, like locations, it takes no part in
 *                      {@link #equals}; the conversion to standard FCL uses it as the interval to approximate
 *                      the input's curved terms over.
 */
public record Fuzzification(String variable, List<Term> terms, SourceLocation location,
        Optional<Range> declaredRange) {
    public Fuzzification {
        terms = List.copyOf(terms);
        Objects.requireNonNull(declaredRange);
    }

    /** A FUZZIFY block as the standard writes it: no range. */
    public Fuzzification(String variable, List<Term> terms, SourceLocation location) {
        this(variable, terms, location, Optional.empty());
    }

    public Optional<Term> term(String name) {
        return terms.stream().filter(t -> Names.same(t.name(), name)).findFirst();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Fuzzification f && variable.equals(f.variable) && terms.equals(f.terms)
                && location.equals(f.location);
    }

    @Override
    public int hashCode() {
        return Objects.hash(variable, terms, location);
    }
}
