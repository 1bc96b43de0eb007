package org.fclcert.syntax;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.Optional;

/**
 * IEC 61131-3 B.1.2 numeric literals as FCL uses them: decimal integers and reals with an optional
 * sign, digit groups separated by single underscores, and unsigned based integers ({@code 2#1010},
 * {@code 8#17}, {@code 16#FF}). The lexer reads digit groups loosely; this class says precisely what
 * is wrong and computes values.
 */
final class NumberSyntax {
    private NumberSyntax() {
    }

    /** What is wrong with a token the lexer read as a number, or empty if it is a valid literal. */
    static Optional<String> problem(int tokenType, String text) {
        if ((tokenType == FclLexer.INTEGER || tokenType == FclLexer.REAL_LITERAL) && plain(text)) {
            return Optional.empty();    // the usual number: nothing below can go wrong with it
        }
        if (tokenType == FclLexer.BAD_REAL) {
            return Optional.of(badRealProblem(text));
        }
        String unsigned = stripSign(text);
        if (tokenType == FclLexer.BASED_INTEGER) {
            return basedProblem(text, unsigned);
        }
        if (!validDecimalGroups(unsigned)) {
            return Optional.of(underscoreProblem(text));
        }
        // only an exponent or some 300 digits can overflow a double
        boolean mayOverflow = text.length() > 300 || text.indexOf('E') >= 0 || text.indexOf('e') >= 0;
        if (mayOverflow && !Double.isFinite(value(tokenType, text))) {
            return Optional.of("'" + text + "' is too large to be represented as a number");
        }
        return Optional.empty();
    }

    static String badRealProblem(String text) {
        String unsigned = stripSign(text);
        if (unsigned.startsWith(".")) {
            return "'" + text + "' is not a valid real literal: IEC 61131-3 requires a digit before the decimal point"
                    + " (write 0" + unsigned + ")";
        }
        if (unsigned.endsWith(".")) {
            return "'" + text + "' is not a valid real literal: IEC 61131-3 requires a digit after the decimal point"
                    + " (write " + text + "0)";
        }
        return "'" + text + "' is not a valid real literal: a real literal needs a decimal point before the exponent"
                + " (write " + text.replaceFirst("[eE]", ".0E") + ")";
    }

    private static Optional<String> basedProblem(String text, String unsigned) {
        if (!unsigned.equals(text)) {
            return Optional.of("'" + text + "': a based integer literal takes no sign (IEC 61131-3 B.1.2)");
        }
        int hash = unsigned.indexOf('#');
        String base = unsigned.substring(0, hash);
        String digits = unsigned.substring(hash + 1);
        if (!base.equals("2") && !base.equals("8") && !base.equals("16")) {
            return Optional.of("'" + text + "': the base of an integer literal is 2, 8 or 16 (IEC 61131-3 B.1.2)");
        }
        int radix = Integer.parseInt(base);
        for (char c : digits.toCharArray()) {
            if (c != '_' && Character.digit(c, radix) < 0) {
                return Optional.of("'" + text + "': '" + c + "' is not a base-" + radix + " digit");
            }
        }
        if (!validDigits(digits, radix)) {
            return Optional.of(underscoreProblem(text));
        }
        return Optional.empty();
    }

    private static String underscoreProblem(String text) {
        return "'" + text + "' is not a valid numeric literal: '_' may only stand between two digits"
                + " (IEC 61131-3 B.1.2)";
    }

    /** At most 300 characters, no underscore and no exponent: no group to check, nothing to overflow. */
    private static boolean plain(String text) {
        if (text.length() > 300) {
            return false;
        }
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '_' || c == 'e' || c == 'E') {
                return false;
            }
        }
        return true;
    }

    /** Every digit group of a decimal literal (between '.', 'E' and the exponent sign) is digit {['_'] digit}. */
    private static boolean validDecimalGroups(String unsigned) {
        char previous = '.';   // as if a group had just started
        for (int i = 0; i < unsigned.length(); i++) {
            char c = unsigned.charAt(i);
            boolean separator = c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
            if (c == '_' && (previous < '0' || previous > '9')) {
                return false;   // '_' not after a digit: leading or doubled
            }
            if (separator && previous == '_') {
                return false;   // '_' at the end of a group
            }
            previous = c;
        }
        return previous != '_';
    }

    /** digit {['_'] digit}: no leading, trailing or doubled underscore. */
    private static boolean validDigits(String group, int radix) {
        if (group.isEmpty() || group.startsWith("_") || group.endsWith("_") || group.contains("__")) {
            return false;
        }
        for (char c : group.toCharArray()) {
            if (c != '_' && Character.digit(c, radix) < 0) {
                return false;
            }
        }
        return true;
    }

    private static String stripSign(String text) {
        return text.startsWith("+") || text.startsWith("-") ? text.substring(1) : text;
    }

    /** True when the literal is an integer literal (decimal or based), false for a real literal. */
    static boolean integral(int tokenType) {
        return tokenType == FclLexer.INTEGER || tokenType == FclLexer.BASED_INTEGER;
    }

    /**
     * The exact value of an integer token whose double is not exact (only possible beyond 2^53, so
     * only for long digit strings), else null: a double rounds 9223372036854775807 to 2^63.
     */
    static BigInteger wideInteger(int tokenType, String text, double value) {
        if (!integral(tokenType) || text.length() < 16 || !Double.isFinite(value)) {
            return null;
        }
        String clean = text.replace("_", "");
        try {
            BigInteger exact;
            if (tokenType == FclLexer.BASED_INTEGER) {
                int hash = clean.indexOf('#');
                exact = new BigInteger(clean.substring(hash + 1), Integer.parseInt(clean.substring(0, hash)));
            } else {
                exact = new BigInteger(clean.startsWith("+") ? clean.substring(1) : clean);
            }
            return new BigDecimal(value).toBigIntegerExact().equals(exact) ? null : exact;
        } catch (NumberFormatException | ArithmeticException e) {
            return null;
        }
    }

    /** The value of a numeric token; NaN if it cannot be computed (already reported as FCL-S004). */
    static double value(int tokenType, String text) {
        String clean = text.replace("_", "");
        try {
            if (tokenType == FclLexer.BASED_INTEGER) {
                boolean negative = clean.startsWith("-");
                String unsigned = stripSign(clean);
                int hash = unsigned.indexOf('#');
                double v = new BigInteger(unsigned.substring(hash + 1), Integer.parseInt(unsigned.substring(0, hash)))
                        .doubleValue();
                return negative ? -v : v;
            }
            return Double.parseDouble(clean);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
