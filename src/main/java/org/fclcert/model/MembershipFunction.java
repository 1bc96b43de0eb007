package org.fclcert.model;

import java.util.List;

/**
 * The membership function of a term (5.4 {@code membership_function ::= singleton | points}):
 * a singleton value, or a piece-wise linear function given by points.
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
}
