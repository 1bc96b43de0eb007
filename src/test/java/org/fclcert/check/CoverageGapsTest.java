package org.fclcert.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.Trace;
import org.fclcert.model.DataType;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Literal;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;
import org.fclcert.model.VariableKind;
import org.junit.jupiter.api.Test;

/**
 * FCL-W005: regions where no rule fires. The expected regions are worked out by hand from the terms; on the
 * corpus, every reported region is confirmed, and every other place denied, by the reference evaluator's rule
 * degrees at sampled inputs (an independent method: it computes the degrees, the analysis never does).
 */
class CoverageGapsTest {
    private static String program(String inputs, String fuzzify, String andOp, String rules) {
        return "FUNCTION_BLOCK t\nVAR_INPUT\n" + inputs + "END_VAR\nVAR_OUTPUT\n    y : REAL;\nEND_VAR\n" + fuzzify
                + "DEFUZZIFY y\n    TERM a := 0;\n    TERM b := 10;\n    METHOD : CoGS;\n    DEFAULT := -1;\n"
                + "END_DEFUZZIFY\nRULEBLOCK main\n    AND : " + andOp + ";\n    ACCU : MAX;\n" + rules
                + "END_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
    }

    private static List<String> messages(String text) {
        return Programs.analyze("g.fcl", text).diagnostics().stream().filter(d -> d.code().equals("FCL-W005"))
                .map(Diagnostic::message).toList();
    }

    private static final String TEMP = "    temp : REAL;\n";

    @Test
    void twoTermsMeetingAtZeroLeaveAGapOfZeroWidth() {
        // cold is 0 from 10 on, hot 0 up to 20... here hot starts at 10: both are 0 exactly at 10, nowhere else
        String text = program(TEMP, "FUZZIFY temp\n    TERM cold := (0, 1) (10, 0);\n    TERM hot := (10, 0) (20, 1);\n"
                + "END_FUZZIFY\n", "MIN", "    RULE 1 : IF temp IS cold THEN y IS a;\n"
                + "    RULE 2 : IF temp IS hot THEN y IS b;\n");
        assertEquals(List.of("temp = 10: no rule of block 'main' fires; y takes DEFAULT -1"), messages(text));
    }

    @Test
    void overlappingTermsLeaveNoGap() {
        String text = program(TEMP, "FUZZIFY temp\n    TERM cold := (0, 1) (10, 0);\n    TERM hot := (5, 0) (20, 1);\n"
                + "END_FUZZIFY\n", "MIN", "    RULE 1 : IF temp IS cold THEN y IS a;\n"
                + "    RULE 2 : IF temp IS hot THEN y IS b;\n");
        assertEquals(List.of(), messages(text));
    }

    @Test
    void aGapOfTwoInputsIsOneBoxWithItsEndsOpenOrClosed() {
        // error: neg is 1 up to -10 and 0 from 0; zero is 0 outside (-5, 5); pos 0 up to 0. trend: rising 0 up to 0.
        // For error <= -5 only rule 3 can fire, and only when trend > 0; elsewhere rule 1 or 2 fires (at error 0
        // zero is 1). So the one gap is error in (-inf, -5] and trend in (-inf, 0].
        String text = program("    error : REAL;\n    trend : REAL;\n",
                "FUZZIFY error\n    TERM neg := (-10, 1) (0, 0);\n    TERM zero := (-5, 0) (0, 1) (5, 0);\n"
                        + "    TERM pos := (0, 0) (10, 1);\nEND_FUZZIFY\n"
                        + "FUZZIFY trend\n    TERM falling := (-2, 1) (0, 0);\n    TERM rising := (0, 0) (2, 1);\n"
                        + "END_FUZZIFY\n", "MIN",
                "    RULE 1 : IF error IS zero THEN y IS a;\n    RULE 2 : IF error IS pos THEN y IS b;\n"
                        + "    RULE 3 : IF error IS neg AND trend IS rising THEN y IS b;\n");
        assertEquals(List.of("error in (-inf, -5] and trend in (-inf, 0]: no rule of block 'main' fires;"
                + " y takes DEFAULT -1"), messages(text));
    }

