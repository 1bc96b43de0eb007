package org.fclcert.model;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.ToDoubleFunction;

/**
 * An arithmetic expression of variables, the value of a Takagi–Sugeno output term (fuzzylite
 * {@code Linear} and {@code Function}, jFuzzyLogic {@code function}): outside the standard (Open Level,
 * Table 10), whose output terms are constants or fuzzy sets. Evaluated in double arithmetic.
 */
public sealed interface Expression {

    /** The value, each variable's value given by {@code value} (by the name as written). */
    double evaluate(ToDoubleFunction<String> value);

    /** The variables the expression reads, in order of first use. */
    default Set<String> variables() {
        Set<String> out = new LinkedHashSet<>();
        collect(this, out);
        return out;
    }

    private static void collect(Expression e, Set<String> out) {
        if (e instanceof Variable v) {
            out.add(v.name());
        } else if (e instanceof Negate n) {
            collect(n.operand(), out);
        } else if (e instanceof Binary b) {
            collect(b.left(), out);
            collect(b.right(), out);
        } else if (e instanceof Call c) {
            c.arguments().forEach(a -> collect(a, out));
        }
    }

    record Number(double value) implements Expression {
        @Override
        public double evaluate(ToDoubleFunction<String> v) {
            return value;
        }
    }

    record Variable(String name) implements Expression {
        @Override
        public double evaluate(ToDoubleFunction<String> v) {
            return v.applyAsDouble(name);
        }
    }

    record Negate(Expression operand) implements Expression {
        @Override
        public double evaluate(ToDoubleFunction<String> v) {
            return -operand.evaluate(v);
        }
    }

    /** {@code + - * / ^ %}. */
    record Binary(char operator, Expression left, Expression right) implements Expression {
        @Override
        public double evaluate(ToDoubleFunction<String> v) {
            double a = left.evaluate(v);
            double b = right.evaluate(v);
            return switch (operator) {
                case '+' -> a + b;
                case '-' -> a - b;
                case '*' -> a * b;
                case '/' -> a / b;
                case '^' -> Math.pow(a, b);
                case '%' -> a % b;
                default -> throw new IllegalStateException("operator " + operator);
            };
        }
    }

    /** A function of {@link #FUNCTIONS}. */
    record Call(String function, List<Expression> arguments) implements Expression {
        public Call {
            arguments = List.copyOf(arguments);
        }

        @Override
        public double evaluate(ToDoubleFunction<String> v) {
            double a = arguments.get(0).evaluate(v);
            double b = arguments.size() > 1 ? arguments.get(1).evaluate(v) : Double.NaN;
            return switch (function) {
                case "sin" -> Math.sin(a);
                case "cos" -> Math.cos(a);
                case "tan" -> Math.tan(a);
                case "asin" -> Math.asin(a);
                case "acos" -> Math.acos(a);
                case "atan" -> Math.atan(a);
                case "sinh" -> Math.sinh(a);
                case "cosh" -> Math.cosh(a);
                case "tanh" -> Math.tanh(a);
                case "exp" -> Math.exp(a);
                case "log" -> Math.log(a);
                case "log10" -> Math.log10(a);
                case "sqrt" -> Math.sqrt(a);
                case "fabs", "abs" -> Math.abs(a);
                case "ceil" -> Math.ceil(a);
                case "floor" -> Math.floor(a);
                case "pow" -> Math.pow(a, b);
                case "atan2" -> Math.atan2(a, b);
                case "fmod" -> a % b;
                case "min" -> Math.min(a, b);
                case "max" -> Math.max(a, b);
                default -> throw new IllegalStateException("function " + function);
            };
        }
    }

    /** The functions an expression may call, with their argument counts. */
    java.util.Map<String, Integer> FUNCTIONS = java.util.Map.ofEntries(java.util.Map.entry("sin", 1),
            java.util.Map.entry("cos", 1), java.util.Map.entry("tan", 1), java.util.Map.entry("asin", 1),
            java.util.Map.entry("acos", 1), java.util.Map.entry("atan", 1), java.util.Map.entry("sinh", 1),
            java.util.Map.entry("cosh", 1), java.util.Map.entry("tanh", 1), java.util.Map.entry("exp", 1),
            java.util.Map.entry("log", 1), java.util.Map.entry("log10", 1), java.util.Map.entry("sqrt", 1),
            java.util.Map.entry("fabs", 1), java.util.Map.entry("abs", 1), java.util.Map.entry("ceil", 1),
            java.util.Map.entry("floor", 1), java.util.Map.entry("pow", 2), java.util.Map.entry("atan2", 2),
            java.util.Map.entry("fmod", 2), java.util.Map.entry("min", 2), java.util.Map.entry("max", 2));
}
