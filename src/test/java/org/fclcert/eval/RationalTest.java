package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The exact arithmetic under the judging path (docs/semantics.md, point 10). */
class RationalTest {
    private static Rational q(long p, long d) {
        return Rational.of(BigInteger.valueOf(p), BigInteger.valueOf(d));
    }

    @Test
    void decimalReadingRecoversTheWrittenDecimalAndBinaryReadingTheDouble() {
        assertEquals(q(1, 10), Rational.decimal(0.1));
        assertEquals(q(201, 10), Rational.decimal(20.1));
        assertEquals(q(-125, 100_000_000), Rational.decimal(-0.00000125));
        assertEquals(Rational.of(new BigDecimal("1e-300")), Rational.decimal(1e-300));
        // the double nearest to 0.1 is 3602879701896397 / 2^55
        assertEquals(Rational.of(BigInteger.valueOf(3602879701896397L), BigInteger.TWO.pow(55)), Rational.exactly(0.1));
        assertFalse(Rational.decimal(0.1).equals(Rational.exactly(0.1)));
        assertEquals(Rational.exactly(0.5), Rational.decimal(0.5));
    }

    /* 1 + 0.13 − 0.13 is exactly 1 in rationals (0.9999999999999999 in doubles). */
    @Test
    void arithmeticIsExact() {
        Rational a = Rational.decimal(0.13);
        assertEquals(Rational.ONE, Rational.ONE.add(a).subtract(Rational.ONE.multiply(a)));
        assertEquals(q(1, 3), q(1, 6).add(q(1, 6)));
        assertEquals(0, q(2, 4).compareTo(Rational.HALF));
        assertTrue(q(-1, 3).compareTo(q(-1, 4)) < 0);
        assertEquals(q(3, 2), q(1, 2).divide(q(1, 3)));
    }

    @Test
    void toDoubleIsCorrectlyRounded() {
        assertEquals(0.1, q(1, 10).toDouble());
        assertEquals(1.0 / 3, q(1, 3).toDouble());
        assertEquals(9500.0 / 127, q(9500, 127).toDouble());
        assertEquals(20.100000125, Rational.decimal(20.100000125).toDouble());
        assertEquals(-62.5, q(-125, 2).toDouble());
        assertEquals(Double.MIN_VALUE, Rational.exactly(Double.MIN_VALUE).toDouble());
        assertEquals(Double.MAX_VALUE, Rational.exactly(Double.MAX_VALUE).toDouble());
        // decimals near both ends of the double range, a negative fraction, zero (the integer shortcut)
        assertEquals(1.0e308, Rational.decimal(1.0e308).toDouble());
        assertEquals(1.0e-300, Rational.decimal(1.0e-300).toDouble());
        assertEquals(-26.6, q(-133, 5).toDouble());
        assertEquals(0.0, Rational.ZERO.toDouble());
        assertThrows(ArithmeticException.class, () -> q(1, 3).divide(Rational.ZERO));
        // p/q for random longs: the double division of two exactly representable integers is correctly rounded
        Random rnd = new Random(12);
        for (int i = 0; i < 10_000; i++) {
            long p = rnd.nextInt(1 << 30) - (1 << 29);
            long d = 1 + rnd.nextInt(1 << 30);
            assertEquals((double) p / d, q(p, d).toDouble(), () -> p + "/" + d);
        }
    }

    @Test
    void roundingHalfAwayFromZeroIsDecidedExactly() {
        assertEquals(Rational.of(-63), q(-125, 2).roundHalfAwayFromZero());
        assertEquals(Rational.of(63), q(125, 2).roundHalfAwayFromZero());
        assertEquals(Rational.of(-62), Rational.exactly(-62.49999999999999).roundHalfAwayFromZero());
        assertEquals(Rational.of(3), q(5, 2).roundHalfAwayFromZero());
        assertEquals(Rational.of(2), q(249, 100).roundHalfAwayFromZero());
        assertEquals(Rational.ZERO, q(-1, 3).roundHalfAwayFromZero());
    }

    @Test
    void squareRootsAreExactWhenRationalAndSixtyDigitsOtherwise() {
        assertEquals(q(3, 5), q(9, 25).sqrt());
        assertEquals(q(1, 3), q(1, 9).sqrt());   // exact although 1/9 has no finite decimal expansion
        assertEquals(Rational.ZERO, Rational.ZERO.sqrt());
        Rational sqrt2 = Rational.TWO.sqrt();
        assertFalse(sqrt2.multiply(sqrt2).equals(Rational.TWO));   // sqrt 2 is irrational: 60 digits, not exact
        BigDecimal root2 = Rational.TWO.sqrt().toBigDecimal(new java.math.MathContext(70));
        assertEquals(0, root2.subtract(new BigDecimal("1.41421356237309504880168872420969807856967187537694807317667973799"))
                .abs().compareTo(new BigDecimal("1e-58")) < 0 ? 0 : 1);
    }
}
