package org.fclcert.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Literal;
import org.fclcert.model.Program;
import org.fclcert.model.ShapeKind;
import org.fclcert.syntax.dialect.FuzzyliteReader;
import org.fclcert.syntax.dialect.JFuzzyLogicReader;
import org.fclcert.write.ShapePoints;
import org.junit.jupiter.api.Test;

/**
 * Evaluation of the dialect constructs (docs/semantics.md, "Named shapes, hedges and other dialect
 * accumulations"): expected values by hand, or by an independent dense midpoint rule written here.
 */
class DialectSemanticsTest {
    private static FunctionBlockInstance load(boolean fuzzylite, String text) {
        Analysis a = Analysis.analyze(fuzzylite ? new FuzzyliteReader() : new JFuzzyLogicReader(), "t.fcl", text);
        assertTrue(a.diagnostics().stream().noneMatch(d -> d.isError()), a.diagnostics().toString());
        Program p = a.program().orElseThrow();
        return Evaluator.load(p).newInstance();
    }

    /** One input x with the given term, one singleton output y; y's CoGS = the rule degree · 10 / degree = 10. */
    private static String fuzzylite(String inputTerm, String condition, String accu, String extraRule) {
        return "FUNCTION_BLOCK f\nVAR_INPUT\n  x: REAL;\nEND_VAR\nVAR_OUTPUT\n  y: REAL;\nEND_VAR\n"
                + "FUZZIFY x\n  TERM a := " + inputTerm + ";\n  TERM b := Triangle 0 5 10;\nEND_FUZZIFY\n"
                + "DEFUZZIFY y\n  RANGE := (0 .. 10);\n  TERM one := 1.000;\n  TERM zero := 0.000;\n  METHOD : COGSS;\n"
                + "  ACCU : " + accu + ";\n  DEFAULT := nan;\nEND_DEFUZZIFY\n"
                + "RULEBLOCK r\n  AND : MIN;\n  ACT : MIN;\n  RULE 1 : if " + condition + " then y is one\n" + extraRule
                + "END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
    }

    /** COGSS with one singleton at 1 and one at 0 is the degree of 'one': the fired degree itself. */
    private static double degree(String inputTerm, String condition, double x) throws EvaluationException {
        FunctionBlockInstance f = load(true, fuzzylite(inputTerm, condition, "MAX", ""));
        f.set("x", x);
        f.evaluate();
        return f.get("y");
    }

    @Test
    void gaussianFuzzificationByItsFormula() throws EvaluationException {
        // exp(-(x-5)^2/(2*2^2)): x=5 -> 1; x=7 -> exp(-0.5) = 0.6065306597126334; x=1 -> exp(-2) = 0.1353352832366127
        assertEquals(1.0, degree("Gaussian 5 2", "x is a", 5), 1e-15);
        assertEquals(0.6065306597126334, degree("Gaussian 5 2", "x is a", 7), 1e-15);
        assertEquals(0.1353352832366127, degree("Gaussian 5 2", "x is a", 1), 1e-15);
        // Bell centre 5 width 2 slope 1: 1/(1+|(x-5)/2|^2); x=7 -> 1/2, x=9 -> 1/5
        assertEquals(0.5, degree("Bell 5 2 1", "x is a", 7), 1e-15);
        assertEquals(0.2, degree("Bell 5 2 1", "x is a", 9), 1e-15);
        // Sigmoid inflection 5 slope 2: 1/(1+exp(-2(x-5))); x=5 -> 0.5, x=6 -> 1/(1+e^-2) = 0.8807970779778823
        assertEquals(0.5, degree("Sigmoid 5 2", "x is a", 5), 1e-15);
        assertEquals(0.8807970779778823, degree("Sigmoid 5 2", "x is a", 6), 1e-15);
        // Cosine centre 5 width 4: (1+cos(2π(x-5)/4))/2; x=6 -> (1+cos(π/2))/2 = 0.5; x=7.5 -> 0 (outside)
        assertEquals(0.5, degree("Cosine 5 4", "x is a", 6), 1e-15);
        assertTrue(Double.isNaN(degree("Cosine 5 4", "x is a", 7.5)));   // degree 0: nothing fired, DEFAULT nan
        // Ramp 10 0 falls: x=2.5 -> 0.75; Rectangle 2 4: x=2 -> 1, x=4.5 -> 0
        assertEquals(0.75, degree("Ramp 10 0", "x is a", 2.5), 1e-15);
        assertEquals(1.0, degree("Rectangle 2 4", "x is a", 2), 0);
        assertTrue(Double.isNaN(degree("Rectangle 2 4", "x is a", 4.5)));
    }

