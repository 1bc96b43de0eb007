package org.fclcert.write;

import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Expression;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.MembershipFunction.NamedShape;
import org.fclcert.model.Names;
import org.fclcert.model.Point;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.ShapeNames;

/** Spellings the library writers share: numbers, points, shape names. */
final class LibraryText {
    private LibraryText() {
    }

    /** A number as {@link LiteralText} spells it (both libraries read these spellings: no '_', no leading '.'). */
    static String number(double v) {
        return LiteralText.of(Literal.of(v));
    }

    static String number(Literal l) {
        return LiteralText.of(l);
    }

    /**
     * A Takagi–Sugeno term in fuzzylite's words: {@code Constant c}, or {@code Linear} with one coefficient per input
     * of the block in declaration order and the constant last. Empty when the expression is not a sum of
     * {@code coefficient * input} terms (each input once) and one constant: fclcert writes no {@code Function}.
     */
    static Optional<String> fuzzyliteComputed(BlockContext cx, MembershipFunction.Computed c) {
        Map<String, Double> coefficients = new HashMap<>();
        double[] constant = {0};
        if (!linear(c.value(), coefficients, constant)) {
            return Optional.empty();
        }
        List<Variable> inputs = cx.fb.variables().stream().filter(v -> v.kind() == VariableKind.INPUT).toList();
        if (!inputs.stream().map(v -> Names.key(v.name())).toList().containsAll(coefficients.keySet())) {
            return Optional.empty();            // a term reading an output or a local: not a Linear
        }
        if (coefficients.isEmpty()) {
            return Optional.of("Constant " + number(constant[0]));
        }
        StringBuilder out = new StringBuilder("Linear");
        for (Variable v : inputs) {
            out.append(' ').append(number(coefficients.getOrDefault(Names.key(v.name()), 0.0)));
        }
        return Optional.of(out.append(' ').append(number(constant[0])).toString());
    }

    /** Collects {@code e} as coefficients and a constant; false where that would not be exact. */
    private static boolean linear(Expression e, Map<String, Double> coefficients, double[] constant) {
        if (e instanceof Expression.Binary b && b.operator() == '+') {
            return linear(b.left(), coefficients, constant) && linear(b.right(), coefficients, constant);
        }
        if (e instanceof Expression.Number n) {
            if (n.value() == 0) {
                return true;
            }
            if (constant[0] != 0) {
                return false;                   // two constants would be added in doubles
            }
            constant[0] = n.value();
            return true;
        }
        Expression.Variable v = null;
        double k = 1;
        if (e instanceof Expression.Variable x) {
            v = x;
        } else if (e instanceof Expression.Binary b && b.operator() == '*') {
            if (b.left() instanceof Expression.Number n && b.right() instanceof Expression.Variable x) {
                v = x;
                k = n.value();
            } else if (b.right() instanceof Expression.Number n && b.left() instanceof Expression.Variable x) {
                v = x;
                k = n.value();
            }
        }
        return v != null && coefficients.putIfAbsent(Names.key(v.name()), k) == null;
    }

    /** The finding for a Takagi–Sugeno term a library's layout cannot state. */
    static void computedLost(BlockContext cx, Term t, MembershipFunction.Computed c, String library) {
        cx.findings.lost(t.location(), WriterCode.SHAPE, library + " cannot state the Takagi-Sugeno term '" + t.name()
                + "' (" + c.written() + ") here; it is not written");
    }

    /** {@code (x, y) (x, y) ...}: the point list both libraries and the standard read. */
    static String points(List<Point> points, BlockContext cx, String term) {
        StringBuilder out = new StringBuilder();
        double previous = 0;
        for (Point p : points) {
            if (!out.isEmpty()) {
                out.append(' ');
            }
            // a point given by a variable falls back to the x before it, so that the points stay in order
            String x = cx.numberText(p.x(), previous, WriterCode.POINT_VARIABLE, "a point of term '" + term + "'");
            previous = Double.parseDouble(x);
            out.append('(').append(x)
                    .append(", ").append(cx.numberText(p.degree(), 0, WriterCode.POINT_VARIABLE, "a degree of term '"
                            + term + "'")).append(')');
        }
        return out.toString();
    }

    /** A shape as its library writes it (ShapeNames: the one table of names, orders and scales). */
    static String shape(ShapeNames.Written shape) {
        StringBuilder out = new StringBuilder(shape.name());
        for (Literal p : shape.parameters()) {
            out.append(' ').append(number(p));
        }
        return out.toString();
    }

    /** The method keyword both libraries read (upper case; MoM is spelled MM, Tsukamoto's method is fuzzylite's COGS). */
    static String method(DefuzzificationMethod m) {
        return m == DefuzzificationMethod.MOM ? "MM" : m == DefuzzificationMethod.TSUKAMOTO ? "COGS"
                : m.keyword().toUpperCase(Locale.ROOT);
    }

    static boolean sampled(DefuzzificationMethod m) {
        return m != DefuzzificationMethod.COGS && m != DefuzzificationMethod.COGSS && m != DefuzzificationMethod.TSUKAMOTO;
    }

    static boolean singleton(MembershipFunction f) {
        return f instanceof MembershipFunction.Singleton;
    }

    /** A bound rounded up to 3 significant digits, so that the printed number is still a bound. */
    static String upTo3Digits(double bound) {
        if (!Double.isFinite(bound) || bound == 0) {
            return Double.toString(bound);
        }
        return new java.math.BigDecimal(bound).round(new java.math.MathContext(3, java.math.RoundingMode.UP))
                .stripTrailingZeros().toPlainString();
    }

    /** FCL-X209 when a point list has a vertical edge (two points at one x), where the libraries differ. */
    static void verticalEdge(BlockContext cx, org.fclcert.model.Term t, MembershipFunction.Points p) {
        for (int i = 1; i < p.points().size(); i++) {
            if (p.points().get(i).x() instanceof Literal a && p.points().get(i - 1).x() instanceof Literal b
                    && a.value() == b.value()) {
                cx.findings.differs(t.location(), WriterCode.VERTICAL_EDGE, "term '" + t.name() + "' has a vertical"
                        + " edge at " + number(a) + "; " + cx.findings.library() + " takes another degree there than"
                        + " fclcert does");
                return;
            }
        }
    }
}
