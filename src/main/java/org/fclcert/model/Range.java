package org.fclcert.model;

/** {@code RANGE := (min .. max);} of an output variable (5.2.3). */
public record Range(Literal min, Literal max, SourceLocation location) {
}