    @Test
    void hedgesAsFuzzyliteDefinesThem() throws EvaluationException {
        // Triangle 0 5 10 at x = 2: μ = 0.4
        String t = "Triangle 0 5 10";
        assertEquals(0.16, degree(t, "x is very a", 2), 1e-15);                        // 0.4²
        assertEquals(Math.sqrt(0.4), degree(t, "x is somewhat a", 2), 1e-15);          // √0.4
        assertEquals(0.32, degree(t, "x is extremely a", 2), 1e-15);                   // 2·0.4² (μ ≤ 0.5)
        assertEquals(Math.sqrt(0.2), degree(t, "x is seldom a", 2), 1e-15);            // √(0.4/2)
        assertEquals(0.6, degree(t, "x is not a", 2), 1e-15);                          // 1 − 0.4 (IS NOT)
        assertEquals(1 - 0.16, degree(t, "x is not very a", 2), 1e-15);                // 1 − 0.4²
        assertEquals(0.36, degree(t, "x is very not a", 2), 1e-15);                    // (1 − 0.4)²
        assertEquals(1.0, degree(t, "x is any", 2), 0);
        // x = 4: μ = 0.8 > 0.5: extremely = 1 − 2·0.2² = 0.92; seldom = 1 − √(0.2/2) = 1 − √0.1
        assertEquals(0.92, degree(t, "x is extremely a", 4), 1e-15);
        assertEquals(1 - Math.sqrt(0.1), degree(t, "x is seldom a", 4), 1e-15);
    }

    @Test
    void proborAndUnboundedSumOnSingletons() throws EvaluationException {
        // two rules on the singleton 'one' at x = 2: degrees 0.4 (Triangle 0 5 10) and 0.8 (Ramp 0 2.5)
        String second = "  RULE 2 : if x is b then y is one\n";
        FunctionBlockInstance probor = load(true, fuzzylite("Ramp 0 2.5", "x is a", "ASUM", second));
        probor.set("x", 2);
        probor.evaluate();
        assertEquals(0.8 + 0.4 - 0.8 * 0.4, probor.get("y"), 1e-15);                  // 0.88
        FunctionBlockInstance sum = load(true, fuzzylite("Ramp 0 2.5", "x is a", "UnboundedSum", second));
        sum.set("x", 2);
        sum.evaluate();
        assertEquals(1.2, sum.get("y"), 1e-15);                                          // 0.8 + 0.4, unbounded
        // nothing fired: DEFAULT := nan
        sum.set("x", -1);
        sum.evaluate();
        assertTrue(Double.isNaN(sum.get("y")));
    }

    private static final String SMOOTH = "FUNCTION_BLOCK s\nVAR_INPUT\n  x : REAL;\nEND_VAR\nVAR_OUTPUT\n  y : REAL;\n"
            + "END_VAR\nFUZZIFY x\n  TERM lo := trian 0 0 10;\n  TERM hi := trian 0 10 10;\nEND_FUZZIFY\n"
            + "DEFUZZIFY y\n  RANGE := (0 .. 20);\n  TERM a := gauss 6 2;\n  TERM b := gbell 3 2 14;\n"
            + "  METHOD : %s;\n  DEFAULT := 0;\nEND_DEFUZZIFY\nRULEBLOCK r\n  AND : MIN;\n  ACT : %s;\n  ACCU : %s;\n"
            + "  RULE 1 : IF x IS lo THEN y IS a;\n  RULE 2 : IF x IS hi THEN y IS b;\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n";

    /** The accumulated set written independently of SmoothSet: for x, μ(u) from the formulas directly. */
    private static double mu(double x, double u, String act, String accu) {
        double dLo = 1 - x / 10;
        double dHi = x / 10;
        double a = Math.exp(-(u - 6) * (u - 6) / 8);
        double b = 1 / (1 + Math.pow(Math.abs((u - 14) / 3), 4));
        double ca = act.equals("MIN") ? Math.min(dLo, a) : dLo * a;
        double cb = act.equals("MIN") ? Math.min(dHi, b) : dHi * b;
        return switch (accu) {
            case "MAX" -> Math.max(ca, cb);
            case "BSUM" -> Math.min(1, ca + cb);
            case "PROBOR" -> ca + cb - ca * cb;
            default -> ca + cb;
        };
    }

