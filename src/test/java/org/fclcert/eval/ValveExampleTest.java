package org.fclcert.eval;

import static org.fclcert.eval.Fcl.and;
import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.num;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefuzzificationMethod;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The FCL example of 5.3 (figure 7), built as a model, at several operating points. */
class ValveExampleTest {

    static Fcl.Block valve() {
        return Fcl.block("Fuzzy_FB").input("temp").input("pressure").output("valve")
                .fuzzify("temp", Fcl.term("cold", pts(3, 1, 27, 0)), Fcl.term("hot", pts(3, 0, 27, 1)))
                .fuzzify("pressure", Fcl.term("low", pts(55, 1, 95, 0)), Fcl.term("high", pts(55, 0, 95, 1)))
                .defuzzify(Fcl.defuzzify("valve", DefuzzificationMethod.COGS)
                        .term("drainage", single(-100)).term("closed", single(0)).term("inlet", single(100))
                        .defaultValue(0))
                .rules(Fcl.ruleBlock("No1").and(AndAlgorithm.MIN)
                        .rule(and(is("temp", "cold"), is("pressure", "low")), then("valve", "inlet"))
                        .rule(and(is("temp", "cold"), is("pressure", "high")), then("valve", "closed", num(0.8)))
                        .rule(and(is("temp", "hot"), is("pressure", "low")), then("valve", "closed"))
                        .rule(and(is("temp", "hot"), is("pressure", "high")), then("valve", "drainage")));
    }

    /*
     * temp=5: cold=(27-5)/24=11/12, hot=1/12; pressure=60: low=(95-60)/40=7/8, high=1/8.
     * R1 inlet=min(11/12,7/8)=7/8; R2 closed=0.8*min(11/12,1/8)=0.1; R3 closed=min(1/12,7/8)=1/12;
     * ACCU MAX per term: closed=max(0.1,1/12)=0.1; R4 drainage=min(1/12,1/8)=1/12.
     * CoGS=(100*7/8 + 0*0.1 - 100/12)/(7/8+0.1+1/12) = (950/12)/(12.7/12) = 9500/127.
     *
     * temp=5, pressure=90: low=1/8, high=7/8. inlet=1/8; closed=max(0.8*7/8, 1/12)=0.7; drainage=1/12.
     * CoGS=(100/8-100/12)/(1/8+7/10+1/12) = (25/6)/(109/120) = 500/109.
     *
     * temp=15, pressure=75: all degrees 1/2. inlet=1/2, closed=max(0.4,0.5)=1/2, drainage=1/2 -> 0.
     * temp=27, pressure=95: only hot=1, high=1 -> drainage=1 -> -100.
     * temp=3, pressure=55: only cold=1, low=1 -> inlet=1 -> 100.
     * temp=0, pressure=100: beyond the outer points the outer degrees hold: cold=1, high=1 ->
     *   closed=0.8 only -> 0.
     * temp=20, pressure=100: cold=7/24, hot=17/24, high=1: closed=0.8*7/24=7/30, drainage=17/24
     *   -> -100*(17/24)/(7/30+17/24) = -(1700/24)/(113/120) = -8500/113.
     */
    @ParameterizedTest(name = "temp={0} pressure={1} -> {2}")
    @CsvSource({
        "5, 60, 74.80314960629921",
        "5, 90, 4.587155963302752",
        "15, 75, 0",
        "27, 95, -100",
        "3, 55, 100",
        "0, 100, 0",
        "20, 100, -75.22123893805310"})
    void operatingPoints(double temp, double pressure, double expected) throws EvaluationException {
        FunctionBlockInstance fb = valve().instance();
        fb.set("temp", temp);
        fb.set("pressure", pressure);
        fb.evaluate();
        assertEquals(expected, fb.get("valve"), 1e-12 * Math.max(1, Math.abs(expected)));
    }

    @Test
    void exactFractionAtTheStandardsOperatingPoint() throws EvaluationException {
        FunctionBlockInstance fb = valve().instance();
        fb.set("TEMP", 5);
        fb.set("Pressure", 60);
        fb.evaluate();
        assertEquals(9500.0 / 127.0, fb.outputs().get("valve"), 1e-13);
    }

    /** The trace shows every stage with the numbers derived above for temp=5, pressure=60. */
    @Test
    void traceRecordsEveryStage() throws EvaluationException {
        FunctionBlockInstance fb = valve().instance();
        fb.set("temp", 5);
        fb.set("pressure", 60);
        Trace trace = new Trace();
        fb.evaluate(trace);
        assertEquals(11.0 / 12, trace.termDegree("temp", "cold").orElseThrow(), 1e-15);
        assertEquals(1.0 / 12, trace.termDegree("temp", "hot").orElseThrow(), 1e-15);
        assertEquals(7.0 / 8, trace.termDegree("pressure", "low").orElseThrow(), 1e-15);
        assertEquals(1.0 / 8, trace.termDegree("pressure", "high").orElseThrow(), 1e-15);
        assertEquals(4, trace.ruleDegrees().size());
        assertEquals(1.0 / 8, trace.ruleDegrees().get(1).degree(), 1e-15);
        assertEquals(0.1, trace.activations().get(1).activatedDegree(), 1e-15);
        Trace.AccumulatedSet set = trace.accumulatedSet("valve").orElseThrow();
        assertEquals(true, set.singletons());
        assertEquals(-100, set.breakpoints().get(0).u());
        assertEquals(1.0 / 12, set.breakpoints().get(0).degree(), 1e-15);
        assertEquals(0.1, set.breakpoints().get(1).degree(), 1e-15);
        assertEquals(7.0 / 8, set.breakpoints().get(2).degree(), 1e-15);
        Trace.Result r = trace.result("valve").orElseThrow();
        assertEquals(Trace.Outcome.DEFUZZIFIED, r.outcome());
        assertEquals(9500.0 / 127, r.value(), 1e-12);
    }
}
