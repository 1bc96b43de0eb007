package org.fclcert.eval;

import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.not;
import static org.fclcert.eval.Fcl.num;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;
import static org.fclcert.eval.Fcl.thenVar;
import static org.fclcert.eval.Fcl.v;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DataType;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.VariableKind;
import org.junit.jupiter.api.Test;

/** Semantics points 6 (DEFAULT, NC), 7 (bare variable conclusions, block order, state), 8 (types). */
class StateAndConclusionsTest {
    private static final MembershipFunction IDENTITY = pts(0, 0, 1, 1);

    /**
     * Output y (singletons lo=0, hi=100) concluded by "p IS deg THEN y IS hi" and
     * "q IS deg THEN y IS lo"; initial value of y 7.
     */
    private static Fcl.Block ncProgram(Fcl.Out out) {
        return Fcl.block("fb").input("p").input("q").variable("y", VariableKind.OUTPUT, DataType.REAL, 7.0)
                .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                .defuzzify(out)
                .rules(Fcl.ruleBlock("r").rule(is("p", "deg"), then("y", "hi"))
                        .rule(is("q", "deg"), then("y", "lo")));
    }

    private static double step(FunctionBlockInstance fb, double p, double q, Trace trace) throws EvaluationException {
        fb.set("p", p);
        fb.set("q", q);
        fb.evaluate(trace);
        return fb.get("y");
    }

    /*
     * NC over several steps on one instance: step 1 nothing fires -> the declared initial value 7;
     * step 2 p=0.5 -> only hi fires -> 100; step 3 nothing fires -> still 100; step 4 p=0.2, q=0.2
     * -> (0.2*100)/(0.4) = 50; step 5 nothing -> 50; reset -> 7 again.
     */
    @Test
    void noChangeKeepsThePreviousValueAcrossEvaluations() throws EvaluationException {
        FunctionBlockInstance fb = ncProgram(Fcl.defuzzify("y", DefuzzificationMethod.COGS)
                .term("lo", single(0)).term("hi", single(100)).noChange()).instance();
        Trace trace = new Trace();
        assertEquals(7.0, step(fb, 0, 0, trace));
        assertEquals(Trace.Outcome.NO_CHANGE, trace.result("y").orElseThrow().outcome());
        assertEquals(100.0, step(fb, 0.5, 0, trace));
        assertEquals(100.0, step(fb, 0, 0, trace));
        assertEquals(50.0, step(fb, 0.2, 0.2, trace), 1e-12);
        assertEquals(50.0, step(fb, 0, 0, trace), 1e-12);
        fb.reset();
        assertEquals(7.0, fb.get("y"));
        assertEquals(7.0, step(fb, 0, 0, trace));
    }

    /** Two instances of one loaded program keep separate state. */
    @Test
    void instancesAreIndependent() throws EvaluationException {
        LoadedProgram program = Evaluator.load(ncProgram(Fcl.defuzzify("y", DefuzzificationMethod.COGS)
                .term("lo", single(0)).term("hi", single(100)).noChange()).program());
        FunctionBlockInstance a = program.newInstance();
        FunctionBlockInstance b = program.newInstance("FB");
        assertEquals(100.0, step(a, 1, 0, null));
        assertEquals(7.0, step(b, 0, 0, null));
        assertEquals(100.0, step(a, 0, 0, null));
    }

    /*
     * One loaded program serves instances on several threads at once: each thread steps its own
     * instance through the valve's operating points and must get the single-threaded results
     * (9500/127 at 5/60, 500/109 at 5/90, -8500/113 at 20/100).
     */
    @Test
    void oneLoadedProgramServesInstancesOnManyThreads() throws Exception {
        LoadedProgram program = Evaluator.load(ValveExampleTest.valve().program());
        double[][] points = {{5, 60, 9500.0 / 127}, {5, 90, 500.0 / 109}, {20, 100, -8500.0 / 113}};
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(4);
        try {
            List<java.util.concurrent.Future<Double>> worst = new java.util.ArrayList<>();
            for (int t = 0; t < 4; t++) {
                int offset = t;
                worst.add(pool.submit(() -> {
                    FunctionBlockInstance fb = program.newInstance();
                    double maxError = 0;
                    for (int i = 0; i < 20_000; i++) {
                        double[] p = points[(i + offset) % points.length];
                        fb.set("temp", p[0]);
                        fb.set("pressure", p[1]);
                        fb.evaluate();
                        maxError = Math.max(maxError, Math.abs(fb.get("valve") - p[2]));
                    }
                    return maxError;
                }));
            }
            for (java.util.concurrent.Future<Double> f : worst) {
                assertEquals(0.0, f.get(), 1e-12);
            }
        } finally {
            pool.shutdown();
        }
    }

