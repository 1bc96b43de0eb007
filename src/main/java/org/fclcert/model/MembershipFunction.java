package org.fclcert.model;

import java.util.List;

/**
 * The membership function of a term (5.4 {@code membership_function ::= singleton | points}):
 * a singleton value, or a piece-wise linear function given by points; and, from the jFuzzyLogic and
 * fuzzylite dialects only (never from the strict reader), a named shape.
 */
public sealed interface MembershipFunction {

    /** {@code TERM t := 100;} or {@code TERM t := v;} - degree 1 at one value, 0 elsewhere (5.2.3). */
    record Singleton(Operand value) implements MembershipFunction {
    }

    /** {@code TERM t := (x1, y1) (x2, y2) ...;} - linear between successive points (5.2.2). */
    record Points(List<Point> points) implements MembershipFunction {
        public Points {
            points = List.copyOf(points);
        }
    }

    /**
     * {@code TERM t := Gaussian 5 2;} (dialects only, Open Level): the shape's formula with literal
     * parameters in the canonical order of {@link ShapeKind}; the count is checked by FCL-C040.
     */
    record NamedShape(ShapeKind kind, List<Literal> parameters) implements MembershipFunction {
        public NamedShape {
            parameters = List.copyOf(parameters);
        }

        /** The parameter values, canonical order. */
        public double[] values() {
            return parameters.stream().mapToDouble(Literal::value).toArray();
        }

        /** The exact points of a linear shape with the right parameter count, else empty. */
        public java.util.Optional<List<Point>> points() {
            return kind.points(values()).map(xy -> {
                java.util.List<Point> out = new java.util.ArrayList<>();
                SourceLocation at = parameters.isEmpty() ? SourceLocation.UNKNOWN : parameters.get(0).location();
                for (int i = 0; i < xy[0].length; i++) {
                    out.add(new Point(Literal.of(xy[0][i]), Literal.of(xy[1][i]), at));
                }
                return List.copyOf(out);
            });
        }
    }

    /**
     * A Takagi–Sugeno output term (dialects only, Open Level): a crisp value computed from the variables at
     * each evaluation (fuzzylite {@code Constant}, {@code Linear}, {@code Function}; jFuzzyLogic
     * {@code function}); defuzzified like a singleton at that value (weighted average of the rules' values).
     *
     * @param value   the expression
     * @param written how the library wrote it, e.g. {@code Linear 75 250}, for messages and conversion
     */
    record Computed(Expression value, String written) implements MembershipFunction {
    }
}
