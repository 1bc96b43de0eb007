package org.fclcert.model;

/**
 * A place where FCL takes either a constant or the name of a variable: a point's abscissa or degree,
 * a singleton's value, a weighting factor.
 */
public sealed interface Operand permits Literal, VariableRef {
    SourceLocation location();
}
