package org.fclcert.corpus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fclcert.model.DataType;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Range;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;
import org.junit.jupiter.api.Test;

class ToleranceTest {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;
    private static final OptionalDouble NO_WIDTH = OptionalDouble.empty();

    @Test
    void exactIsAbsoluteBelowOneAndRelativeAbove() {
        // below |expected| = 1 the bound is 1e-9 absolute
        assertTrue(Tolerance.EXACT.compare("y", 0.0, 1e-9, NO_WIDTH).passed());
        assertFalse(Tolerance.EXACT.compare("y", 0.0, 1.1e-9, NO_WIDTH).passed());
        assertTrue(Tolerance.EXACT.compare("y", 0.5, 0.5 - 0.9e-9, NO_WIDTH).passed());
        assertFalse(Tolerance.EXACT.compare("y", 0.5, 0.5 - 1.1e-9, NO_WIDTH).passed());
        // 74.8...: allowed 74.8e-9; 5.46 off (per-rule CoGS, 69.343) fails, 7e-8 off passes
        assertTrue(Tolerance.EXACT.compare("valve", 74.80314960629921, 74.80314960629921 + 7e-8, NO_WIDTH).passed());
        assertFalse(Tolerance.EXACT.compare("valve", 74.80314960629921, 74.80314960629921 + 8e-8, NO_WIDTH).passed());
        assertFalse(Tolerance.EXACT.compare("valve", 74.80314960629921, 69.343, NO_WIDTH).passed());
        assertEquals(-1e6 * 1e-9, -Tolerance.EXACT.allowed(-1e6, NO_WIDTH), 1e-18);
    }

    @Test
    void exactIgnoresAnyWidth() {
        assertFalse(Tolerance.EXACT.compare("y", 10, 10.01, OptionalDouble.of(100)).passed());
    }

    @Test
    void continuousAllowsTwoThousandthsOfTheWidth() {
        OptionalDouble width = OptionalDouble.of(100);   // RANGE (0 .. 100): allowed 0.2
        Comparison inside = Tolerance.CONTINUOUS.compare("y", 50, 50.19, width);
        assertTrue(inside.passed());
        assertEquals(0.19, inside.error(), 1e-12);
        assertEquals(0.2, inside.allowed(), 1e-15);
        assertTrue(Tolerance.CONTINUOUS.compare("y", 50, 49.81, width).passed());
        assertFalse(Tolerance.CONTINUOUS.compare("y", 50, 50.21, width).passed());
        // one sampling step of a 100-sample LM/RM is 1.0 here: five times the allowance
        assertFalse(Tolerance.CONTINUOUS.compare("y", 50, 51, width).passed());
    }

    @Test
    void continuousWithoutWidthIsExact() {
        assertFalse(Tolerance.CONTINUOUS.compare("y", 50, 50.001, NO_WIDTH).passed());
        assertTrue(Tolerance.CONTINUOUS.compare("y", 50, 50 + 4e-8, NO_WIDTH).passed());
        // a tiny width never makes the continuous class stricter than the exact one
        assertEquals(1e-9 * 50, Tolerance.CONTINUOUS.allowed(50, OptionalDouble.of(1e-9)), 1e-20);
    }

    @Test
    void nanAndInfinityNeverPass() {
        Comparison nan = Tolerance.CONTINUOUS.compare("y", 0, Double.NaN, OptionalDouble.of(1e9));
        assertFalse(nan.passed());
        assertEquals(Double.POSITIVE_INFINITY, nan.error(), "one rule with certify: a non-finite value is infinitely off");
        assertFalse(Tolerance.CONTINUOUS.compare("y", 0, Double.POSITIVE_INFINITY, OptionalDouble.of(1e300)).passed());
    }

    @Test
    void compareAllMatchesNamesCaseInsensitivelyAndFailsMissingOutputs() {
        Map<String, Double> expected = new LinkedHashMap<>();
        expected.put("Valve", 10.0);
        expected.put("power", 2.0);
        List<Comparison> result = Tolerance.EXACT.compareAll(expected, Map.of("VALVE", 10.0, "other", 1.0),
                OutputScales.none());
        assertEquals(2, result.size());
        assertTrue(result.get(0).passed());
        assertEquals("power", result.get(1).output());
        assertFalse(result.get(1).passed());
        assertTrue(Double.isNaN(result.get(1).actual()));
        assertTrue(result.get(1).missing());
        assertFalse(result.get(0).missing());
    }

    @Test
    void widthsComeFromRangeElseTermSpanElseNone() {
        FunctionBlock fb = new FunctionBlock("f",
                List.of(out("ranged"), out("spanned"), out("singletons"), out("bare"), out("variablePoints")),
                List.of(),
                List.of(defuzzify("ranged", Optional.of(new Range(Literal.of(-10), Literal.of(30), AT)),
                                points(0, 5, 10)),
                        defuzzify("spanned", Optional.empty(), points(-2, 1, 4), points(4, 6, 7)),
                        defuzzify("singletons", Optional.empty(),
                                new Term("a", new MembershipFunction.Singleton(Literal.of(100)), AT)),
                        defuzzify("variablePoints", Optional.empty(), new Term("v", new MembershipFunction.Points(
                                List.of(new Point(new VariableRef("p", AT), Literal.of(0), AT),
                                        new Point(Literal.of(3), Literal.of(1), AT))), AT))),
                List.of(), List.of(), AT);
        OutputScales scales = OutputScales.of(fb);
        assertEquals(OptionalDouble.of(40), scales.width("RANGED"));        // 30 - (-10)
        assertEquals(OptionalDouble.of(9), scales.width("spanned"));        // 7 - (-2)
        assertEquals(NO_WIDTH, scales.width("singletons"));
        assertEquals(NO_WIDTH, scales.width("bare"));                       // no DEFUZZIFY block
        assertEquals(NO_WIDTH, scales.width("variablePoints"));             // one constant x only: span 0
    }

    private static Variable out(String name) {
        return new Variable(name, VariableKind.OUTPUT, DataType.REAL, Optional.empty(), AT);
    }

    private static Term points(double a, double b, double c) {
        return new Term("t" + a, new MembershipFunction.Points(List.of(
                new Point(Literal.of(a), Literal.of(0), AT),
                new Point(Literal.of(b), Literal.of(1), AT),
                new Point(Literal.of(c), Literal.of(0), AT))), AT);
    }

    private static Defuzzification defuzzify(String name, Optional<Range> range, Term... terms) {
        return new Defuzzification(name, range, List.of(terms), Optional.empty(), Optional.empty(), AT);
    }
}
