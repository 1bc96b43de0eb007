package org.fclcert.eval;

import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Hedge;
import org.fclcert.model.OrAlgorithm;

/**
 * The operators of Table 3 (AND/OR pairs, NOT), the activation norms of Table 4 and the accumulations of
 * Table 5 (with the dialects' others), in one place: each in double arithmetic, in exact rational arithmetic,
 * and as the error bound the filtered evaluator carries with a double (docs/semantics.md, "Filtered exact
 * evaluation"). Every evaluator of the package calls these; none has its own copy.
 *
 * <p>An error bound {@code e} of a double {@code x} means: the exact value lies in [x − e, x + e]. A bound of 0
 * means the double <em>is</em> the exact value. An operator whose discrete choice (DPROD's "is one operand 1",
 * NMIN's "x + y &gt; 1", …) the bounds cannot decide returns an infinite bound, which every later decision
 * treats as undecided, so the evaluation is redone exactly.
 */
final class Norms {
    private Norms() {
    }

    /** Unit roundoff of a double (2^-53), times four: a bound on the rounding of a few operations on [0, 2]. */
    static final double R = 4 * 0x1.0p-53;

    // ----------------------------------------------------------------------------------------- doubles

    static double and(AndAlgorithm a, double x, double y) {
        return switch (a) {
            case MIN -> Math.min(x, y);
            case PROD -> x * y;
            case BDIF -> Math.max(0.0, x + y - 1.0);
            case EPROD -> x * y / (2 - (x + y - x * y));
            case HPROD -> x + y == 0 ? 0.0 : x * y / (x + y - x * y);
            case DPROD -> Math.max(x, y) == 1.0 ? Math.min(x, y) : 0.0;
            case NMIN -> x + y > 1.0 ? Math.min(x, y) : 0.0;
        };
    }

    static double or(OrAlgorithm o, double x, double y) {
        return switch (o) {
            case MAX -> Math.max(x, y);
            case ASUM -> x == 1.0 || y == 1.0 ? 1.0 : x + y - x * y;   // exactly 1 when an operand is (NOT of it: 0)
            case BSUM -> Math.min(1.0, x + y);
            case ESUM -> (x + y) / (1 + x * y);
            case HSUM -> x * y == 1.0 ? 1.0 : (x + y - 2 * x * y) / (1 - x * y);
            case DSUM -> Math.min(x, y) == 0.0 ? Math.max(x, y) : 1.0;
            case NMAX -> x + y < 1.0 ? Math.max(x, y) : 1.0;
        };
    }

    /** Table 5 applied to two degrees; NSUM sums here and normalises once all are summed. */
    static double accumulate(AccumulationMethod accu, double a, double b) {
        return switch (accu) {
            case MAX -> Math.max(a, b);
            case BSUM -> Math.min(1.0, a + b);
            case NSUM, SUM -> a + b;
            case PROBOR -> or(OrAlgorithm.ASUM, a, b);
            case ESUM -> or(OrAlgorithm.ESUM, a, b);
            case HSUM -> or(OrAlgorithm.HSUM, a, b);
            case DSUM -> or(OrAlgorithm.DSUM, a, b);
            case NMAX -> or(OrAlgorithm.NMAX, a, b);
        };
    }

    // ----------------------------------------------------------------------------------------- rationals

    static Rational and(AndAlgorithm a, Rational x, Rational y) {
        return switch (a) {
            case MIN -> x.min(y);
            case PROD -> x.multiply(y);
            case BDIF -> x.add(y).subtract(Rational.ONE).max(Rational.ZERO);
            case EPROD -> x.multiply(y).divide(Rational.of(2).subtract(x.add(y).subtract(x.multiply(y))));
            case HPROD -> x.add(y).signum() == 0 ? Rational.ZERO
                    : x.multiply(y).divide(x.add(y).subtract(x.multiply(y)));
            case DPROD -> x.max(y).equals(Rational.ONE) ? x.min(y) : Rational.ZERO;
            case NMIN -> x.add(y).compareTo(Rational.ONE) > 0 ? x.min(y) : Rational.ZERO;
        };
    }

    static Rational or(OrAlgorithm o, Rational x, Rational y) {
        return switch (o) {
            case MAX -> x.max(y);
            case ASUM -> x.add(y).subtract(x.multiply(y));
            case BSUM -> x.add(y).min(Rational.ONE);
            case ESUM -> x.add(y).divide(Rational.ONE.add(x.multiply(y)));
            case HSUM -> x.multiply(y).equals(Rational.ONE) ? Rational.ONE
                    : x.add(y).subtract(Rational.TWO.multiply(x.multiply(y))).divide(Rational.ONE.subtract(x.multiply(y)));
            case DSUM -> x.min(y).signum() == 0 ? x.max(y) : Rational.ONE;
            case NMAX -> x.add(y).compareTo(Rational.ONE) < 0 ? x.max(y) : Rational.ONE;
        };
    }

