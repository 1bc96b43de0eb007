package org.fclcert.eval;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.math.MathContext;
import java.math.RoundingMode;

/**
 * An exact rational number p/q on {@link BigInteger} (q &gt; 0, gcd(p, q) = 1), the arithmetic of the exact
 * judging path ({@link ExactInstance}). Every value the evaluator derives from literals and inputs with
 * +, −, ·, / is exact here, so every comparison (a clip crossing, a tie, a degree of 0 or 1, a .5 of an integer
 * output) is decided as the mathematics decides it.
 */
final class Rational implements Comparable<Rational> {
    static final Rational ZERO = new Rational(BigInteger.ZERO, BigInteger.ONE);
    static final Rational ONE = new Rational(BigInteger.ONE, BigInteger.ONE);
    static final Rational HALF = new Rational(BigInteger.ONE, BigInteger.TWO);
    static final Rational TWO = new Rational(BigInteger.TWO, BigInteger.ONE);

    /** Digits of the square roots (hedges somewhat/seldom, CoA's quadratic when its root is irrational). */
    static final MathContext SQRT_CONTEXT = new MathContext(60, RoundingMode.HALF_EVEN);

    final BigInteger num;
    final BigInteger den;

    private Rational(BigInteger num, BigInteger den) {
        this.num = num;
        this.den = den;
    }

    static Rational of(BigInteger num, BigInteger den) {
        if (den.signum() == 0) {
            throw new ArithmeticException("division by zero");
        }
        if (den.signum() < 0) {
            num = num.negate();
            den = den.negate();
        }
        if (num.signum() == 0) {
            return ZERO;
        }
        if (!den.equals(BigInteger.ONE)) {
            BigInteger g = num.gcd(den);
            if (!g.equals(BigInteger.ONE)) {
                num = num.divide(g);
                den = den.divide(g);
            }
        }
        return new Rational(num, den);
    }

    static Rational of(long n) {
        return n == 0 ? ZERO : n == 1 ? ONE : new Rational(BigInteger.valueOf(n), BigInteger.ONE);
    }

    static Rational of(BigDecimal d) {
        BigInteger unscaled = d.unscaledValue();
        int scale = d.scale();
        return scale <= 0 ? of(unscaled.multiply(BigInteger.TEN.pow(-scale)), BigInteger.ONE)
                : of(unscaled, BigInteger.TEN.pow(scale));
    }

    /** The exact binary value of a finite double. */
    static Rational exactly(double d) {
        if (d == 0) {
            return ZERO;
        }
        if (d == 1) {
            return ONE;
        }
        return of(new BigDecimal(d));
    }

    /**
     * The shortest decimal that reads back as {@code d} (round to nearest), as an exact rational: for a literal
     * or an input written with at most 15 significant digits, exactly the decimal that was written
     * (docs/semantics.md, point 10).
     */
    static Rational decimal(double d) {
        return of(shortestDecimal(d));
    }

    static BigDecimal shortestDecimal(double d) {
        if (d == 0) {
            return BigDecimal.ZERO;
        }
        BigDecimal exact = new BigDecimal(d);
        for (int digits = 1; digits < 17; digits++) {
            BigDecimal r = exact.round(new MathContext(digits, RoundingMode.HALF_EVEN));
            if (r.doubleValue() == d) {
                return r.stripTrailingZeros();
            }
        }
        return exact.round(new MathContext(17, RoundingMode.HALF_EVEN)).stripTrailingZeros();
    }

    int signum() {
        return num.signum();
    }

    boolean isZero() {
        return num.signum() == 0;
    }

    Rational add(Rational o) {
        if (o.num.signum() == 0) {
            return this;
        }
        if (num.signum() == 0) {
            return o;
        }
        if (den.equals(o.den)) {
            return of(num.add(o.num), den);
        }
        return of(num.multiply(o.den).add(o.num.multiply(den)), den.multiply(o.den));
    }

    Rational subtract(Rational o) {
        if (o.num.signum() == 0) {
            return this;
        }
        return add(o.negate());
    }

    Rational multiply(Rational o) {
        if (num.signum() == 0 || o.num.signum() == 0) {
            return ZERO;
        }
        if (this == ONE) {
            return o;
        }
        if (o == ONE) {
            return this;
        }
        return of(num.multiply(o.num), den.multiply(o.den));
    }

    /** This divided by o; o = 0 throws {@link ArithmeticException} ({@link #of(BigInteger, BigInteger)} refuses den 0). */
    Rational divide(Rational o) {
        return of(num.multiply(o.den), den.multiply(o.num));
    }

