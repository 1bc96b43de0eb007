package org.fclcert.eval;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.eval.BlockPlan.RuleBlockPlan;
import org.fclcert.eval.BlockPlan.SubconclusionPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DataType;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Hedge;
import org.fclcert.model.OrAlgorithm;

/**
 * The exact judging path: one function block instance evaluated in exact rational arithmetic on the program's
 * literals and inputs as {@link NumberReading} reads them (docs/semantics.md, point 10). Same semantics, plan
 * and public surface as {@link FunctionBlockInstance} (set, get, outputs, evaluate, reset), but every decision
 * (a clip crossing, a tie for LM/RM/MoM, whether anything fired, NOT of exactly 1, the .5 of an integer output,
 * CoA's halfway point) is decided exactly. Results are rounded to the nearest double only when read.
 *
 * <p>Not exact, and said so by {@link #exact()}: the Open Level constructs outside rational arithmetic — a
 * smooth named shape's degree (exp, powers: computed in double and then taken exactly) and outputs whose set is
 * not piece-wise linear (smooth shapes, PROBOR on point terms: {@link SmoothSet} on doubles). The square roots
 * of the hedges somewhat and seldom are computed to 60 significant digits.
 *
 * <p>Slower than the reference's doubles (every number a fraction of BigIntegers); the reference evaluator's
 * fallback where its error bounds cannot settle a decision, and the judge of corpus replay,
 * probing, fuzzing, certification of the reference. Not thread-safe.
 */
public final class ExactInstance {
    private static final Hedge[] HEDGES = Hedge.values();

    private final BlockPlan plan;
    private final NumberReading reading;
    /** Current values; null is NaN (only a {@code DEFAULT := nan} of the fuzzylite dialect stores it). */
    private final Rational[] values;
    private final Rational[] initial;
    private final Rational[][] curX;
    private final Rational[][] curY;
    private final Rational[][] constX;
    private final Rational[][] constY;
    private final Rational[] termDegrees;
    private final Rational[] contributionDegree;
    private final Rational[] contributionWeight;
    private final Rational[] rangeMin;
    private final Rational[] rangeMax;
    private final Rational[] defaults;
    private final Rational[] previous;
    /** Per output: nothing fired in the last evaluation (DEFAULT or NC). */
    private final boolean[] defaulted;
    /** Per output: the last value before its conversion to the output's data type (the trace shows the rounding). */
    private final Rational[] computed;
    private final ExactSet set = new ExactSet();
    private final SmoothSet[] smoothSets;
    private boolean exact = true;
    /** Per slot: the last value stored was rounded to an integer type from (within 1e-9 of) a half-integer. */
    private final boolean[] nearHalf;
    private final boolean[] exactHalf;
    private final Map<Double, Rational> weights = new java.util.HashMap<>();

    ExactInstance(BlockPlan plan, NumberReading reading) {
        // dialect constructs only the double computation evaluates: refused, never computed wrong
        if (plan.chainedTerms > 0 || plan.contributionHedges.length > 0
                || java.util.Arrays.stream(plan.shapes).anyMatch(sh -> sh.computed != null)
                || java.util.Arrays.stream(plan.outputs).anyMatch(o -> o.method() == DefuzzificationMethod.TSUKAMOTO
                        || java.util.Arrays.stream(o.contributionActivation()).anyMatch(a -> !a.standard()))) {
            throw new IllegalArgumentException("the exact path does not evaluate Takagi-Sugeno terms, hedges in"
                    + " conclusions, output terms in conditions, Tsukamoto's method or activations outside Table 4"
                    + " (dialect constructs); the reference evaluator does");
        }
        this.plan = plan;
        this.reading = reading;
        int nv = plan.initialValues.length;
        this.initial = new Rational[nv];
        for (int i = 0; i < nv; i++) {
            initial[i] = reading.read(plan.initialValues[i]);
        }
        this.values = initial.clone();
        this.nearHalf = new boolean[nv];
        this.exactHalf = new boolean[nv];
        int shapes = plan.shapes.length;
        curX = new Rational[shapes][];
        curY = new Rational[shapes][];
        constX = new Rational[shapes][];
        constY = new Rational[shapes][];
        for (int s = 0; s < shapes; s++) {
            Shape shape = plan.shapes[s];
            constX[s] = new Rational[shape.n];
            constY[s] = new Rational[shape.n];
            for (int i = 0; i < shape.n; i++) {
                constX[s][i] = reading.read(shape.xConst[i]);
                constY[s][i] = reading.read(shape.yConst[i]).clamp01();
            }
            curX[s] = new Rational[shape.n];
            curY[s] = new Rational[shape.n];
            if (shape.constant) {
                resolve(s);
            }
        }
        termDegrees = new Rational[plan.termShape.length];
        contributionDegree = new Rational[plan.contributionCount];
        contributionWeight = new Rational[plan.contributionCount];
        java.util.Arrays.fill(contributionDegree, Rational.ZERO);
        java.util.Arrays.fill(contributionWeight, Rational.ZERO);
        int no = plan.outputs.length;
        rangeMin = new Rational[no];
        rangeMax = new Rational[no];
        defaults = new Rational[no];
        previous = new Rational[no];
        defaulted = new boolean[no];
        computed = new Rational[no];
        smoothSets = new SmoothSet[no];
        for (int i = 0; i < no; i++) {
            OutputPlan o = plan.outputs[i];
            rangeMin[i] = reading.read(o.rangeMin());
            rangeMax[i] = reading.read(o.rangeMax());
            defaults[i] = Double.isNaN(o.defaultValue()) ? null : reading.read(o.defaultValue());
            smoothSets[i] = plan.smoothOutputs[i] ? new SmoothSet() : null;
            if (smoothSets[i] != null) {
                exact = false;
            }
        }
        for (Shape s : plan.shapes) {
            exact &= s.kind == null;
        }
    }