    /*
     * DEFAULT applies when rules fire only with degree 0: p=0, q=0 gives both rules degree 0 -> the
     * DEFAULT constant -3 (not 0/0, not the previous value).
     */
    @Test
    void defaultWhenOnlyZeroDegreeRulesFire() throws EvaluationException {
        FunctionBlockInstance fb = ncProgram(Fcl.defuzzify("y", DefuzzificationMethod.COGS)
                .term("lo", single(0)).term("hi", single(100)).defaultValue(-3)).instance();
        Trace trace = new Trace();
        assertEquals(100.0, step(fb, 1, 0, trace));
        assertEquals(-3.0, step(fb, 0, 0, trace));
        assertEquals(Trace.Outcome.DEFAULT, trace.result("y").orElseThrow().outcome());
    }

    /*
     * A point term entirely outside the RANGE: hi=(200,0)(210,1)(220,0) with RANGE 0..100 is 0 on
     * [0,100], so although the rule fires with degree 1 the accumulated set is identically zero and
     * the DEFAULT (-3) applies.
     */
    @Test
    void defaultWhenTheAccumulatedSetIsZeroInsideTheRange() throws EvaluationException {
        FunctionBlockInstance fb = ncProgram(Fcl.defuzzify("y", DefuzzificationMethod.COG).range(0, 100)
                .term("lo", pts(0, 0, 10, 1, 20, 0)).term("hi", pts(200, 0, 210, 1, 220, 0)).defaultValue(-3))
                .instance();
        assertEquals(-3.0, step(fb, 1, 0, null));
        assertEquals(10.0, step(fb, 0, 1, null), 1e-12);
    }

