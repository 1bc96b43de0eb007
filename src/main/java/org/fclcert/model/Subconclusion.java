package org.fclcert.model;

import java.util.Optional;

/**
 * One part of a rule's conclusion (5.2.4): {@code variable IS term} or a bare {@code variable},
 * optionally followed by {@code WITH weighting_factor} (a literal or a VAR_INPUT variable).
 *
 * @param hedges dialects only (fuzzylite, Open Level): hedges applied to the rule's degree before it activates
 *               this subconclusion's term, in the order applied; empty in the standard
 */
public record Subconclusion(String variable, Optional<String> term, Optional<Operand> weight,
        java.util.List<Hedge> hedges, SourceLocation location) {
    public Subconclusion {
        hedges = java.util.List.copyOf(hedges);
    }

    public Subconclusion(String variable, Optional<String> term, Optional<Operand> weight, SourceLocation location) {
        this(variable, term, weight, java.util.List.of(), location);
    }

    /** True for a bare variable conclusion ({@code THEN var1, ...}). */
    public boolean bareVariable() {
        return term.isEmpty();
    }
}