    /** Whether every step of this block is exact (false for smooth shapes and PROBOR point outputs). */
    public boolean exact() {
        return exact;
    }

    public NumberReading reading() {
        return reading;
    }

    public String functionBlockName() {
        return plan.name;
    }

    public List<String> inputNames() {
        return plan.inputNames;
    }

    public List<String> outputNames() {
        return plan.outputNames;
    }

    /** Sets an input (case-insensitive); integer-typed inputs take the value rounded half away from zero. */
    public void set(String name, double value) throws EvaluationException {
        store(plan.inputSlot(name, value), reading.read(value));
    }

    /** The current value of a variable, rounded to the nearest double. */
    public double get(String name) throws EvaluationException {
        return toDouble(values[plan.slot(name)]);
    }

    /**
     * Whether the output's last value was rounded to its integer type from a value within 1e-9 (relative above
     * 1) of a half-integer but not exactly one: a rounding decision that the last bits of any floating-point
     * computation decide.
     */
    boolean roundedNearHalf(String name) throws EvaluationException {
        return nearHalf[plan.slot(name)];
    }

    /** Whether the output's last value was rounded to its integer type from exactly a half-integer. */
    boolean roundedFromExactHalf(String name) throws EvaluationException {
        return exactHalf[plan.slot(name)];
    }

    private static final Rational HALF_BAND = Rational.of(java.math.BigInteger.ONE, java.math.BigInteger.TEN.pow(9));

    private static boolean nearHalfInteger(Rational v) {
        Rational a = v.abs();
        Rational frac = a.subtract(Rational.of(a.num.divide(a.den), java.math.BigInteger.ONE));
        Rational off = frac.subtract(Rational.HALF).abs();
        // exactly .5 is decided by the exact rounding; FairVectors' double-arithmetic run tells whether doubles miss it
        return off.signum() != 0 && off.compareTo(HALF_BAND.multiply(a.max(Rational.ONE))) <= 0;
    }

    /** The exact current value of a variable (null for NaN). */
    Rational exactValue(String name) throws EvaluationException {
        return values[plan.slot(name)];
    }

    /** VAR_OUTPUT values in declaration order, each the double nearest to the exact value. */
    public Map<String, Double> outputs() {
        Map<String, Double> out = new LinkedHashMap<>();
        for (int i = 0; i < plan.outputSlots.length; i++) {
            out.put(plan.outputNames.get(i), toDouble(values[plan.outputSlots[i]]));
        }
        return Collections.unmodifiableMap(out);
    }

    public void reset() {
        System.arraycopy(initial, 0, values, 0, values.length);
    }

    private static double toDouble(Rational r) {
        return r == null ? Double.NaN : r.toDouble();
    }

    /**
     * One evaluation from the given state (every variable's value as a double, NaN for none), as the filtered
     * evaluator hands over a step it cannot decide: each value read as {@link #reading()} reads it.
     */
    void evaluateFrom(double[] state) throws EvaluationException {
        for (int i = 0; i < state.length; i++) {
            values[i] = Double.isNaN(state[i]) ? null : reading.read(state[i]);
        }
        evaluate();
    }

    /** Writes the current values, each the double nearest the exact value, into {@code into} (inputs skipped). */
    void copyState(double[] into, boolean[] isInput) {
        for (int i = 0; i < into.length; i++) {
            if (!isInput[i]) {
                into[i] = toDouble(values[i]);
            }
        }
    }

