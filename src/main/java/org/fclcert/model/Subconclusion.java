package org.fclcert.model;

import java.util.Optional;

/**
 * One part of a rule's conclusion (5.2.4): {@code variable IS term} or a bare {@code variable},
 * optionally followed by {@code WITH weighting_factor} (a literal or a VAR_INPUT variable).
 */
public record Subconclusion(String variable, Optional<String> term, Optional<Operand> weight, SourceLocation location) {
    /** True for a bare variable conclusion ({@code THEN var1, ...}). */
    public boolean bareVariable() {
        return term.isEmpty();
    }
}