    @Test
    void notOfAVerticalEdgeAndAnOrAreClassifiedAtTheEdgeItself() {
        // step is 0 left of 5, 1 at 5 (the larger of the two degrees there) and up to 10 and beyond: NOT step fires
        // only left of 5. With 'OR x IS spot' (a singleton at 7) the point 7 is covered too.
        String fuzzify = "FUZZIFY x\n    TERM step := (5, 0) (5, 1) (10, 1);\n    TERM spot := 7;\nEND_FUZZIFY\n";
        assertEquals(List.of("x in [5, inf): no rule of block 'main' fires; y takes DEFAULT -1"),
                messages(program("    x : REAL;\n", fuzzify, "MIN", "    RULE 1 : IF x IS NOT step THEN y IS a;\n")));
        assertEquals(List.of("x in [5, 7): no rule of block 'main' fires; y takes DEFAULT -1",
                "x in (7, inf): no rule of block 'main' fires; y takes DEFAULT -1"),
                messages(program("    x : REAL;\n", fuzzify, "MIN",
                        "    RULE 1 : IF x IS NOT step OR x IS spot THEN y IS a;\n")));
    }

    @Test
    void boundedDifferenceOfTwoPartialDegreesIsUndecidedNeverAGap() {
        // a AND b with BDIF is max(0, a + b - 1): on (0, 10) x (0, 10) it is 0 in one corner and positive in the
        // other, so the analysis must not call it a gap; outside, one of them is 0 and so is the rule
        String text = program("    p : REAL;\n    q : REAL;\n",
                "FUZZIFY p\n    TERM up := (0, 0) (10, 1);\nEND_FUZZIFY\nFUZZIFY q\n    TERM up := (0, 0) (10, 1);\n"
                        + "END_FUZZIFY\n", "BDIF", "    RULE 1 : IF p IS up AND q IS up THEN y IS a;\n");
        Program program = Programs.analyze("g.fcl", text).program().orElseThrow();
        FunctionBlock fb = program.functionBlocks().get(0);
        CoverageGaps.Result result = CoverageGaps.of(fb, fb.ruleBlocks().get(0));
        assertTrue(result.analysed());
        assertEquals(1, result.undecidedCells());  // the open square (0, 10) x (0, 10), one cell
        // merged along p first: all p with q <= 0, then p <= 0 with q > 0
        assertEquals(List.of("q in (-inf, 0]", "p in (-inf, 0] and q in (0, inf)"), result.gaps().stream()
                .map(b -> RulesCoverTheInputSpace.region(result.inputs(), b)).toList());
    }

    @Test
    void moreInputsThanTheLimitAreNotAnalysed() {
        StringBuilder inputs = new StringBuilder();
        StringBuilder fuzzify = new StringBuilder();
        List<String> parts = new ArrayList<>();
        for (int i = 0; i <= CoverageGaps.MAX_INPUTS; i++) {
            inputs.append("    x").append(i).append(" : REAL;\n");
            fuzzify.append("FUZZIFY x").append(i).append("\n    TERM on := (0, 0) (1, 1);\nEND_FUZZIFY\n");
            parts.add("x" + i + " IS on");
        }
        String text = program(inputs.toString(), fuzzify.toString(), "MIN",
                "    RULE 1 : IF " + String.join(" AND ", parts) + " THEN y IS a;\n");
        FunctionBlock fb = Programs.analyze("g.fcl", text).program().orElseThrow().functionBlocks().get(0);
        CoverageGaps.Result result = CoverageGaps.of(fb, fb.ruleBlocks().get(0));
        assertEquals("its conditions use 7 inputs (at most 6 are analysed)", result.notAnalysed().orElseThrow());
        assertEquals(List.of(), messages(text));
    }

    /**
     * Inputs beyond the limit are counted, not given an axis: 5 000 rules on 5 000 inputs, and a rule whose
     * undefined term is named after them still decides the reason (an undefined term before the count, as before).
     */
    @Test
    void manyInputsAreCountedAndALaterUndefinedTermStillDecides() {
        StringBuilder inputs = new StringBuilder();
        StringBuilder fuzzify = new StringBuilder();
        StringBuilder rules = new StringBuilder();
        for (int i = 0; i < 5000; i++) {
            inputs.append("    x").append(i).append(" : REAL;\n");
            fuzzify.append("FUZZIFY x").append(i).append(" TERM on := (0, 0) (1, 1); END_FUZZIFY\n");
            rules.append("    RULE ").append(i + 1).append(" : IF x").append(i).append(" IS on THEN y IS a;\n");
        }
        String text = program(inputs.toString(), fuzzify.toString(), "MIN", rules.toString());
        FunctionBlock fb = Programs.analyze("many.fcl", text).program().orElseThrow().functionBlocks().get(0);
        assertEquals("its conditions use 5000 inputs (at most 6 are analysed)",
                CoverageGaps.of(fb, fb.ruleBlocks().get(0)).notAnalysed().orElseThrow());

        // the same block with one more rule naming a term x4999 does not have: the compiler stops at that leaf
        String undefined = program(inputs.toString(), fuzzify.toString(), "MIN",
                rules + "    RULE 5001 : IF x4999 IS off THEN y IS a;\n");
        FunctionBlock raw = new org.fclcert.syntax.StrictReader().read("undefined.fcl", undefined).program().orElseThrow()
                .functionBlocks().get(0);
        assertEquals("term 'off' of 'x4999' is not defined",
                CoverageGaps.of(raw, raw.ruleBlocks().get(0)).notAnalysed().orElseThrow());
    }

