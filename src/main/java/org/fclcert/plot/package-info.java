/**
 * Pictures of a program for people: the membership functions of every variable, the control surface
 * of an output over two inputs (a heat map) and the transfer curve of an output over one input, as
 * self-contained SVG (no scripts, no fonts or files fetched). Every value drawn comes from the model
 * (exact corners of piece-wise linear terms) or from the reference evaluator, sampled only for drawing.
 * Depends on {@code eval} and {@code model} only.
 */
package org.fclcert.plot;