    static Rational accumulate(AccumulationMethod accu, Rational a, Rational b) {
        return switch (accu) {
            case MAX -> a.max(b);
            case BSUM -> a.add(b).min(Rational.ONE);
            case NSUM, SUM -> a.add(b);
            case PROBOR -> or(OrAlgorithm.ASUM, a, b);
            case ESUM -> or(OrAlgorithm.ESUM, a, b);
            case HSUM -> or(OrAlgorithm.HSUM, a, b);
            case DSUM -> or(OrAlgorithm.DSUM, a, b);
            case NMAX -> or(OrAlgorithm.NMAX, a, b);
        };
    }

    /** The hedges of {@link Hedge#apply} in exact arithmetic (square roots to 60 digits). */
    static Rational hedge(Hedge h, Rational mu) {
        return switch (h) {
            case VERY -> mu.multiply(mu);
            case SOMEWHAT -> mu.sqrt();
            case EXTREMELY -> mu.compareTo(Rational.HALF) <= 0 ? Rational.TWO.multiply(mu).multiply(mu)
                    : Rational.ONE.subtract(Rational.TWO.multiply(Rational.ONE.subtract(mu)).multiply(Rational.ONE.subtract(mu)));
            case SELDOM -> mu.compareTo(Rational.HALF) <= 0 ? mu.multiply(Rational.HALF).sqrt()
                    : Rational.ONE.subtract(Rational.ONE.subtract(mu).multiply(Rational.HALF).sqrt());
            case ANY -> Rational.ONE;
            case NOT -> Rational.ONE.subtract(mu);
        };
    }

    // ----------------------------------------------------------------------------------------- error bounds

    /**
     * The sign of the exact x + y − 1 for two finite doubles: the rounded sum and its rounding error (Knuth's
     * TwoSum, exact in binary floating point) tell it apart even where x + y rounds to 1. NMIN and NMAX choose by
     * it; without it every exact degree summing to 1, and every NMAX with an exact 0 and a 1, left the double path.
     */
    static int sumAgainstOne(double x, double y) {
        double s = x + y;
        double yv = s - x;
        double t = (x - (s - yv)) + (y - yv);
        return s > 1.0 ? 1 : s < 1.0 ? -1 : t > 0 ? 1 : t < 0 ? -1 : 0;
    }

    /** The bound of NOT: 1 − x is exact for x in [1/2, 1] (Sterbenz) and rounds once below. */
    static double notError(double x, double ex) {
        return x > 0 && x < 0.5 ? ex + R : ex;
    }

    /** The bound of {@code and(a, x, y)} = r, from the bounds ex, ey of its operands (degrees in [0, 1]). */
    static double andError(AndAlgorithm a, double x, double ex, double y, double ey, double r) {
        return switch (a) {
            // an exact 0 operand gives an exact 0 (the other operand is a degree, so not below 0)
            case MIN -> minError(x, ex, y, ey);
            case PROD -> productError(x, ex, y, ey, r);
            case BDIF -> clampAtZero(x + y - 1.0, ex + ey + R);
            // Lipschitz constant at most 1 in each operand on [0, 1]^2
            case EPROD, HPROD -> x == 0 && ex == 0 || y == 0 && ey == 0 ? 0 : ex + ey + 4 * R;
            case DPROD -> {
                double m = Math.max(x, y);
                double em = x >= y ? ex : ey;
                yield m == 1.0 && em == 0 ? Math.max(ex, ey) : m + em < 1.0 ? 0 : Double.POSITIVE_INFINITY;
            }
            case NMIN -> {
                if (x == 0 && ex == 0 || y == 0 && ey == 0) {
                    yield 0;            // an exact 0 and a degree never sum past 1: exactly 0
                }
                if (ex == 0 && ey == 0 && !Double.isNaN(x + y)) {
                    // exact operands: the double's choice is exact when it agrees with the exact sum's
                    yield x + y > 1.0 == sumAgainstOne(x, y) > 0 ? 0 : Double.POSITIVE_INFINITY;
                }
                double es = ex + ey + R;
                yield x + y - es > 1.0 ? Math.max(ex, ey) : x + y + es <= 1.0 ? 0 : Double.POSITIVE_INFINITY;
            }
        };
    }

