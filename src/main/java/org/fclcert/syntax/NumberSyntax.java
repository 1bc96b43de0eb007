package org.fclcert.syntax;

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
        if (tokenType == FclLexer.BAD_REAL) {
            return Optional.of(badRealProblem(text));
        }
        String unsigned = stripSign(text);
        if (tokenType == FclLexer.BASED_INTEGER) {
            return basedProblem(text, unsigned);
        }
        for (String group : unsigned.split("[.eE+-]")) {
            if (!group.isEmpty() && !validDigits(group, 10)) {
                return Optional.of(underscoreProblem(text));
            }
        }
        if (!Double.isFinite(value(tokenType, text))) {
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
