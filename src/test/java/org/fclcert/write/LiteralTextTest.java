package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.regex.Pattern;
import org.fclcert.model.Literal;
import org.fclcert.model.SourceLocation;
import org.junit.jupiter.api.Test;

class LiteralTextTest {
    /** IEC 61131-3 B.1.2.1 real literal without '_' (digits on both sides of '.', optional exponent). */
    private static final Pattern REAL = Pattern.compile("-?[0-9]+\\.[0-9]+(E-?[0-9]+)?");

    private static String real(double v) {
        return LiteralText.of(new Literal(v, false, SourceLocation.UNKNOWN));
    }

    private static String integer(double v) {
        return LiteralText.of(new Literal(v, true, SourceLocation.UNKNOWN));
    }

    @Test
    void integerLiteralsAreWrittenWithoutPoint() {
        assertEquals("5", integer(5));
        assertEquals("-100", integer(-100));
        assertEquals("0", integer(0));
        // 1e20 is exactly representable; an integer literal keeps all its digits
        assertEquals("100000000000000000000", integer(1e20));
    }

    /*
     * Issue 18: integer literals beyond 2^53 keep their digits through read and write. As doubles,
     * 9223372036854775807 is 2^63 = ...808 and 9007199254740993 is 2^53 = ...992.
     */
    @Test
    void wideIntegerLiteralsAreWrittenAsRead() {
        String text = """
                FUNCTION_BLOCK w
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                VAR a : LINT := 9223372036854775807; b : LINT := 9007199254740993; c : ULINT := 16#FFFF_FFFF_FFFF_FFFF;
                  d : LINT := -9007199254740993; END_VAR
                FUZZIFY x TERM t := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y TERM one := 1; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACCU : MAX; RULE 1 : IF x IS t THEN y IS one; END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        org.fclcert.syntax.ReadResult read = new org.fclcert.syntax.StrictReader().read("w.fcl", text);
        String written = new CanonicalWriter().write(read.program().orElseThrow());
        assertTrue(written.contains(":= 9223372036854775807;"), written);
        assertTrue(written.contains(":= 9007199254740993;"), written);
        assertTrue(written.contains(":= 18446744073709551615;"), written);
        assertTrue(written.contains(":= -9007199254740993;"), written);
        String again = new CanonicalWriter().write(new org.fclcert.syntax.StrictReader().read("w2.fcl", written)
                .program().orElseThrow());
        assertEquals(written, again);
        // 2^53 + 2 is a double: nothing extra is kept
        assertEquals("9007199254740994", integer(9007199254740994.0));
    }

    @Test
    void integralFlagOnAFractionFallsBackToReal() {
        assertEquals("2.5", integer(2.5));
    }

    @Test
    void realLiteralsInPlainRange() {
        assertEquals("0.8", real(0.8));
        assertEquals("100.0", real(100));
        assertEquals("-17.5", real(-17.5));
        assertEquals("0.001", real(0.001));
        assertEquals("1234567.0", real(1234567));
        assertEquals("0.0", real(0));
        assertEquals("-0.0", real(-0.0));
    }

    @Test
    void realLiteralsOutsidePlainRangeUseExponent() {
        assertEquals("1.0E-5", real(1e-5));
        assertEquals("1.0E7", real(1e7));
        assertEquals("-2.5E-4", real(-2.5e-4));
    }

    @Test
    void realDigitsAreTheShortestThatRoundTrip() {
        // Expected spellings are Python's repr() of the same doubles (shortest round-trip digits):
        // repr(0.1 + 0.2) = '0.30000000000000004', repr(2/3) = '0.6666666666666666',
        // repr(2**-44) = '5.684341886080802e-14' (Java 17's Double.toString gives 17 digits here),
        // repr(5e-324) = '5e-324' (Java 17 gives 4.9E-324), repr(sys.float_info.max) = '1.7976931348623157e+308'.
        assertEquals("0.30000000000000004", real(0.1 + 0.2));
        assertEquals("0.6666666666666666", real(2.0 / 3));
        assertEquals("5.684341886080802E-14", real(Math.pow(2, -44)));
        assertEquals("5.0E-324", real(Double.MIN_VALUE));
        assertEquals("1.7976931348623157E308", real(Double.MAX_VALUE));
    }

    @Test
    void nonFiniteValuesHaveNoSpelling() {
        assertThrows(IllegalArgumentException.class, () -> real(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> integer(Double.POSITIVE_INFINITY));
    }

    @Test
    void randomDoublesRoundTripWithNoMoreDigitsThanJava() {
        Random random = new Random(61131_7);
        for (int i = 0; i < 5_000; i++) {
            double v = Double.longBitsToDouble(random.nextLong());
            if (!Double.isFinite(v)) {
                continue;
            }
            String text = real(v);
            assertTrue(REAL.matcher(text).matches(), text);
            assertEquals(v, Double.parseDouble(text), text);
            assertTrue(significantDigits(text) <= significantDigits(Double.toString(v)), text + " vs " + v);
        }
    }

    @Test
    void shortestMatchesAnExhaustiveSearchOverTheExactValue() {
        Random random = new Random(2000);
        for (int i = 0; i < 1_000; i++) {
            // half arbitrary bit patterns, half values of everyday magnitude
            double v = i % 2 == 0 ? Math.abs(Double.longBitsToDouble(random.nextLong()))
                    : random.nextDouble() * Math.pow(10, random.nextInt(10) - 5);
            if (!Double.isFinite(v) || v == 0) {
                continue;
            }
            assertEquals(exhaustivePrecision(v), LiteralText.shortest(v).precision(), Double.toString(v));
        }
    }

    /** Independent method: the first precision at which a rounding of the exact binary value round-trips. */
    private static int exhaustivePrecision(double v) {
        java.math.BigDecimal exact = new java.math.BigDecimal(v);
        for (int precision = 1; precision <= 17; precision++) {
            for (java.math.RoundingMode mode : java.math.RoundingMode.values()) {
                if (mode == java.math.RoundingMode.UNNECESSARY) {
                    continue;
                }
                java.math.BigDecimal c = exact.round(new java.math.MathContext(precision, mode));
                if (Double.parseDouble(c.toString()) == v) {
                    return precision;
                }
            }
        }
        throw new AssertionError("17 digits always round-trip");
    }

    private static int significantDigits(String text) {
        String mantissa = text.replaceFirst("[eE].*", "").replace("-", "").replace(".", "");
        return mantissa.replaceFirst("^0+", "").replaceFirst("0+$", "").length();
    }
}