    /** The bound of {@code or(o, x, y)} = r. */
    static double orError(OrAlgorithm o, double x, double ex, double y, double ey, double r) {
        return switch (o) {
            case MAX -> maxError(x, ex, y, ey);
            case ASUM -> x == 1.0 && ex == 0 || y == 1.0 && ey == 0 ? 0 : ex + ey + ex * ey + 2 * R;
            case BSUM -> clampAtOne(x + y, ex + ey + R);
            // Lipschitz constant at most 1 in each operand ((1-y)^2/(1-xy)^2 <= 1 for HSUM)
            case ESUM, HSUM -> ex + ey + 4 * R;
            case DSUM -> {
                double m = Math.min(x, y);
                double em = x <= y ? ex : ey;
                yield m == 0 && em == 0 ? Math.max(ex, ey) : m - em > 0 ? 0 : Double.POSITIVE_INFINITY;
            }
            case NMAX -> {
                // NMAX(0, d) = d and NMAX(1, d) = 1 for every degree d (an accumulation's first contribution)
                if (x == 0 && ex == 0 || y == 0 && ey == 0) {
                    yield x == 0 && ex == 0 ? ey : ex;
                }
                if (x == 1 && ex == 0 || y == 1 && ey == 0) {
                    yield 0;
                }
                if (ex == 0 && ey == 0 && !Double.isNaN(x + y)) {
                    yield x + y < 1.0 == sumAgainstOne(x, y) < 0 ? 0 : Double.POSITIVE_INFINITY;
                }
                double es = ex + ey + R;
                yield x + y + es < 1.0 ? Math.max(ex, ey) : x + y - es >= 1.0 ? 0 : Double.POSITIVE_INFINITY;
            }
        };
    }

    /** The bound of {@code accumulate(accu, a, b)} = r. */
    static double accumulateError(AccumulationMethod accu, double a, double ea, double b, double eb, double r) {
        return switch (accu) {
            case MAX -> maxError(a, ea, b, eb);
            case BSUM -> clampAtOne(a + b, ea + eb + R);
            case NSUM, SUM -> ea + eb + R * Math.abs(r);
            case PROBOR -> orError(OrAlgorithm.ASUM, a, ea, b, eb, r);
            case ESUM -> orError(OrAlgorithm.ESUM, a, ea, b, eb, r);
            case HSUM -> orError(OrAlgorithm.HSUM, a, ea, b, eb, r);
            case DSUM -> orError(OrAlgorithm.DSUM, a, ea, b, eb, r);
            case NMAX -> orError(OrAlgorithm.NMAX, a, ea, b, eb, r);
        };
    }

    /** The bound of a hedge's value r = h(mu), from the bound of mu (square roots: |√a − √b| ≤ min(√e, e/√b)). */
    static double hedgeError(Hedge h, double mu, double e, double r) {
        if (e == Double.POSITIVE_INFINITY) {
            return e;
        }
        return switch (h) {
            case VERY -> e == 0 && (mu == 0 || mu == 1) ? 0 : 2 * mu * e + e * e + R;
            case SOMEWHAT -> sqrtError(mu, e);
            case EXTREMELY -> e == 0 && (mu == 0 || mu == 1) ? 0 : 2 * e + R;
            case SELDOM -> sqrtError(mu <= 0.5 ? mu / 2 : (1 - mu) / 2, e / 2) + R;
            case ANY -> 0;
            case NOT -> notError(mu, e);
        };
    }

    private static double sqrtError(double a, double e) {
        if (e == 0 && (a == 0 || a == 1)) {
            return 0;
        }
        double propagated = a > 0 ? Math.min(Math.sqrt(e), e / Math.sqrt(a)) : Math.sqrt(e);
        return propagated + 1e-58 + R;      // the exact path's square root carries 60 digits
    }

    /** The bound of min(x, y) of two degrees: 0 with an exact 0 operand, else the smaller operand's when certain. */
    static double minError(double x, double ex, double y, double ey) {
        return x == 0 && ex == 0 || y == 0 && ey == 0 ? 0
                : x + ex <= y - ey ? ex : y + ey <= x - ex ? ey : Math.max(ex, ey);
    }

    /** The bound of max(x, y): the larger operand's when it is certainly the larger, else the larger bound. */
    static double maxError(double x, double ex, double y, double ey) {
        return x - ex >= y + ey ? ex : y - ey >= x + ex ? ey : Math.max(ex, ey);
    }

    /** The bound of x·y = r; a product that underflows gets the smallest normal double as its bound. */
    static double productError(double x, double ex, double y, double ey, double r) {
        if (x == 0 && ex == 0 || y == 0 && ey == 0) {
            return 0;
        }
        double e = Math.abs(x) * ey + Math.abs(y) * ex + ex * ey + R * Math.abs(r);
        return Math.abs(r) < Double.MIN_NORMAL && x != 0 && y != 0 ? e + Double.MIN_NORMAL : e;
    }

    /** The bound of max(0, z) from the bound of z: 0 when z is certainly not positive. */
    static double clampAtZero(double z, double ez) {
        return z + ez <= 0 ? 0 : ez;
    }

    /** The bound of min(1, z) from the bound of z: 0 when z is certainly at least 1. */
    static double clampAtOne(double z, double ez) {
        return z - ez >= 1.0 ? 0 : ez;
    }
}