    /*
     * Bare variable conclusions and rule block order. x IS hi := (0,0)(1,1), x = 0.8.
     * Block "first": IF x IS hi THEN m WITH 0.5 -> m = 0.4 (written when the block ends).
     * Block "second": IF m THEN y IS big; IF NOT m THEN y IS small -> big 0.4, small 0.6,
     * CoGS = (0.4*10 + 0.6*0)/1 = 4.
     */
    @Test
    void laterBlocksSeeValuesWrittenByEarlierBlocks() throws EvaluationException {
        FunctionBlockInstance fb = Fcl.block("fb").input("x").local("m").output("y")
                .fuzzify("x", Fcl.term("hi", IDENTITY))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("small", single(0))
                        .term("big", single(10)))
                .rules(Fcl.ruleBlock("first").rule(is("x", "hi"), Fcl.thenVar("m", num(0.5))))
                .rules(Fcl.ruleBlock("second").rule(v("m"), then("y", "big")).rule(not(v("m")), then("y", "small")))
                .instance();
        fb.set("x", 0.8);
        fb.evaluate();
        assertEquals(0.4, fb.get("m"), 1e-15);
        assertEquals(4.0, fb.get("y"), 1e-12);
    }

    /*
     * Within one block every condition sees the values of the block's start. One block:
     * rule 1: IF x IS hi THEN m; rule 2: IF m THEN o (o a bare output).
     * Step 1 (m starts at 0): m becomes 0.8 but rule 2 saw m = 0 -> o = 0.
     * Step 2: rule 2 sees the m of step 1, 0.8 -> o = 0.8. Step 3 with x = 0.3: o = 0.8, m = 0.3.
     */
    @Test
    void conditionsInABlockSeeTheValuesOfTheBlocksStart() throws EvaluationException {
        FunctionBlockInstance fb = Fcl.block("fb").input("x").local("m").output("o")
                .fuzzify("x", Fcl.term("hi", IDENTITY))
                .rules(Fcl.ruleBlock("only").rule(is("x", "hi"), thenVar("m")).rule(v("m"), thenVar("o")))
                .instance();
        fb.set("x", 0.8);
        fb.evaluate();
        assertEquals(0.8, fb.get("m"), 1e-15);
        assertEquals(0.0, fb.get("o"), 0.0);
        fb.evaluate();
        assertEquals(0.8, fb.get("o"), 1e-15);
        fb.set("x", 0.3);
        fb.evaluate();
        assertEquals(0.8, fb.get("o"), 1e-15);
        assertEquals(0.3, fb.get("m"), 1e-15);
    }

    /*
     * A variable concluded in two blocks takes the later block's value: block a sets m = 0.8 (x),
     * block b sets m = 0.5*0.8 = 0.4.
     * Several rules of one block concluding m accumulate with the block's ACCU: rules with degrees
     * 0.7 and 0.5 give MAX 0.7, BSUM min(1, 1.2) = 1, NSUM 1.2/max(1, 1.2) = 1; degrees 0.3 and
     * 0.2 give MAX 0.3, BSUM 0.5, NSUM 0.5.
     */
    @Test
    void bareConclusionsAccumulateWithTheBlocksAccu() throws EvaluationException {
        FunctionBlockInstance twoBlocks = Fcl.block("fb").input("x").local("m").output("o")
                .fuzzify("x", Fcl.term("hi", IDENTITY))
                .rules(Fcl.ruleBlock("a").rule(is("x", "hi"), thenVar("m")))
                .rules(Fcl.ruleBlock("b").rule(is("x", "hi"), thenVar("m", num(0.5))))
                .instance();
        twoBlocks.set("x", 0.8);
        twoBlocks.evaluate();
        assertEquals(0.4, twoBlocks.get("m"), 1e-15);

        double[][] expected = {{0.7, 1, 1}, {0.3, 0.5, 0.5}};
        double[][] inputs = {{0.7, 0.5}, {0.3, 0.2}};
        AccumulationMethod[] methods = {AccumulationMethod.MAX, AccumulationMethod.BSUM, AccumulationMethod.NSUM};
        for (int m = 0; m < 3; m++) {
            FunctionBlockInstance fb = Fcl.block("fb").input("p").input("q").output("o")
                    .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                    .rules(Fcl.ruleBlock("r").accu(methods[m]).rule(is("p", "deg"), thenVar("o"))
                            .rule(is("q", "deg"), thenVar("o")))
                    .instance();
            for (int i = 0; i < 2; i++) {
                fb.set("p", inputs[i][0]);
                fb.set("q", inputs[i][1]);
                fb.evaluate();
                assertEquals(expected[i][m], fb.get("o"), 1e-15, methods[m] + " case " + i);
            }
        }
    }

    /*
     * An input not set keeps its previous value; initially its declared initial value, else 0.
     * Valve with temp := 5 declared: pressure 60 alone -> 9500/127. Then pressure 90 -> 500/109
     * (temp still 5). Integer inputs round half away from zero: 2.5 -> 3, -2.5 -> -3,
     * 0.49999999999999994 -> 0.
     */
    @Test
    void inputsKeepTheirValueAndIntegerInputsRound() throws EvaluationException {
        FunctionBlockInstance fb = Fcl.block("fb").variable("temp", VariableKind.INPUT, DataType.REAL, 5.0)
                .input("pressure").variable("n", VariableKind.INPUT, DataType.INT, null).output("valve")
                .fuzzify("temp", Fcl.term("cold", pts(3, 1, 27, 0)), Fcl.term("hot", pts(3, 0, 27, 1)))
                .fuzzify("pressure", Fcl.term("low", pts(55, 1, 95, 0)), Fcl.term("high", pts(55, 0, 95, 1)))
                .defuzzify(Fcl.defuzzify("valve", DefuzzificationMethod.COGS)
                        .term("drainage", single(-100)).term("closed", single(0)).term("inlet", single(100)))
                .rules(Fcl.ruleBlock("No1")
                        .rule(Fcl.and(is("temp", "cold"), is("pressure", "low")), then("valve", "inlet"))
                        .rule(Fcl.and(is("temp", "cold"), is("pressure", "high")), then("valve", "closed", num(0.8)))
                        .rule(Fcl.and(is("temp", "hot"), is("pressure", "low")), then("valve", "closed"))
                        .rule(Fcl.and(is("temp", "hot"), is("pressure", "high")), then("valve", "drainage")))
                .instance();
        fb.set("pressure", 60);
        fb.evaluate();
        assertEquals(9500.0 / 127, fb.get("valve"), 1e-12);
        fb.set("pressure", 90);
        fb.evaluate();
        assertEquals(500.0 / 109, fb.get("valve"), 1e-12);
        fb.set("n", 2.5);
        assertEquals(3.0, fb.get("n"));
        fb.set("n", -2.5);
        assertEquals(-3.0, fb.get("n"));
        fb.set("n", 0.49999999999999994);
        assertEquals(0.0, fb.get("n"));
        assertEquals(List.of("temp", "pressure", "n"), fb.inputNames());
        assertEquals(List.of("valve"), fb.outputNames());
    }

    /** Output y of the given type: singletons a and b, rule degrees p and q, CoGS. */
    private static FunctionBlockInstance typed(DataType type, double a, double b) {
        return Fcl.block("fb").input("p").input("q").variable("y", VariableKind.OUTPUT, type, null)
                .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COGS).term("a", single(a)).term("b", single(b)))
                .rules(Fcl.ruleBlock("r").rule(is("p", "deg"), then("y", "a")).rule(is("q", "deg"), then("y", "b")))
                .instance();
    }

    /*
     * Integer outputs: a=0, b=5 at equal degrees -> 2.5 -> INT 3; a=0, b=-5 -> -2.5 -> -3;
     * a=0, b=7, degrees 0.6/0.4 -> 2.8 -> 3. SINT with a=200 alone -> 200 > 127 -> FCL-V004.
     */
    @Test
    void integerOutputsRoundHalfAwayFromZeroAndMustFit() throws EvaluationException {
        FunctionBlockInstance up = typed(DataType.INT, 0, 5);
        up.set("p", 0.5);
        up.set("q", 0.5);
        up.evaluate();
        assertEquals(3.0, up.get("y"));
        FunctionBlockInstance down = typed(DataType.DINT, 0, -5);
        down.set("p", 0.5);
        down.set("q", 0.5);
        down.evaluate();
        assertEquals(-3.0, down.get("y"));
        FunctionBlockInstance near = typed(DataType.UINT, 0, 7);
        near.set("p", 0.6);
        near.set("q", 0.4);
        near.evaluate();
        assertEquals(3.0, near.get("y"));
        FunctionBlockInstance tooBig = typed(DataType.SINT, 200, 0);
        tooBig.set("p", 1);
        EvaluationException e = assertThrows(EvaluationException.class, tooBig::evaluate);
        assertEquals("FCL-V004", e.code());
    }

    @Test
    void namesAreCheckedWithStableCodes() throws EvaluationException {
        LoadedProgram program = Evaluator.load(ValveExampleTest.valve().program());
        assertEquals(List.of("Fuzzy_FB"), program.functionBlockNames());
        assertEquals("FCL-V001", assertThrows(EvaluationException.class, () -> program.newInstance("nope")).code());
        FunctionBlockInstance fb = program.newInstance("fuzzy_fb");
        assertEquals("FCL-V001", assertThrows(EvaluationException.class, () -> fb.set("tmp", 1)).code());
        assertEquals("FCL-V001", assertThrows(EvaluationException.class, () -> fb.get("tmp")).code());
        assertEquals("FCL-V003", assertThrows(EvaluationException.class, () -> fb.set("valve", 1)).code());
        assertEquals(Map.of("valve", 0.0), fb.outputs());
    }

    /*
     * Overflow in doubles is never a silent DEFAULT: the reference hands the step to exact arithmetic, which has
     * the value (issue 24). RANGE -1e308..1e308 is 2e308 wide, infinite in doubles, so CoG = inf/inf; exactly,
     * T = 1 everywhere on a range symmetric about 0 has its centre at 0. Singletons at 1.5e308 with degree 1 twice:
     * the CoGS numerator 3e308 overflows in doubles; exactly (1.5e308 + 1.5e308) / 2 = 1.5e308. The plain double
     * arithmetic (FairVectors' other arithmetic) still reports the overflow as FCL-V005.
     */
    @Test
    void overflowIsDecidedExactlyNotADefault() throws EvaluationException {
        Fcl.Block wideBlock = Fcl.block("fb").input("p").output("y")
                .fuzzify("p", Fcl.term("deg", IDENTITY))
                .defuzzify(Fcl.defuzzify("y", DefuzzificationMethod.COG).range(-1e308, 1e308)
                        .term("t", pts(0, 1, 1, 1)))
                .rules(Fcl.ruleBlock("r").rule(is("p", "deg"), then("y", "t")));
        FunctionBlockInstance wide = wideBlock.instance();
        wide.set("p", 1);
        wide.evaluate();
        assertEquals(0.0, wide.get("y"));
        assertEquals(1, wide.fallbacks());
        FunctionBlockInstance huge = typed(DataType.LREAL, 1.5e308, 1.5e308);
        huge.set("p", 1);
        huge.set("q", 1);
        huge.evaluate();
        assertEquals(1.5e308, huge.get("y"));
        FunctionBlockInstance plain = Evaluator.load(wideBlock.program()).newDoubleInstance(null);
        plain.set("p", 1);
        assertEquals("FCL-V005", assertThrows(EvaluationException.class, plain::evaluate).code());
    }
}
