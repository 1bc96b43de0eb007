package org.fclcert.model;

import java.util.List;

/**
 * {@code RULE n : IF condition THEN conclusion;} (5.2.4). The name is the rule's number as a decimal
 * string ({@code RULE 01} and {@code RULE 1} are both {@code "1"}) or, in the form 5.2.4's prose
 * allows, an identifier as written. The conclusion is one or more subconclusions.
 */
public record Rule(String name, Condition condition, List<Subconclusion> conclusion, SourceLocation location) {
    public Rule {
        conclusion = List.copyOf(conclusion);
    }

    /** True when the rule is named by a number, as the 5.4 production requires. */
    public boolean numbered() {
        return !name.isEmpty() && Character.isDigit(name.charAt(0));
    }
}
