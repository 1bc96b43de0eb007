package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.fclcert.model.Expression;

/**
 * Reads the formula of a Takagi–Sugeno term ({@code sin(inputX)/inputX}, {@code 2*x + 3*y - 1}): numbers,
 * variables, {@code + - * / ^ %}, unary minus, parentheses and the functions of {@link Expression#FUNCTIONS};
 * the usual priorities, {@code ^} binding right. A mistake is an {@link IllegalArgumentException} whose
 * message names it and whose {@link #position} is its offset in the text.
 */
final class ExpressionParser {
    private final String s;
    private final Set<String> variables;
    private int i;
    int position;

    private ExpressionParser(String text, Set<String> variables) {
        this.s = text;
        this.variables = variables;
    }

    /** The expression; {@code variables} are the names it may read (case as declared, matched in any case). */
    static Expression parse(String text, Set<String> variables) {
        ExpressionParser p = new ExpressionParser(text, variables);
        try {
            Expression e = p.sum();
            p.blanks();
            if (p.i < p.s.length()) {
                throw new IllegalArgumentException("unexpected '" + p.s.charAt(p.i) + "'");
            }
            return e;
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(e.getMessage() + " at column " + (p.i + 1) + " of the formula", e);
        }
    }

    private void blanks() {
        while (i < s.length() && Character.isWhitespace(s.charAt(i))) {
            i++;
        }
    }

    private boolean eat(char c) {
        blanks();
        if (i < s.length() && s.charAt(i) == c) {
            i++;
            return true;
        }
        return false;
    }

    private Expression sum() {
        Expression e = product();
        while (true) {
            if (eat('+')) {
                e = new Expression.Binary('+', e, product());
            } else if (eat('-')) {
                e = new Expression.Binary('-', e, product());
            } else {
                return e;
            }
        }
    }

    private Expression product() {
        Expression e = unary();
        while (true) {
            if (eat('*')) {
                e = new Expression.Binary('*', e, unary());
            } else if (eat('/')) {
                e = new Expression.Binary('/', e, unary());
            } else if (eat('%')) {
                e = new Expression.Binary('%', e, unary());
            } else {
                return e;
            }
        }
    }

    private Expression unary() {
        if (eat('-')) {
            return new Expression.Negate(unary());
        }
        if (eat('+')) {
            return unary();
        }
        Expression base = atom();
        if (eat('^')) {
            return new Expression.Binary('^', base, unary());
        }
        return base;
    }

    private Expression atom() {
        blanks();
        if (eat('(')) {
            Expression e = sum();
            if (!eat(')')) {
                throw new IllegalArgumentException("')' missing");
            }
            return e;
        }
        if (i >= s.length()) {
            throw new IllegalArgumentException("the formula ends too early");
        }
        char c = s.charAt(i);
        if (Character.isDigit(c) || c == '.') {
            int start = i;
            while (i < s.length() && (Character.isDigit(s.charAt(i)) || s.charAt(i) == '.')) {
                i++;
            }
            if (i < s.length() && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
                i++;
                if (i < s.length() && (s.charAt(i) == '+' || s.charAt(i) == '-')) {
                    i++;
                }
                while (i < s.length() && Character.isDigit(s.charAt(i))) {
                    i++;
                }
            }
            try {
                return new Expression.Number(Double.parseDouble(s.substring(start, i)));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + s.substring(start, i) + "' is not a number");
            }
        }
        if (Character.isLetter(c) || c == '_') {
            int start = i;
            while (i < s.length() && (Character.isLetterOrDigit(s.charAt(i)) || s.charAt(i) == '_')) {
                i++;
            }
            String word = s.substring(start, i);
            if (eat('(')) {
                Integer arity = Expression.FUNCTIONS.get(word);
                if (arity == null) {
                    throw new IllegalArgumentException("'" + word + "' is not a function fclcert evaluates");
                }
                List<Expression> args = new ArrayList<>();
                args.add(sum());
                while (eat(',')) {
                    args.add(sum());
                }
                if (!eat(')')) {
                    throw new IllegalArgumentException("')' missing after the arguments of " + word);
                }
                if (args.size() != arity) {
                    throw new IllegalArgumentException(word + " takes " + arity + " argument" + (arity == 1 ? "" : "s"));
                }
                return new Expression.Call(word, args);
            }
            if (word.equals("pi")) {
                return new Expression.Number(Math.PI);
            }
            String declared = variables.stream().filter(v -> v.equalsIgnoreCase(word)).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("'" + word + "' is not a declared variable"));
            return new Expression.Variable(declared);
        }
        throw new IllegalArgumentException("unexpected '" + c + "'");
    }
}
