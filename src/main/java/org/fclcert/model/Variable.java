package org.fclcert.model;

import java.util.Optional;

/** One declared variable: {@code name : TYPE [:= initial];} in a VAR_INPUT, VAR_OUTPUT or VAR section. */
public record Variable(
        String name, VariableKind kind, DataType type, Optional<Literal> initialValue, SourceLocation location) {
}