    /**
     * The container crane of Annex C (rule 2's pos_big corrected to pos_high), its gaps derived by hand.
     *
     * <p>Where each term used by a rule is above 0 (FCL terms keep their outer degrees beyond the first and last
     * point): distance far (10,0)(22,1): d &gt; 10; medium (5,0)(10,1)(22,0): 5 &lt; d &lt; 22; close
     * (0,0)(5,1)(10,0): 0 &lt; d &lt; 10; zero (-5,0)(0,1)(5,0): -5 &lt; d &lt; 5. angle zero: -5 &lt; a &lt; 5;
     * neg_small (-50,0)(-5,1)(0,0): -50 &lt; a &lt; 0; neg_big (-50,1)(-5,0): a &lt; -5; pos_small (0,0)(5,1)(50,0):
     * 0 &lt; a &lt; 50. With AND MIN a rule fires exactly where both its terms are above 0:
     * R1 d&gt;10, -5&lt;a&lt;5; R2 d&gt;10, -50&lt;a&lt;0; R3 d&gt;10, a&lt;-5; R4 5&lt;d&lt;22, -50&lt;a&lt;0;
     * R5 0&lt;d&lt;10, 0&lt;a&lt;50; R6 -5&lt;d&lt;5, -5&lt;a&lt;5.
     *
     * <p>The angles no rule covers, slab by slab of distance:
     * <pre>
     * d &lt;= -5      : every a (no distance term above 0)
     * -5 &lt; d &lt;= 0  : a &lt;= -5 or a &gt;= 5        (R6 only; close(0) = 0)
     * 0 &lt; d &lt; 5    : a &lt;= -5 or a &gt;= 50       (R5 and R6: -5 &lt; a &lt; 50)
     * d = 5         : a &lt;= 0 or a &gt;= 50        (R5 only: zero(5) = medium(5) = 0)
     * 5 &lt; d &lt; 10   : a &lt;= -50, a = 0, a &gt;= 50 (R4 and R5 meet at a = 0, where both are 0)
     * d = 10        : a &lt;= -50 or a &gt;= 0       (R4 only: close(10) = far(10) = 0)
     * d &gt; 10        : a &gt;= 5                   (R1, R2, R3 cover a &lt; 5; R4 adds nothing new)
     * </pre>
     * Joined into boxes: a &lt;= -50 for every d &lt;= 10 (1); -50 &lt; a &lt;= -5 for d &lt;= 5 (2); a &gt; -5 for
     * d &lt;= -5 (3); the rest of d = 5, -5 &lt; a &lt;= 0 (4); a = 0 for 5 &lt; d &lt;= 10, a gap of zero width where
     * medium's R4 and close's R5 hand over (5); the rest of d = 10, a &gt; 0 (6); a &gt;= 5 for -5 &lt; d &lt;= 0 (7);
     * a &gt;= 5 for d &gt; 10 (8); a &gt;= 50 for 0 &lt; d &lt; 10 (9, where pos_small ends). Nine boxes, disjoint, and
     * their union is the table: checked below both as the list and point by point on the table's breakpoints and
     * between them.
     */
    @Test
    void theCraneOfAnnexCHasTheNineHandDerivedGaps() {
        Analysis analysis = Programs.analyzeResource("standard/crane_annex_c_corrected.fcl");
        FunctionBlock fb = analysis.program().orElseThrow().functionBlocks().get(0);
        CoverageGaps.Result result = CoverageGaps.of(fb, fb.ruleBlocks().get(0));
        assertEquals(List.of("distance", "angle"), result.inputs());
        assertEquals(0, result.undecidedCells());
        List<String> expected = List.of(
                "(-inf, 10] x (-inf, -50]",
                "(-inf, 5] x (-50, -5]",
                "(-inf, -5] x (-5, inf)",
                "= 5 x (-5, 0]",
                "(5, 10] x = 0",
                "= 10 x (0, inf)",
                "(-5, 0] x [5, inf)",
                "(10, inf) x [5, inf)",
                "(0, 10) x [50, inf)");
        List<String> found = result.gaps().stream()
                .map(b -> b.intervals().get(0) + " x " + b.intervals().get(1)).toList();
        assertEquals(new TreeSet<>(expected), new TreeSet<>(found), found.toString());
        assertEquals(expected.size(), found.size());
        double[] distances = {-9, -5, -2.5, 0, 2.5, 5, 7.5, 10, 16, 22, 30};
        double[] angles = {-70, -50, -27.5, -5, -2.5, 0, 2.5, 5, 27.5, 50, 70};
        for (double d : distances) {
            for (double a : angles) {
                long boxes = result.gaps().stream().filter(b -> b.intervals().get(0).contains(d)
                        && b.intervals().get(1).contains(a)).count();
                assertEquals(craneGapByHand(d, a) ? 1 : 0, boxes, "distance " + d + ", angle " + a);
            }
        }
        // check shows the first eight, in the analysis's order, and counts the ninth
        List<String> shown = messages(Programs.text("standard/crane_annex_c_corrected.fcl"));
        assertEquals(8, shown.size());
        assertTrue(shown.get(7).endsWith("power takes DEFAULT 0 (and 1 more such regions)"), shown.get(7));
    }