    @Test
    void smoothCentreOfGravityAndAreaAgreeWithADenseMidpointRule() throws EvaluationException {
        int n = 1_000_000;
        for (String act : List.of("MIN", "PROD")) {
            for (String accu : List.of("MAX", "BSUM", "PROBOR", "SUM")) {
                for (double x : new double[] {3, 6.5}) {
                    double h = 20.0 / n;
                    double area = 0;
                    double moment = 0;
                    double[] cum = new double[n + 1];
                    for (int i = 0; i < n; i++) {
                        double u = (i + 0.5) * h;
                        double m = mu(x, u, act, accu);
                        area += m * h;
                        moment += u * m * h;
                        cum[i + 1] = area;
                    }
                    double cog = moment / area;
                    int k = 0;
                    while (cum[k + 1] < area / 2) {
                        k++;
                    }
                    double coa = (k + (area / 2 - cum[k]) / (cum[k + 1] - cum[k])) * h;
                    FunctionBlockInstance f = load(false, String.format(SMOOTH, "COG", act, accu));
                    f.set("x", x);
                    f.evaluate();
                    assertEquals(cog, f.get("y"), Math.abs(cog) * 1e-6, act + " " + accu + " x=" + x);
                    FunctionBlockInstance g = load(false, String.format(SMOOTH, "COA", act, accu));
                    g.set("x", x);
                    g.evaluate();
                    assertEquals(coa, g.get("y"), Math.abs(coa) * 1e-6, "CoA " + act + " " + accu + " x=" + x);
                }
            }
        }
    }

    private static final String OTHER_NORMS = "FUNCTION_BLOCK s\nVAR_INPUT\n  x: REAL;\nEND_VAR\nVAR_OUTPUT\n  y: REAL;\n"
            + "END_VAR\nFUZZIFY x\n  RANGE := (0.000 .. 10.000);\n  TERM lo := Triangle 0 0 10;\n  TERM hi := Triangle 0 10 10;\n"
            + "END_FUZZIFY\nDEFUZZIFY y\n  RANGE := (0.000 .. 20.000);\n  TERM a := %s;\n  TERM b := %s;\n  METHOD : COG;\n"
            + "  ACCU : %s;\n  DEFAULT := nan;\nEND_DEFUZZIFY\nRULEBLOCK\n  ACT : %s;\n  RULE 1 : if x is lo then y is a\n"
            + "  RULE 2 : if x is hi then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n";

    /** The t-norms and s-norms by their textbook formulas, written here independently of the evaluator. */
    private static double t(String norm, double a, double b) {
        return switch (norm) {
            case "BDIF" -> Math.max(0, a + b - 1);
            case "EPROD" -> a * b / (2 - (a + b - a * b));
            case "HPROD" -> a + b == 0 ? 0 : a * b / (a + b - a * b);
            case "NMIN" -> a + b > 1 ? Math.min(a, b) : 0;
            default -> throw new IllegalArgumentException(norm);
        };
    }

    private static double s(String norm, double a, double b) {
        return switch (norm) {
            case "ESUM" -> (a + b) / (1 + a * b);
            case "HSUM" -> a * b == 1 ? 1 : (a + b - 2 * a * b) / (1 - a * b);
            case "NMAX" -> a + b < 1 ? Math.max(a, b) : 1;
            default -> throw new IllegalArgumentException(norm);
        };
    }

    /**
     * fuzzylite's ACT and ACCU by other norms (O-ACT-OTHER-NORM, O-ACCU-OTHER-NORM): the accumulated set
     * S(w·T(d1, μa), w·T(d2, μb)), its CoG against a 10⁶-sample midpoint rule of that formula, on smooth terms
     * (Gaussian, bell) and on triangles (points: the kinks of BDIF and NMIN split the integration).
     */
    @Test
    void fuzzyliteOtherActivationsAndAccumulationsAgreeWithADenseMidpointRule() throws EvaluationException {
        int n = 1_000_000;
        double h = 20.0 / n;
        String[][] terms = {{"Gaussian 6 2", "Bell 14 3 2"}, {"Triangle 2 6 10", "Triangle 10 14 18"}};
        for (String[] term : terms) {
            boolean smooth = term[0].startsWith("Gaussian");
            for (String act : List.of("BDIF", "EPROD", "HPROD", "NMIN")) {
                for (String accu : List.of("ESUM", "HSUM", "NMAX")) {
                    FunctionBlockInstance f = load(true, String.format(OTHER_NORMS, term[0], term[1], accu, act));
                    for (double x : new double[] {3, 6.5}) {
                        double dLo = 1 - x / 10;
                        double dHi = x / 10;
                        double area = 0;
                        double moment = 0;
                        for (int i = 0; i < n; i++) {
                            double u = (i + 0.5) * h;
                            double ma = smooth ? Math.exp(-(u - 6) * (u - 6) / 8) : Math.max(0, 1 - Math.abs(u - 6) / 4);
                            double mb = smooth ? 1 / (1 + Math.pow(Math.abs((u - 14) / 3), 4))
                                    : Math.max(0, 1 - Math.abs(u - 14) / 4);
                            double m = s(accu, s(accu, 0, t(act, dLo, ma)), t(act, dHi, mb));
                            area += m * h;
                            moment += u * m * h;
                        }
                        f.set("x", x);
                        f.evaluate();
                        String what = term[0] + " " + act + " " + accu + " x=" + x;
                        // NMIN and NMAX jump: the midpoint rule is off by up to a sample step per jump
                        double tol = act.equals("NMIN") || accu.equals("NMAX") ? 1e-5 : 1e-6;
                        assertEquals(moment / area, f.get("y"), moment / area * tol, what);
                    }
                }
            }
        }
    }

