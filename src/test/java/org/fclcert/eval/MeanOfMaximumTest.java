package org.fclcert.eval;

import static org.fclcert.eval.Fcl.is;
import static org.fclcert.eval.Fcl.pts;
import static org.fclcert.eval.Fcl.single;
import static org.fclcert.eval.Fcl.then;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.MembershipFunction;
import org.junit.jupiter.api.Test;

/**
 * MoM (Open Level, O-MOM), docs/semantics.md "Open Level (dialect) semantics": the centre of the set of
 * points at the supremum of the accumulated set, in closed form. Inputs p and q have the term
 * deg := (0,0)(1,1), so the value given to p (q) is the degree of rule 1 (rule 2).
 */
class MeanOfMaximumTest {
    private static final MembershipFunction IDENTITY = pts(0, 0, 1, 1);

    private static double run(Fcl.Out out, AccumulationMethod accu, double p, double q) throws EvaluationException {
        FunctionBlockInstance fb = Fcl.block("fb").input("p").input("q").output("y")
                .fuzzify("p", Fcl.term("deg", IDENTITY)).fuzzify("q", Fcl.term("deg", IDENTITY))
                .defuzzify(out.defaultValue(-1))
                .rules(Fcl.ruleBlock("r").act(ActivationMethod.MIN).accu(accu)
                        .rule(is("p", "deg"), then("y", "a")).rule(is("q", "deg"), then("y", "b")))
                .instance();
        fb.set("p", p);
        fb.set("q", q);
        fb.evaluate();
        return fb.get("y");
    }

    private static Fcl.Out mom() {
        return Fcl.defuzzify("y", DefuzzificationMethod.MOM);
    }

    /*
     * Two separated plateaus of equal height: a = (0,0)(2,1)(4,1)(6,0), b = (10,0)(12,1)(20,1)(22,0), both
     * fully activated (ACCU MAX). The argmax set is [2,4] ∪ [12,20], lengths 2 and 8, midpoints 3 and 16:
     * MoM = (2·3 + 8·16) / 10 = 134/10 = 13.4. (The mean of LM 2 and RM 20 would be 11; the middle of the
     * single most activated term, FFLL's reading, 3 or 16.)
     */
    @Test
    void twoSeparatedPlateausWeighByLength() throws EvaluationException {
        Fcl.Out out = mom().term("a", pts(0, 0, 2, 1, 4, 1, 6, 0)).term("b", pts(10, 0, 12, 1, 20, 1, 22, 0));
        assertEquals(13.4, run(out, AccumulationMethod.MAX, 1, 1), 1e-12);
    }

    /*
     * Clipping makes plateaus: a = (0,0)(10,1)(20,0) at degree 0.5 is 0.5 on [5, 15]; b = (30,0)(40,1)(50,0)
     * at 0.25 stays lower. MoM = 10. With b at 0.5 too, [35, 45] joins: (10·10 + 10·40)/20 = 25.
     */
    @Test
    void clippedTrianglesArePlateaus() throws EvaluationException {
        Fcl.Out out = mom().term("a", pts(0, 0, 10, 1, 20, 0)).term("b", pts(30, 0, 40, 1, 50, 0));
        assertEquals(10.0, run(out, AccumulationMethod.MAX, 0.5, 0.25), 1e-12);
        assertEquals(25.0, run(out, AccumulationMethod.MAX, 0.5, 0.5), 1e-12);
    }

    /*
     * A single peak: a = (0,0)(3,1)(10,0) fully activated has its maximum at one point, u = 3 (no plateau):
     * MoM = 3. Two equal isolated peaks a at 3 and b = (10,0)(17,1)(20,0) at 17: mean (3 + 17)/2 = 10.
     */
    @Test
    void isolatedMaximaAreAveraged() throws EvaluationException {
        Fcl.Out out = mom().term("a", pts(0, 0, 3, 1, 10, 0)).term("b", pts(10, 0, 17, 1, 20, 0));
        assertEquals(3.0, run(out, AccumulationMethod.MAX, 1, 0), 1e-12);
        assertEquals(10.0, run(out, AccumulationMethod.MAX, 1, 1), 1e-12);
    }

    /*
     * ACCU BSUM: a = (0,0)(10,1)(20,0) and b = (10,0)(20,1)(30,0), each clipped at 0.5: a is 0.5 on [5,15],
     * b is 0.5 on [15,25]. On [10,15] a stays 0.5 while b = (u-10)/10 rises to 0.5; on [15,20] b stays 0.5
     * while a = (20-u)/10 falls. The sum reaches 1 only at u = 15: a single peak, MoM = 15.
     */
    @Test
    void boundedSumMakesAPeakWherePlateausMeet() throws EvaluationException {
        Fcl.Out out = mom().term("a", pts(0, 0, 10, 1, 20, 0)).term("b", pts(10, 0, 20, 1, 30, 0));
        assertEquals(15.0, run(out, AccumulationMethod.BSUM, 0.5, 0.5), 1e-12);
    }

    /*
     * Singletons a = 10 and b = 40: with degrees 0.7 and 0.3 only a is maximal, MoM = 10; with 0.6 and 0.6
     * both are, MoM = (10 + 40)/2 = 25 (CoGS would give 25 too; with 0.6 and 0.2 CoGS gives
     * (6 + 8)/0.8 = 17.5 where MoM stays 10).
     */
    @Test
    void singletonsWithTheLargestDegree() throws EvaluationException {
        Fcl.Out out = mom().term("a", single(10)).term("b", single(40));
        assertEquals(10.0, run(out, AccumulationMethod.MAX, 0.7, 0.3), 1e-12);
        assertEquals(25.0, run(out, AccumulationMethod.MAX, 0.6, 0.6), 1e-12);
        assertEquals(10.0, run(out, AccumulationMethod.MAX, 0.6, 0.2), 1e-12);
    }

    /* Nothing fires: DEFAULT (-1), for point terms and for singletons. */
    @Test
    void noRuleFiredGivesTheDefault() throws EvaluationException {
        assertEquals(-1.0, run(mom().term("a", pts(0, 0, 3, 1, 10, 0)).term("b", pts(10, 0, 17, 1, 20, 0)),
                AccumulationMethod.MAX, 0, 0), 0);
        assertEquals(-1.0, run(mom().term("a", single(10)).term("b", single(40)), AccumulationMethod.MAX, 0, 0), 0);
    }
}
