package org.fclcert.model;

/**
 * One point of a piece-wise linear membership function: abscissa {@code x} (a literal or an input
 * variable, 5.2.2) and membership degree (a literal; a variable degree is an Open Level feature,
 * Table 10).
 */
public record Point(Operand x, Operand degree, SourceLocation location) {
}