    /** Einstein sum of singletons: (a + b) / (1 + ab) per term; the activation does not change a singleton. */
    @Test
    void einsteinSumOfSingletons() throws EvaluationException {
        String second = "  RULE 2 : if x is b then y is one\n";
        FunctionBlockInstance f = load(true, fuzzylite("Ramp 0 2.5", "x is a", "ESUM", second).replace("ACT : MIN",
                "ACT : EPROD"));
        f.set("x", 2);                                      // degrees 0.8 and 0.4 on 'one'
        f.evaluate();
        assertEquals(1.2 / 1.32, f.get("y"), 1e-15);      // COGSS = the degree of 'one' = 1.2 / (1 + 0.32)
    }

    private static final String TSUKAMOTO = """
            FUNCTION_BLOCK tsukamoto
            VAR_INPUT
              x: REAL;
            END_VAR
            VAR_OUTPUT
              r: REAL;
              s: REAL;
              z: REAL;
            END_VAR
            FUZZIFY x
              RANGE := (0.000 .. 10.000);
              TERM lo := Ramp 10.000 0.000;
              TERM hi := Ramp 0.000 10.000;
            END_FUZZIFY
            DEFUZZIFY r
              RANGE := (0.000 .. 1.000);
              TERM a := Ramp 0.000 1.000;
              TERM b := Ramp 1.000 0.200;
              METHOD : COGS;
              DEFAULT := nan;
            END_DEFUZZIFY
            DEFUZZIFY s
              RANGE := (0.000 .. 10.000);
              TERM a := Sigmoid 5.000 2.000;
              TERM b := SShape 0.000 10.000;
              METHOD : COGS;
              DEFAULT := nan;
            END_DEFUZZIFY
            DEFUZZIFY z
              RANGE := (0.000 .. 10.000);
              TERM a := ZShape 0.000 10.000;
              TERM b := Concave 4.000 5.000;
              METHOD : COGS;
              DEFAULT := nan;
            END_DEFUZZIFY
            RULEBLOCK
              RULE 1 : if x is lo then r is a and s is a and z is a
              RULE 2 : if x is hi then r is b and s is b and z is b
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * Tsukamoto's method (fuzzylite's COGS on monotonic terms, O-TSUKAMOTO): each term inverted at its degree, the
     * weighted average of those points; by hand.
     */
    @Test
    void tsukamotoInvertsEachMonotonicTermAtItsDegree() throws EvaluationException {
        FunctionBlockInstance f = load(true, TSUKAMOTO);
        f.set("x", 2);                                      // lo 0.8, hi 0.2
        f.evaluate();
        // r: rising ramp 0→1 at 0.8: 0.8; falling ramp 1→0.2 at 0.2: 1 + 0.2·(0.2 − 1) = 0.84
        assertEquals((0.8 * 0.8 + 0.2 * 0.84) / 1.0, f.get("r"), 1e-15);
        // s: sigmoid 1/(1+e^(−2(u−5))) = 0.8 at u = 5 − ln(1/0.8 − 1)/2 = 5 + ln 2; S shape 0..10 at 0.2 (≤ ½):
        // 2(u/10)² = 0.2, u = 10·√0.1
        assertEquals(0.8 * (5 + Math.log(2)) + 0.2 * 10 * Math.sqrt(0.1), f.get("s"), 1e-12);
        // z: Z shape 0..10 at 0.8 (≥ ½): 1 − 2(u/10)² = 0.8, u = 10·√0.1; Concave 4 5 (rising) at 0.2:
        // (5 − 4)/(10 − 4 − u) = 0.2, u = 1
        assertEquals(0.8 * 10 * Math.sqrt(0.1) + 0.2 * 1, f.get("z"), 1e-12);
        f.set("x", 10);                                     // hi alone, at 1: the falling ramp's end 0.2, the S
        f.evaluate();                                       // shape's end 10, the Concave's end 5
        assertEquals(0.2, f.get("r"), 1e-15);
        assertEquals(10, f.get("s"), 1e-12);
        assertEquals(5, f.get("z"), 1e-12);
        f.set("x", 0);                                      // lo alone, at 1: a sigmoid never reaches 1, so the
        f.evaluate();                                       // RANGE's end beyond its rise; Z shape 1 up to 0
        assertEquals(1, f.get("r"), 1e-15);
        assertEquals(10, f.get("s"), 0);
        assertEquals(0, f.get("z"), 1e-12);
    }

    @Test
    void smoothMaximaByHand() throws EvaluationException {
        // x = 3: rule 1 degree 0.7 clips gauss(6, 2): plateau where exp(-(u-6)²/8) ≥ 0.7, i.e.
        // u = 6 ± 2·√(−2 ln 0.7) = 6 ± 1.6891...; rule 2 degree 0.3 clips the bell at 0.3 < 0.7.
        double r = 2 * Math.sqrt(-2 * Math.log(0.7));
        FunctionBlockInstance lm = load(false, String.format(SMOOTH, "LM", "MIN", "MAX"));
        lm.set("x", 3);
        lm.evaluate();
        assertEquals(6 - r, lm.get("y"), 1e-9);
        FunctionBlockInstance rm = load(false, String.format(SMOOTH, "RM", "MIN", "MAX"));
        rm.set("x", 3);
        rm.evaluate();
        assertEquals(6 + r, rm.get("y"), 1e-9);
        // ACT PROD at x = 3: 0.7·gauss peaks at u = 6 exactly (0.7 > 0.3·bell); LM = RM = 6 up to the
        // width of the 1e-12 tie band: |u − 6| ≤ 2·√(2e-12) ≈ 2.9e-6
        FunctionBlockInstance peak = load(false, String.format(SMOOTH, "LM", "PROD", "MAX"));
        peak.set("x", 3);
        peak.evaluate();
        assertEquals(6, peak.get("y"), 3e-6);
        // nothing fires above the RANGE ends? x = 0 fires rule 1 fully: RM of min(1, gauss) is 6 (the peak)
        rm.set("x", 0);
        rm.evaluate();
        assertEquals(6, rm.get("y"), 3e-6);
    }

    @Test
    void linearNamedShapesTakeTheExactPathAndConvertExactly() {
        MembershipFunction.NamedShape tri = new MembershipFunction.NamedShape(ShapeKind.TRIANGLE,
                List.of(Literal.of(0), Literal.of(5), Literal.of(10)));
        assertEquals(List.of(0.0, 5.0, 10.0), ShapePoints.exact(tri).orElseThrow().stream()
                .map(p -> ((Literal) p.x()).value()).toList());
        MembershipFunction.NamedShape gauss = new MembershipFunction.NamedShape(ShapeKind.GAUSSIAN,
                List.of(Literal.of(5), Literal.of(2)));
        assertTrue(ShapePoints.exact(gauss).isEmpty());
        ShapePoints.Approximation ap = ShapePoints.approximate(gauss, 0, 10, 41);
        // linear interpolation error of exp(-(u-5)²/8) with spacing h = 0.25 is at most h²/8·max|f''| = 0.0078·0.25
        // (max |f''| = 1/sd² = 0.25): 0.001953; the computed bound must cover the sampled error and be near it
        assertTrue(ap.sampledError() <= 0.25 * 0.25 / 8 * 0.25 + 1e-12, "sampled " + ap.sampledError());
        assertTrue(ap.maxError() >= ap.sampledError() && ap.maxError() < 2 * 0.25 * 0.25 / 8 * 0.25,
                "bound " + ap.maxError());
        // a dense independent check of the bound
        double worst = 0;
        List<org.fclcert.model.Point> pts = ap.points();
        for (int i = 0; i + 1 < pts.size(); i++) {
            double x0 = ((Literal) pts.get(i).x()).value();
            double x1 = ((Literal) pts.get(i + 1).x()).value();
            double y0 = ((Literal) pts.get(i).degree()).value();
            double y1 = ((Literal) pts.get(i + 1).degree()).value();
            for (int j = 0; j <= 1000; j++) {
                double u = x0 + (x1 - x0) * j / 1000;
                worst = Math.max(worst, Math.abs(Math.exp(-(u - 5) * (u - 5) / 8) - (y0 + (y1 - y0) * j / 1000)));
            }
        }
        assertTrue(worst <= ap.maxError(), worst + " > " + ap.maxError());
    }
}