    /** The table of {@link #theCraneOfAnnexCHasTheNineHandDerivedGaps}, as written there. */
    private static boolean craneGapByHand(double d, double a) {
        if (d <= -5) {
            return true;
        }
        if (d <= 0) {
            return a <= -5 || a >= 5;
        }
        if (d < 5) {
            return a <= -5 || a >= 50;
        }
        if (d == 5) {
            return a <= 0 || a >= 50;
        }
        if (d < 10) {
            return a <= -50 || a == 0 || a >= 50;
        }
        if (d == 10) {
            return a <= -50 || a >= 0;
        }
        return a >= 5;
    }

    @Test
    void aCaseOfTheCorpusWhoseOneRuleLeavesTheLowerInputsUncovered() throws IOException {
        // E-COA-001: one rule 'a IS on', on := (0, 0) (1, 1): nothing fires for a <= 0, and y falls back to 0
        String text = Files.readString(Path.of("conformance/extension/E-COA-001.fcl"));
        assertEquals(List.of("a in (-inf, 0]: no rule of block 'r' fires; y takes DEFAULT 0"), messages(text));
    }

    /**
     * Every positive corpus case: inside each reported box the evaluator finds every rule of the block at 0, and at
     * sampled inputs outside all boxes some rule above 0 (unless the block has undecided cells).
     */
    @Test
    void onTheCorpusTheEvaluatorConfirmsEveryGapAndNoOther() throws IOException, EvaluationException {
        int programs = 0;
        int withGaps = 0;
        int blocksChecked = 0;
        List<Path> cases;
        try (Stream<Path> files = Stream.of("basic", "extension", "open").flatMap(CoverageGapsTest::list)) {
            cases = files.filter(p -> p.toString().endsWith(".fcl")).sorted().toList();
        }
        Random random = new Random(30);
        for (Path file : cases) {
            var analysis = Programs.analyze(file.toString(), Files.readString(file));
            if (analysis.program().isEmpty()) {
                continue;
            }
            programs++;
            Program program = analysis.program().get();
            boolean gaps = false;
            for (FunctionBlock fb : program.functionBlocks()) {
                for (RuleBlock rb : fb.ruleBlocks()) {
                    CoverageGaps.Result result = CoverageGaps.of(fb, rb);
                    if (!result.analysed()) {
                        continue;
                    }
                    blocksChecked++;
                    gaps |= !result.gaps().isEmpty();
                    confirm(program, fb, rb, result, random, file.toString());
                }
            }
            if (gaps) {
                withGaps++;
            }
        }
        assertTrue(programs > 100, "corpus read: " + programs);
        assertTrue(blocksChecked > 100, "blocks analysed: " + blocksChecked);
        System.out.println("coverage: " + withGaps + " of " + programs + " positive corpus programs have gaps");
    }

