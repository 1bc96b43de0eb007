package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;

/** The one output comparison of lint and certify; every expected number below is worked by hand. */
class OutputComparisonTest {
    private static final OutputComparison.Allowance TENTH = (output, expected) -> 0.1;

    @Test
    void aFiniteValuePassesUpToTheAllowanceInclusive() {
        Comparison at = OutputComparison.compare("y", 2.0, 2.5, 0.5);
        assertTrue(at.passed());
        assertEquals(0.5, at.error());
        assertFalse(OutputComparison.compare("y", 2.0, 2.5000001, 0.5).passed());
        assertTrue(OutputComparison.compare("y", -3.0, -3.25, 0.25).passed());
        assertEquals(0.25, OutputComparison.error(-3.0, -3.25));
    }

    @Test
    void nanAndBothInfinitiesNeverPassAndAreInfinitelyOff() {
        for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
            Comparison c = OutputComparison.compare("y", 50.0, bad, Double.MAX_VALUE);
            assertFalse(c.passed(), "value " + bad);
            assertFalse(c.missing());
            assertEquals(Double.POSITIVE_INFINITY, c.error(), "value " + bad);
            assertFalse(OutputComparison.passes(50.0, bad, Double.POSITIVE_INFINITY), "value " + bad);
        }
    }

    @Test
    void aMissingOrNullOutputFailsWithNothingMeasured() {
        Map<String, Double> actual = new HashMap<>();
        actual.put("b", null);
        Map<String, Double> expected = new LinkedHashMap<>();
        expected.put("a", 1.0);
        expected.put("b", 2.0);
        List<Comparison> result = OutputComparison.compareAll(expected, actual, TENTH);
        assertEquals(2, result.size());
        result.forEach(c -> {
            assertTrue(c.missing(), c.output());
            assertFalse(c.passed(), c.output());
            assertTrue(Double.isNaN(c.error()), c.output());
            assertEquals(0.1, c.allowed());
        });
    }

    @Test
    void namesMatchExactlyFirstThenIgnoringCaseAndExtraOutputsAreIgnored() {
        Map<String, Double> actual = new LinkedHashMap<>();
        actual.put("VALVE", 9.0);
        actual.put("Valve", 10.0);
        actual.put("other", 1.0);
        assertEquals(Optional.of(10.0), OutputComparison.lookup(actual, "Valve"));
        assertEquals(Optional.of(9.0), OutputComparison.lookup(Map.of("VALVE", 9.0), "valve"));
        assertEquals(Optional.empty(), OutputComparison.lookup(actual, "power"));
        List<Comparison> result = OutputComparison.compareAll(Map.of("valve", 9.05), Map.of("VALVE", 9.0), TENTH);
        assertEquals(1, result.size());
        assertTrue(result.get(0).passed());
        assertEquals(0.05, result.get(0).error(), 1e-15);
    }

    @Test
    void theToleranceClassesAllowWhatTheyDocument() {
        // exact: 1e-9 * max(1, |expected|): 1e-9 at 0.5, 1e-7 at -100
        assertEquals(1e-9, Tolerance.EXACT.allowed(0.5, OptionalDouble.empty()));
        assertEquals(1e-7, Tolerance.EXACT.allowed(-100, OptionalDouble.empty()), 1e-22);
        // continuous: 0.002 * width, here 0.002 * 100 = 0.2
        assertEquals(0.2, Tolerance.CONTINUOUS.allowed(50, OptionalDouble.of(100)), 1e-15);
        assertTrue(Tolerance.CONTINUOUS.compare("y", 50, 50.19, OptionalDouble.of(100)).passed());
        assertEquals(Double.POSITIVE_INFINITY,
                Tolerance.CONTINUOUS.compare("y", 50, Double.NEGATIVE_INFINITY, OptionalDouble.of(100)).error());
        // certify's exact tolerance is the corpus's exact class, not a second spelling of 1e-9
        assertEquals(Tolerance.EXACT.allowed(-100, OptionalDouble.empty()),
                org.fclcert.harness.Tolerances.exact().allowedError("y", -100));
    }
}
