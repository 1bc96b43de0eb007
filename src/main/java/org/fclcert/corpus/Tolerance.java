package org.fclcert.corpus;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalDouble;

/**
 * How close an implementation's output must be to the expected value (see {@code conformance/README.md}).
 *
 * <ul>
 *   <li>{@link #EXACT}: |error| &le; 1e-9 &middot; max(1, |expected|) &mdash; relative for large values,
 *       absolute near zero. For CoGS and everything computed without integration.</li>
 *   <li>{@link #CONTINUOUS}: |error| &le; 0.002 &middot; width of the output's scale, for outputs defuzzified
 *       by CoG, CoA, LM or RM. The width is that of the output's RANGE, or without RANGE the span of its
 *       terms' constant abscissae ({@link OutputScales}). An output with no such width (singleton terms, a
 *       bare variable conclusion) is compared as {@link #EXACT} even in a continuous case. The allowance is
 *       never smaller than the exact one.</li>
 * </ul>
 *
 * <p>Why 0.002: an implementation integrating CoG with about 1000 samples is typically within 1e-3 of the
 * width (usually far better), so it passes; one that is a whole sampling step off on LM or RM with 100
 * samples is 0.01 of the width off, so it fails.
 */
public enum Tolerance {
    EXACT,
    CONTINUOUS;

    /** The relative (and, below magnitude 1, absolute) bound of the exact class. */
    public static final double EXACT_RELATIVE = 1e-9;

    /** The fraction of the output's width allowed in the continuous class. */
    public static final double WIDTH_FRACTION = 0.002;

    /** Lower-case word used in case files ({@code exact}, {@code continuous}). */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static Tolerance byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT));
    }

    /**
     * The largest error allowed for one output.
     *
     * @param expected the expected value
     * @param width    the output's scale width ({@link OutputScales#width}); empty = compare exactly
     */
    public double allowed(double expected, OptionalDouble width) {
        double exact = EXACT_RELATIVE * Math.max(1.0, Math.abs(expected));
        if (this == EXACT || width.isEmpty()) {
            return exact;
        }
        return Math.max(exact, WIDTH_FRACTION * width.getAsDouble());
    }

    /** Compares one output by {@link OutputComparison}'s rule: a NaN or infinite actual value never passes. */
    public Comparison compare(String output, double expected, double actual, OptionalDouble width) {
        return OutputComparison.compare(output, expected, actual, allowed(expected, width));
    }

    /**
     * Compares every expected output of one step with what was computed ({@link OutputComparison#compareAll}:
     * names matched case-insensitively, a missing expected output fails, extra outputs are ignored).
     */
    public List<Comparison> compareAll(Map<String, Double> expected, Map<String, Double> actual, OutputScales scales) {
        return OutputComparison.compareAll(expected, actual, allowance(scales));
    }

    /** This class's allowance with one program's output widths. */
    public OutputComparison.Allowance allowance(OutputScales scales) {
        return (output, expected) -> allowed(expected, scales.width(output));
    }
}