    private static Stream<Path> list(String dir) {
        try {
            return Files.list(Path.of("conformance", dir)).toList().stream();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static void confirm(Program program, FunctionBlock fb, RuleBlock rb, CoverageGaps.Result result,
            Random random, String file) throws EvaluationException {
        List<String> inputs = result.inputs();
        List<double[]> breaks = new ArrayList<>();
        for (String input : inputs) {
            TreeSet<Double> xs = new TreeSet<>(List.of(0.0, 1.0));
            for (Term t : fb.fuzzification(input).map(f -> f.terms()).orElse(List.of())) {
                if (t.function() instanceof MembershipFunction.Points p) {
                    for (Point pt : p.points()) {
                        xs.add(((Literal) pt.x()).value());
                    }
                } else if (t.function() instanceof MembershipFunction.Singleton s) {
                    xs.add(((Literal) s.value()).value());
                }
            }
            breaks.add(xs.stream().mapToDouble(Double::doubleValue).toArray());
        }
        FunctionBlockInstance instance = Evaluator.load(program).newInstance(fb.name());
        // inside each box: a point of it (its single value, its middle, or one beyond a finite end)
        for (CoverageGaps.Box box : result.gaps()) {
            double[] at = new double[inputs.size()];
            for (int a = 0; a < at.length; a++) {
                at[a] = inside(box.intervals().get(a));
            }
            if (!holds(fb, inputs, at)) {
                continue;       // the gap's chosen point is no value of the input's type
            }
            assertEquals(0.0, maxDegree(instance, fb, rb, inputs, at), file + ": a rule fires inside the gap "
                    + RulesCoverTheInputSpace.region(inputs, box));
        }
        if (result.undecidedCells() > 0) {
            return;
        }
        // outside: breakpoints, their neighbours and random values, in random combinations
        for (int trial = 0; trial < 400; trial++) {
            double[] at = new double[inputs.size()];
            for (int a = 0; a < at.length; a++) {
                double[] b = breaks.get(a);
                double lo = b[0] - 3;
                double hi = b[b.length - 1] + 3;
                int pick = random.nextInt(3);
                double r = random.nextDouble();
                // lo·(1 − r) + hi·r: hi − lo overflows for terms that span most of the doubles (O-DEGREES-0-1-071)
                at[a] = pick == 0 ? b[random.nextInt(b.length)] : lo * (1 - r) + hi * r;
                // a value the input's type holds (an integer type stores others rounded; outside its range, or
                // REAL's, it refuses them: FCL-V004)
                DataType type = fb.variable(inputs.get(a)).orElseThrow().type();
                double v = type.isInteger() ? Math.rint(at[a]) : at[a];
                at[a] = Math.max(type.min(), Math.min(type.max(), v));
            }
            boolean inGap = result.gaps().stream().anyMatch(box -> contains(box, at));
            double degree = maxDegree(instance, fb, rb, inputs, at);
            if (inGap) {
                assertEquals(0.0, degree, file + ": a rule fires at " + java.util.Arrays.toString(at));
            } else {
                assertTrue(degree > 0, file + ": no rule of " + rb.name() + " fires at " + inputs + " = "
                        + java.util.Arrays.toString(at) + ", outside every reported gap");
            }
        }
    }

    /** Whether every value is one its input's data type holds as it is (in its range; integer types: whole). */
    private static boolean holds(FunctionBlock fb, List<String> inputs, double[] at) {
        for (int a = 0; a < at.length; a++) {
            DataType type = fb.variable(inputs.get(a)).orElseThrow().type();
            if (!(at[a] >= type.min() && at[a] <= type.max()) || type.isInteger() && at[a] != Math.rint(at[a])) {
                return false;
            }
        }
        return true;
    }

    private static double inside(CoverageGaps.Interval in) {
        if (in.point()) {
            return in.low();
        }
        if (Double.isInfinite(in.low()) && Double.isInfinite(in.high())) {
            return 0.5;
        }
        if (Double.isInfinite(in.low())) {
            return in.high() - 1;
        }
        if (Double.isInfinite(in.high())) {
            return in.low() + 1;
        }
        return (in.low() + in.high()) / 2;
    }

    private static boolean contains(CoverageGaps.Box box, double[] at) {
        for (int a = 0; a < at.length; a++) {
            if (!box.intervals().get(a).contains(at[a])) {
                return false;
            }
        }
        return true;
    }

    private static double maxDegree(FunctionBlockInstance instance, FunctionBlock fb, RuleBlock rb,
            List<String> inputs, double[] at) throws EvaluationException {
        instance.reset();
        for (var v : fb.variables(VariableKind.INPUT)) {
            instance.set(v.name(), 0.5);
        }
        for (int a = 0; a < at.length; a++) {
            instance.set(inputs.get(a), at[a]);
        }
        Trace trace = new Trace();
        try {
            instance.evaluate(trace);
        } catch (EvaluationException e) {
            // an output beyond its type or an unbounded set (B-FB-151, E-TERM-VARIABLE-POINT-151: steps that must be
            // refused): the error comes after the rules ran, and the trace holds their degrees
            if (!e.diagnosticCode().causedByTheProgram()) {
                throw e;
            }
        }
        return trace.ruleDegrees().stream().filter(d -> d.ruleBlock().equalsIgnoreCase(rb.name()))
                .mapToDouble(Trace.RuleDegree::degree).max().orElse(0);
    }
}
