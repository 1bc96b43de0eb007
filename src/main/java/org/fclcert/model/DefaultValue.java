package org.fclcert.model;

/** {@code DEFAULT := value;} or {@code DEFAULT := NC;} (5.2.3): the output when no rule has fired. */
public sealed interface DefaultValue {
    SourceLocation location();

    /** A constant output value. */
    record Constant(Literal value, SourceLocation location) implements DefaultValue {
    }

    /** NC, no change: the output keeps its previous value. */
    record NoChange(SourceLocation location) implements DefaultValue {
    }
}