    /** The last evaluation's results as a trace records them: each output's value and how it got it. */
    List<Trace.Result> results() {
        List<Trace.Result> out = new ArrayList<>();
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            for (int slot : rb.bareTargetSlots()) {
                out.add(new Trace.Result(plan.variableNames[slot], toDouble(values[slot]), Trace.Outcome.ASSIGNED));
            }
        }
        for (int i = 0; i < plan.outputs.length; i++) {
            OutputPlan o = plan.outputs[i];
            Trace.Outcome outcome = !defaulted[i] ? Trace.Outcome.DEFUZZIFIED
                    : o.noChange() ? Trace.Outcome.NO_CHANGE : Trace.Outcome.DEFAULT;
            out.add(new Trace.Result(o.variable(), toDouble(values[o.slot()]), outcome, toDouble(computed[i])));
        }
        return out;
    }

    public void evaluate() throws EvaluationException {
        for (int i = 0; i < plan.outputs.length; i++) {
            previous[i] = values[plan.outputs[i].slot()];
        }
        for (int s = 0; s < plan.shapes.length; s++) {
            if (!plan.shapes[s].constant) {
                resolve(s);
            }
        }
        fuzzify();
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            runRuleBlock(rb);
        }
        for (int i = 0; i < plan.outputs.length; i++) {
            defuzzify(i);
        }
    }

    private Rational store(int slot, Rational value) throws EvaluationException {
        if (value == null) {
            values[slot] = null;
            return null;
        }
        DataType type = plan.types[slot];
        Rational v = type.isInteger() ? value.roundHalfAwayFromZero() : value;
        nearHalf[slot] = type.isInteger() && nearHalfInteger(value);
        exactHalf[slot] = type.isInteger() && !value.den.equals(java.math.BigInteger.ONE)
                && value.den.equals(java.math.BigInteger.TWO);
        if (v.compareTo(Rational.exactly(type.min())) < 0 || v.compareTo(Rational.exactly(type.max())) > 0) {
            throw new EvaluationException(EvaluationCode.OUT_OF_RANGE, "value " + value.toDouble() + " of '"
                    + plan.variableNames[slot] + "' does not fit its data type " + type);
        }
        values[slot] = v;
        return v;
    }

    private Rational value(int slot) {
        Rational v = values[slot];
        return v == null ? Rational.ZERO : v;
    }

    /** The current points of shape s, degrees clamped to [0, 1], stably sorted by x (point 1). */
    private void resolve(int s) {
        Shape shape = plan.shapes[s];
        Rational[] x = curX[s];
        Rational[] y = curY[s];
        for (int i = 0; i < shape.n; i++) {
            x[i] = shape.xSlot[i] < 0 ? constX[s][i] : value(shape.xSlot[i]);
            y[i] = shape.ySlot[i] < 0 ? constY[s][i] : value(shape.ySlot[i]).clamp01();
        }
        if (!shape.singleton) {
            for (int i = 1; i < shape.n; i++) {
                Rational xi = x[i];
                Rational yi = y[i];
                int j = i - 1;
                while (j >= 0 && x[j].compareTo(xi) > 0) {
                    x[j + 1] = x[j];
                    y[j + 1] = y[j];
                    j--;
                }
                x[j + 1] = xi;
                y[j + 1] = yi;
            }
        }
    }

    private void fuzzify() {
        for (int t = 0; t < termDegrees.length; t++) {
            int s = plan.termShape[t];
            Rational u = value(plan.termVariableSlot[t]);
            Shape shape = plan.shapes[s];
            if (shape.singleton) {
                termDegrees[t] = u.equals(curX[s][0]) ? Rational.ONE : Rational.ZERO;
            } else if (shape.kind == null) {
                termDegrees[t] = degree(curX[s], curY[s], u);
            } else {
                termDegrees[t] = Rational.exactly(shape.kind.degree(shape.params, u.toDouble())).clamp01();
            }
        }
    }

    /** 5.2.2 on exact points: linear between points, outer degrees beyond, the largest degree at a shared x. */
    static Rational degree(Rational[] x, Rational[] y, Rational u) {
        int n = x.length;
        if (u.compareTo(x[0]) < 0) {
            return y[0];
        }
        if (u.compareTo(x[n - 1]) > 0) {
            return y[n - 1];
        }
        int i = 0;
        while (x[i].compareTo(u) < 0) {
            i++;
        }
        if (x[i].equals(u)) {
            Rational max = y[i];
            for (int j = i + 1; j < n && x[j].equals(u); j++) {
                max = max.max(y[j]);
            }
            return max;
        }
        return ExactSet.interpolate(x[i - 1], y[i - 1], x[i], y[i], u);
    }

    private void runRuleBlock(RuleBlockPlan rb) throws EvaluationException {
        int targets = rb.bareTargetSlots().length;
        Rational[] bare = new Rational[targets];
        java.util.Arrays.fill(bare, Rational.ZERO);
        ConditionCode[] conditions = rb.conditions();
        for (int r = 0; r < conditions.length; r++) {
            Rational d = aggregate(conditions[r], rb.and(), rb.or());
            for (SubconclusionPlan sc : rb.conclusions()[r]) {
                Rational w = sc.weightSlot() < 0 ? weights.computeIfAbsent(sc.weightConst(), reading::read)
                        : value(sc.weightSlot()).clamp01();
                if (sc.contribution() >= 0) {
                    contributionDegree[sc.contribution()] = d;
                    contributionWeight[sc.contribution()] = w;
                } else {
                    bare[sc.bareTarget()] = Norms.accumulate(rb.accumulation(), bare[sc.bareTarget()], w.multiply(d));
                }
            }
        }
        for (int j = 0; j < targets; j++) {
            Rational v = rb.accumulation() == AccumulationMethod.NSUM ? bare[j].divide(bare[j].max(Rational.ONE))
                    : bare[j];
            store(rb.bareTargetSlots()[j], v);
        }
    }

    private Rational aggregate(ConditionCode code, AndAlgorithm and, OrAlgorithm or) {
        int[] ops = code.ops;
        int[] args = code.args;
        Rational[] st = new Rational[Math.max(1, code.maxStack)];
        int sp = 0;
        for (int i = 0; i < ops.length; i++) {
            switch (ops[i]) {
                case ConditionCode.TERM -> st[sp++] = termDegrees[args[i]];
                case ConditionCode.TERM_NOT -> st[sp++] = Rational.ONE.subtract(termDegrees[args[i]]);
                case ConditionCode.VARIABLE -> st[sp++] = value(args[i]).clamp01();
                case ConditionCode.NOT -> st[sp - 1] = Rational.ONE.subtract(st[sp - 1]);
                case ConditionCode.HEDGE -> st[sp - 1] = Norms.hedge(HEDGES[args[i]], st[sp - 1]);
                case ConditionCode.ONE -> st[sp++] = Rational.ONE;
                default -> {
                    boolean isAnd = ops[i] == ConditionCode.AND;
                    int base = sp - args[i];
                    Rational acc = st[base];
                    for (int j = base + 1; j < sp; j++) {
                        acc = isAnd ? Norms.and(and, acc, st[j]) : Norms.or(or, acc, st[j]);
                    }
                    st[base] = acc;
                    sp = base + 1;
                }
            }
        }
        return st[0];
    }

    // ------------------------------------------------------------------------------------ defuzzification

    private void defuzzify(int i) throws EvaluationException {
        OutputPlan o = plan.outputs[i];
        Rational result;
        boolean empty;
        if (o.singletons()) {
            result = singletons(o);
            empty = result == null;
        } else if (smoothSets[i] != null) {
            double r = smooth(o, smoothSets[i]);
            empty = smoothSets[i].empty();
            if (Double.isNaN(r) && !empty || Double.isInfinite(r)) {
                throw new EvaluationException(EvaluationCode.NO_RESULT,
                        "defuzzification of '" + o.variable() + "' has no numeric result (the arithmetic overflowed)");
            }
            result = empty ? null : Rational.exactly(r);
        } else {
            result = pointSet(o, i);
            empty = result == null;
        }
        defaulted[i] = empty;
        if (empty) {
            result = o.noChange() ? previous[i] : defaults[i];
        }
        computed[i] = result;
        store(o.slot(), result);
    }

    private Rational singletons(OutputPlan o) {
        int terms = o.termShapes().length;
        Rational[] degree = new Rational[terms];
        Rational[] value = new Rational[terms];
        for (int t = 0; t < terms; t++) {
            degree[t] = Rational.ZERO;
            value[t] = curX[o.termShapes()[t]][0];
        }
        int[] cs = o.contributions();
        for (int k = 0; k < cs.length; k++) {
            int t = o.contributionTerm()[k];
            degree[t] = Norms.accumulate(o.accumulation(), degree[t],
                    contributionWeight[cs[k]].multiply(contributionDegree[cs[k]]));
        }
        if (o.accumulation() == AccumulationMethod.NSUM) {
            Rational max = Rational.ONE;
            for (Rational d : degree) {
                max = max.max(d);
            }
            for (int t = 0; t < terms; t++) {
                degree[t] = degree[t].divide(max);
            }
        }
        Rational sup = Rational.ZERO;
        for (Rational d : degree) {
            sup = sup.max(d);
        }
        if (sup.signum() <= 0) {
            return null;
        }
        DefuzzificationMethod m = o.method();
        if (m == DefuzzificationMethod.LM || m == DefuzzificationMethod.RM) {
            Rational best = null;
            for (int t = 0; t < terms; t++) {
                if (degree[t].equals(sup) && (best == null
                        || (m == DefuzzificationMethod.LM ? value[t].compareTo(best) < 0 : value[t].compareTo(best) > 0))) {
                    best = value[t];
                }
            }
            return best;
        }
        if (m == DefuzzificationMethod.MOM) {
            List<Rational> distinct = new ArrayList<>();
            for (int t = 0; t < terms; t++) {
                if (degree[t].equals(sup) && !distinct.contains(value[t])) {
                    distinct.add(value[t]);
                }
            }
            Rational sum = Rational.ZERO;
            for (Rational v : distinct) {
                sum = sum.add(v);
            }
            return sum.divide(Rational.of(distinct.size()));
        }
        Rational num = Rational.ZERO;
        Rational den = Rational.ZERO;
        for (int t = 0; t < terms; t++) {
            num = num.add(value[t].multiply(degree[t]));
            den = den.add(degree[t]);
        }
        return m == DefuzzificationMethod.COGSS ? num : num.divide(den);
    }

    private List<ExactSet.Contribution> fired(OutputPlan o) {
        List<ExactSet.Contribution> out = new ArrayList<>();
        int[] cs = o.contributions();
        for (int k = 0; k < cs.length; k++) {
            Rational d = contributionDegree[cs[k]];
            Rational w = contributionWeight[cs[k]];
            if (d.multiply(w).signum() > 0) {
                int s = o.termShapes()[o.contributionTerm()[k]];
                out.add(new ExactSet.Contribution(curX[s], curY[s], d, w, o.contributionProd()[k]));
            }
        }
        return out;
    }

    private Rational pointSet(OutputPlan o, int i) throws EvaluationException {
        List<ExactSet.Contribution> cs = fired(o);
        Rational lo = rangeMin[i];
        Rational hi = rangeMax[i];
        if (!o.hasRange()) {
            lo = null;
            hi = null;
            for (int s : o.termShapes()) {
                Rational[] x = curX[s];
                lo = lo == null ? x[0] : lo.min(x[0]);
                hi = hi == null ? x[x.length - 1] : hi.max(x[x.length - 1]);
            }
            for (ExactSet.Contribution c : cs) {
                Rational[] y = c.y();
                if (y[0].signum() > 0 || y[y.length - 1].signum() > 0) {
                    throw EvaluationException.unbounded(o.variable(), y[0].signum() > 0 ? c.x()[0].toDouble()
                            : c.x()[y.length - 1].toDouble());
                }
            }
        }
        set.build(o.accumulation(), lo, hi, cs);
        return switch (o.method()) {
            case COA -> set.centreOfArea();
            case LM -> set.extremeMaximum(true);
            case RM -> set.extremeMaximum(false);
            case MOM -> set.meanOfMaximum();
            case COGSS -> throw new AssertionError("COGSS on a point set: BlockCompiler admits it only on singletons");
            default -> set.centreOfGravity();
        };
    }

    private double smooth(OutputPlan o, SmoothSet smooth) {
        smooth.act.clear();
        int[] cs = o.contributions();
        for (int k = 0; k < cs.length; k++) {
            Rational d = contributionDegree[cs[k]];
            Rational w = contributionWeight[cs[k]];
            if (d.multiply(w).signum() > 0) {
                smooth.act.add(o.termShapes()[o.contributionTerm()[k]], d.toDouble(), w.toDouble(),
                        o.contributionProd()[k]);
            }
        }
        int shapes = plan.shapes.length;
        double[][] dx = new double[shapes][];
        double[][] dy = new double[shapes][];
        for (int s = 0; s < shapes; s++) {
            dx[s] = new double[curX[s].length];
            dy[s] = new double[curY[s].length];
            for (int k = 0; k < dx[s].length; k++) {
                dx[s][k] = curX[s][k].toDouble();
                dy[s][k] = curY[s][k].toDouble();
            }
        }
        return smooth.defuzzify(o.method(), o.accumulation(), o.rangeMin(), o.rangeMax(), plan.shapes, dx, dy);
    }
}