    Rational negate() {
        return num.signum() == 0 ? this : new Rational(num.negate(), den);
    }

    Rational abs() {
        return num.signum() < 0 ? negate() : this;
    }

    Rational min(Rational o) {
        return compareTo(o) <= 0 ? this : o;
    }

    Rational max(Rational o) {
        return compareTo(o) >= 0 ? this : o;
    }

    /** Clamped to [0, 1]. */
    Rational clamp01() {
        return signum() <= 0 ? ZERO : compareTo(ONE) >= 0 ? ONE : this;
    }

    @Override
    public int compareTo(Rational o) {
        if (den.equals(o.den)) {
            return num.compareTo(o.num);
        }
        int s = num.signum() - o.num.signum();
        if (s != 0) {
            return s > 0 ? 1 : -1;
        }
        return num.multiply(o.den).compareTo(o.num.multiply(den));
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Rational r && num.equals(r.num) && den.equals(r.den);
    }

    @Override
    public int hashCode() {
        return 31 * num.hashCode() + den.hashCode();
    }

    /** Rounded half away from zero to an integer (IEC 61131-3 conversion, semantics point 8), decided exactly. */
    Rational roundHalfAwayFromZero() {
        if (den.equals(BigInteger.ONE)) {
            return this;
        }
        BigInteger twice = num.abs().shiftLeft(1).add(den);   // floor((2|p| + q) / 2q) = floor(|p|/q + 1/2)
        BigInteger r = twice.divide(den.shiftLeft(1));
        return of(num.signum() < 0 ? r.negate() : r, BigInteger.ONE);
    }

    /** The nearest double (ties to even), correctly rounded. */
    double toDouble() {
        if (den.equals(BigInteger.ONE) && num.bitLength() < 53) {   // integers, zero among them (its den is 1)
            return num.longValue();
        }
        BigInteger p = num.abs();
        // shift so that the quotient has at least 66 significant bits, then add a sticky bit for the remainder
        int shift = 66 - (p.bitLength() - den.bitLength());
        BigInteger[] qr = shift >= 0 ? p.shiftLeft(shift).divideAndRemainder(den)
                : p.divideAndRemainder(den.shiftLeft(-shift));
        BigInteger q = qr[0];
        if (qr[1].signum() != 0) {
            q = q.shiftLeft(1).or(BigInteger.ONE);
            shift++;
        }
        double v = scaledToDouble(q, -shift);
        return num.signum() < 0 ? -v : v;
    }

    /** q · 2^exp correctly rounded, q having at least 66 bits of which the last is sticky. */
    private static double scaledToDouble(BigInteger q, int exp) {
        int bits = q.bitLength();
        int e = bits - 1 + exp;   // the value's binary exponent
        if (e > 1023) {
            return Double.POSITIVE_INFINITY;
        }
        int keep = e >= -1022 ? 53 : Math.max(0, 53 - (-1022 - e));   // subnormals keep fewer bits
        int drop = bits - keep;
        BigInteger kept = q.shiftRight(drop);
        BigInteger rest = q.subtract(kept.shiftLeft(drop));
        BigInteger halfWay = BigInteger.ONE.shiftLeft(drop - 1);
        int c = rest.compareTo(halfWay);
        if (c > 0 || c == 0 && kept.testBit(0)) {
            kept = kept.add(BigInteger.ONE);
        }
        return Math.scalb(kept.doubleValue(), drop + exp);
    }

    BigDecimal toBigDecimal(MathContext mc) {
        return new BigDecimal(num).divide(new BigDecimal(den), mc);
    }

    /**
     * The square root of a non-negative value: exact when numerator and denominator are perfect squares, else
     * to {@link #SQRT_CONTEXT} (60 significant digits).
     */
    Rational sqrt() {
        if (num.signum() < 0) {
            throw new ArithmeticException("square root of a negative number");
        }
        BigInteger rp = num.sqrt();   // 0 for zero, whose den is 1: of(0, 1) below
        BigInteger rq = den.sqrt();
        if (rp.multiply(rp).equals(num) && rq.multiply(rq).equals(den)) {
            return of(rp, rq);
        }
        return of(toBigDecimal(new MathContext(70)).sqrt(SQRT_CONTEXT));
    }

    @Override
    public String toString() {
        return den.equals(BigInteger.ONE) ? num.toString() : num + "/" + den;
    }
}
