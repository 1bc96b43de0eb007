package org.fclcert.model;

/** A use of a variable by name, resolved case-insensitively against the function block's declarations. */
public record VariableRef(String name, SourceLocation location) implements Operand {
}
