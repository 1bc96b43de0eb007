package org.fclcert.eval;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.eval.BlockPlan.RuleBlockPlan;
import org.fclcert.eval.BlockPlan.SubconclusionPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DataType;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;

/**
 * One instance of a fuzzy function block (IEC 61131-3 instance semantics): it keeps its variable
 * values between evaluations, so unset inputs keep their last value and DEFAULT NC keeps the last
 * output. Not thread-safe; create one instance per thread. {@link #evaluate()} does no name lookup
 * and allocates nothing once its scratch arrays have grown to the program's needs.
 */
public final class FunctionBlockInstance {
    private final BlockPlan plan;
    private final double[] values;
    private final double[] termDegrees;
    private final double[][] curX;
    private final double[][] curY;
    private final double[] stack;
    private final double[] bare;
    private final double[] contributionDegree;
    private final double[] contributionWeight;
    private final double[] singletonDegree;
    private final double[] singletonValue;
    private final SetBuilder set = new SetBuilder();
    /** Per output: the smooth-set integrator when its set is not piece-wise linear, else null. */
    private final SmoothSet[] smoothSets;
    private static final org.fclcert.model.Hedge[] HEDGES = org.fclcert.model.Hedge.values();
    /**
     * Per output: its value when this evaluation began, which DEFAULT NC keeps (point 6) even when a bare
     * conclusion on the same variable wrote to it during the rule blocks.
     */
    private final double[] previous;
    /** Shapes with points from variables, re-read at each evaluation. */
    private final int[] variableShapes;

    FunctionBlockInstance(BlockPlan plan) {
        this.plan = plan;
        this.values = plan.initialValues.clone();
        this.termDegrees = new double[plan.termShape.length + plan.chainedTerms];
        int shapes = plan.shapes.length;
        this.curX = new double[shapes][];
        this.curY = new double[shapes][];
        for (int s = 0; s < shapes; s++) {
            Shape shape = plan.shapes[s];
            curX[s] = shape.constant ? shape.sortedX : new double[shape.n];
            curY[s] = shape.constant ? shape.sortedY : new double[shape.n];
        }
        this.variableShapes = java.util.stream.IntStream.range(0, shapes)
                .filter(s -> !plan.shapes[s].constant).toArray();
        this.stack = new double[plan.maxStack];
        this.bare = new double[Math.max(1, plan.maxBareTargets)];
        int terms = 0;
        for (OutputPlan o : plan.outputs) {
            terms = Math.max(terms, o.termShapes().length);
        }
        this.contributionDegree = new double[plan.contributionCount];
        this.contributionWeight = new double[plan.contributionCount];
        this.singletonDegree = new double[terms];
        this.singletonValue = new double[terms];
        this.previous = new double[plan.outputs.length];
        this.smoothSets = new SmoothSet[plan.outputs.length];
        for (int i = 0; i < smoothSets.length; i++) {
            smoothSets[i] = plan.smoothOutputs[i] ? new SmoothSet() : null;
        }
    }

    /** The function block's name as declared. */
    public String functionBlockName() {
        return plan.name;
    }

    /** VAR_INPUT names in declaration order. */
    public List<String> inputNames() {
        return plan.inputNames;
    }

    /** VAR_OUTPUT names in declaration order. */
    public List<String> outputNames() {
        return plan.outputNames;
    }

    /**
     * Sets an input (case-insensitive name). Integer-typed inputs take the value rounded half away
     * from zero.
     */
    public void set(String name, double value) throws EvaluationException {
        int slot = slot(name);
        if (!plan.isInput[slot]) {
            throw new EvaluationException(EvaluationCode.NOT_AN_INPUT,
                    "'" + plan.variableNames[slot] + "' is not a VAR_INPUT and cannot be set");
        }
        if (!Double.isFinite(value)) {
            throw new EvaluationException(EvaluationCode.NOT_FINITE,
                    "input '" + plan.variableNames[slot] + "' must be a finite number, not " + value);
        }
        store(slot, value);
    }

    /** The current value of any variable (input, output or local), by case-insensitive name. */
    public double get(String name) throws EvaluationException {
        return values[slot(name)];
    }

    /** VAR_OUTPUT values in declaration order, names as declared. */
    public Map<String, Double> outputs() {
        Map<String, Double> out = new LinkedHashMap<>();
        for (int i = 0; i < plan.outputSlots.length; i++) {
            out.put(plan.outputNames.get(i), values[plan.outputSlots[i]]);
        }
        return Collections.unmodifiableMap(out);
    }

    /** Back to the state of a fresh instance: every variable at its declared initial value, else 0. */
    public void reset() {
        System.arraycopy(plan.initialValues, 0, values, 0, values.length);
    }

    public void evaluate() throws EvaluationException {
        evaluate(null);
    }

    /** One evaluation: fuzzification, the rule blocks in textual order, then defuzzification. */
    public void evaluate(Trace trace) throws EvaluationException {
        if (trace != null) {
            trace.clear();
        }
        for (int i = 0; i < plan.outputs.length; i++) {
            previous[i] = values[plan.outputs[i].slot()];
        }
        resolveVariableShapes();
        fuzzify(trace);
        for (int t = plan.termShape.length; t < termDegrees.length; t++) {
            termDegrees[t] = 0.0;           // 'output IS term' (dialects): nothing concluded yet
        }
        if (plan.valueTermShape != null) {
            valueConditions();
        }
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            runRuleBlock(rb, trace);
        }
        for (int i = 0; i < plan.outputs.length; i++) {
            defuzzify(plan.outputs[i], previous[i], smoothSets[i], trace);
        }
    }

    private int slot(String name) throws EvaluationException {
        Integer slot = plan.slotByName.get(name);
        if (slot == null) {
            slot = plan.slotByName.get(Names.key(name));
        }
        if (slot == null) {
            throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                    "function block '" + plan.name + "' has no variable '" + name + "'");
        }
        return slot;
    }

    /** Writes a value, converting to the variable's integer type (8.: half away from zero). */
    private double store(int slot, double value) throws EvaluationException {
        DataType type = plan.types[slot];
        double v = type.isInteger() ? Conversions.roundHalfAwayFromZero(value) : value;
        if (v < type.min() || v > type.max()) {
            throw new EvaluationException(EvaluationCode.OUT_OF_RANGE, "value " + value + " of '"
                    + plan.variableNames[slot] + "' does not fit its data type " + type);
        }
        values[slot] = v;
        return v;
    }

    private void resolveVariableShapes() {
        for (int s : variableShapes) {
            plan.shapes[s].resolve(values, curX[s], curY[s]);
        }
    }

    /** 5.2.2: the degree of every term of every fuzzified input. */
    private void fuzzify(Trace trace) {
        int[] termShape = plan.termShape;
        for (int t = 0; t < termShape.length; t++) {
            int s = termShape[t];
            double u = values[plan.termVariableSlot[t]];
            Shape shape = plan.shapes[s];
            termDegrees[t] = shape.singleton ? (u == curX[s][0] ? 1.0 : 0.0)
                    : shape.kind == null ? Pwl.degree(curX[s], curY[s], shape.n, u) : shape.kind.degree(shape.params, u);
            if (trace != null) {
                trace.add(new Trace.TermDegree(plan.termVariableName[t], plan.termName[t], termDegrees[t]));
            }
        }
    }

    /**
     * jFuzzyLogic's 'output IS term' in a condition: the term's degree at the output's value when the evaluation
     * begins, which is its numeric DEFAULT (jFuzzyLogic resets it so before the rules) or, with DEFAULT NC, the value
     * of the last evaluation.
     */
    private void valueConditions() {
        for (int k = 0; k < plan.valueTermShape.length; k++) {
            double u = Double.isNaN(plan.valueTermStart[k]) ? values[plan.valueTermSlot[k]] : plan.valueTermStart[k];
            int s = plan.valueTermShape[k];
            Shape shape = plan.shapes[s];
            termDegrees[plan.termShape.length + k] = shape.singleton ? (u == curX[s][0] ? 1.0 : 0.0)
                    : shape.kind == null ? Pwl.degree(curX[s], curY[s], shape.n, u) : shape.kind.degree(shape.params, u);
        }
    }

    /**
     * Aggregation and activation of one rule block. Every condition reads the values as they were
     * when the block started: bare-variable conclusions are collected and written at the end.
     */
    private void runRuleBlock(RuleBlockPlan rb, Trace trace) throws EvaluationException {
        int targets = rb.bareTargetSlots().length;
        for (int j = 0; j < targets; j++) {
            bare[j] = 0;
        }
        ConditionCode[] conditions = rb.conditions();
        for (int r = 0; r < conditions.length; r++) {
            double d = aggregate(conditions[r], rb.and(), rb.or());
            double ruleDegree = d;
            if (trace != null) {
                trace.add(new Trace.RuleDegree(rb.name(), rb.ruleNames()[r], d));
            }
            for (SubconclusionPlan sc : rb.conclusions()[r]) {
                org.fclcert.model.Hedge[] hedged = sc.contribution() < 0 || plan.contributionHedges.length == 0 ? null
                        : plan.contributionHedges[sc.contribution()];
                d = hedged == null ? ruleDegree : org.fclcert.model.Hedge.applyAll(java.util.List.of(hedged), ruleDegree);
                double w = sc.weightSlot() < 0 ? sc.weightConst() : clamp01(values[sc.weightSlot()]);
                if (sc.contribution() >= 0) {
                    contributionDegree[sc.contribution()] = d;
                    contributionWeight[sc.contribution()] = w;
                    int chained = plan.chainedDegree.length == 0 ? -1 : plan.chainedDegree[sc.contribution()];
                    if (chained >= 0) {
                        termDegrees[chained] = accumulate(plan.chainedAccumulation[sc.contribution()],
                                termDegrees[chained], w * d);
                    }
                } else {
                    bare[sc.bareTarget()] = accumulate(rb.accumulation(), bare[sc.bareTarget()], w * d);
                }
                if (trace != null) {
                    trace.add(new Trace.Activation(rb.name(), rb.ruleNames()[r], sc.variable(),
                            Optional.ofNullable(sc.term()), w, w * d));
                }
            }
        }
        for (int j = 0; j < targets; j++) {
            double v = rb.accumulation() == AccumulationMethod.NSUM ? bare[j] / Math.max(1.0, bare[j]) : bare[j];
            int slot = rb.bareTargetSlots()[j];
            double stored = store(slot, v);
            if (trace != null) {
                trace.add(new Trace.Result(plan.variableNames[slot], stored, Trace.Outcome.ASSIGNED));
            }
        }
    }

    /** Table 5 applied to two degrees; NSUM sums here and normalises once all are summed. */
    private static double accumulate(AccumulationMethod accu, double a, double b) {
        return switch (accu) {
            case MAX -> Math.max(a, b);
            case BSUM -> Math.min(1.0, a + b);
            case NSUM, SUM -> a + b;
            case PROBOR -> a == 1.0 || b == 1.0 ? 1.0 : a + b - a * b;
            case ESUM -> or(OrAlgorithm.ESUM, a, b);
            case HSUM -> or(OrAlgorithm.HSUM, a, b);
            case DSUM -> or(OrAlgorithm.DSUM, a, b);
            case NMAX -> or(OrAlgorithm.NMAX, a, b);
        };
    }

    /** Runs a condition's postfix code (Table 3 operators; NOT = 1 − a). */
    private double aggregate(ConditionCode code, AndAlgorithm and, OrAlgorithm or) {
        int[] ops = code.ops;
        int[] args = code.args;
        double[] st = stack;
        int sp = 0;
        for (int i = 0; i < ops.length; i++) {
            switch (ops[i]) {
                case ConditionCode.TERM -> st[sp++] = termDegrees[args[i]];
                case ConditionCode.TERM_NOT -> st[sp++] = 1.0 - termDegrees[args[i]];
                case ConditionCode.VARIABLE -> st[sp++] = clamp01(values[args[i]]);
                case ConditionCode.NOT -> st[sp - 1] = 1.0 - st[sp - 1];
                case ConditionCode.AND -> sp = fold(st, sp, args[i], true, and, or);
                case ConditionCode.HEDGE -> st[sp - 1] = HEDGES[args[i]].apply(st[sp - 1]);
                case ConditionCode.ONE -> st[sp++] = 1.0;
                default -> sp = fold(st, sp, args[i], false, and, or);
            }
        }
        return st[0];
    }

    private static int fold(double[] st, int sp, int n, boolean isAnd, AndAlgorithm and, OrAlgorithm or) {
        int base = sp - n;
        double acc = st[base];
        for (int j = base + 1; j < sp; j++) {
            acc = isAnd ? and(and, acc, st[j]) : or(or, acc, st[j]);
        }
        st[base] = acc;
        return base + 1;
    }

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

    private static double clamp01(double v) {
        return Math.max(0.0, Math.min(1.0, v));
    }

    /** Accumulation and defuzzification of one output, or DEFAULT / NC when nothing fired. */
    private void defuzzify(OutputPlan o, double previousValue, SmoothSet smooth, Trace trace)
            throws EvaluationException {
        for (int s : o.termShapes()) {
            if (plan.shapes[s].computed != null) {      // Takagi–Sugeno: the value now, after the outputs before it
                plan.shapes[s].resolve(values, curX[s], curY[s]);
            }
        }
        double result = o.singletons() ? singletons(o, trace)
                : o.method() == DefuzzificationMethod.TSUKAMOTO ? tsukamoto(o, trace)
                : smooth != null ? smoothSet(o, smooth, trace) : pointSet(o, trace);
        Trace.Outcome outcome = Trace.Outcome.DEFUZZIFIED;
        if (Double.isNaN(result) && !(smooth != null ? smooth.empty() : nothingFired(o))) {
            throw new EvaluationException(EvaluationCode.NO_RESULT,
                    "defuzzification of '" + o.variable() + "' has no numeric result (the arithmetic overflowed)");
        }
        if (Double.isNaN(result)) {
            outcome = o.noChange() ? Trace.Outcome.NO_CHANGE : Trace.Outcome.DEFAULT;
            result = o.noChange() ? previousValue : o.defaultValue();
        }
        boolean nanDefault = Double.isNaN(result) && outcome == Trace.Outcome.DEFAULT;   // DEFAULT := nan (fuzzylite)
        if (!Double.isFinite(result) && !nanDefault) {
            throw new EvaluationException(EvaluationCode.NO_RESULT,
                    "defuzzification of '" + o.variable() + "' overflowed (result " + result + ")");
        }
        double stored = store(o.slot(), result);
        if (trace != null) {
            trace.add(new Trace.Result(o.variable(), stored, outcome, result));
        }
    }

    /**
     * Whether the accumulated set just computed is empty for the output's method (point 6): every
     * singleton at degree 0, or a point set without area (CoG, CoA) or without positive degree
     * (LM, RM). A NaN result from a non-empty set is an overflow, not a reason for DEFAULT.
     */
    private boolean nothingFired(OutputPlan o) {
        if (o.singletons() || o.method() == DefuzzificationMethod.TSUKAMOTO) {
            for (int t = 0; t < o.termShapes().length; t++) {
                if (singletonDegree[t] != 0) {
                    return false;
                }
            }
            return true;
        }
        boolean byArea = o.method() == DefuzzificationMethod.COG || o.method() == DefuzzificationMethod.COA;
        return byArea ? Defuzzifier.area(set.px, set.py, set.np) == 0 : Defuzzifier.supremum(set.py, set.np) == 0;
    }

    /** Each term's accumulated degree (point 4: w·d of every subconclusion naming it, NSUM normalised) into singletonDegree. */
    private void degreesPerTerm(OutputPlan o) {
        int terms = o.termShapes().length;
        for (int t = 0; t < terms; t++) {
            singletonDegree[t] = 0;
        }
        int[] cs = o.contributions();
        for (int i = 0; i < cs.length; i++) {
            int t = o.contributionTerm()[i];
            double a = contributionWeight[cs[i]] * contributionDegree[cs[i]];
            singletonDegree[t] = accumulate(o.accumulation(), singletonDegree[t], a);
        }
        if (o.accumulation() == AccumulationMethod.NSUM) {
            double max = 1.0;
            for (int t = 0; t < terms; t++) {
                max = Math.max(max, singletonDegree[t]);
            }
            for (int t = 0; t < terms; t++) {
                singletonDegree[t] /= max;
            }
        }
    }

    /** Singleton outputs accumulate per term; CoGS (= CoG), LM and RM over the terms. NaN if empty. */
    private double singletons(OutputPlan o, Trace trace) {
        int terms = o.termShapes().length;
        for (int t = 0; t < terms; t++) {
            singletonValue[t] = curX[o.termShapes()[t]][0];
        }
        degreesPerTerm(o);
        if (trace != null) {
            List<Trace.Breakpoint> pts = new ArrayList<>();
            for (int t = 0; t < terms; t++) {
                pts.add(new Trace.Breakpoint(singletonValue[t], singletonDegree[t]));
            }
            trace.add(new Trace.AccumulatedSet(o.variable(), true, pts));
        }
        return switch (o.method()) {
            case LM -> extremeSingleton(terms, true);
            case RM -> extremeSingleton(terms, false);
            case MOM -> meanOfMaximalSingletons(terms);
            case COGSS -> weightedSumOfSingletons(terms);
            default -> centreOfGravityForSingletons(terms);
        };
    }

    /**
     * Tsukamoto's method (Open Level, O-TSUKAMOTO): the terms' degrees accumulated per term as for singletons, each
     * monotonic term inverted at its degree ({@link Tsukamoto#point}), the weighted average of those points; NaN when
     * nothing fired.
     */
    private double tsukamoto(OutputPlan o, Trace trace) {
        int terms = o.termShapes().length;
        degreesPerTerm(o);
        double num = 0;
        double den = 0;
        for (int t = 0; t < terms; t++) {
            int s = o.termShapes()[t];
            singletonValue[t] = singletonDegree[t] > 0 ? Tsukamoto.point(plan.shapes[s], curX[s], curY[s],
                    singletonDegree[t], o.hasRange(), o.rangeMin(), o.rangeMax()) : Double.NaN;
            if (singletonDegree[t] > 0) {
                num += singletonDegree[t] * singletonValue[t];
                den += singletonDegree[t];
            }
        }
        if (trace != null) {
            List<Trace.Breakpoint> pts = new ArrayList<>();
            for (int t = 0; t < terms; t++) {
                if (singletonDegree[t] > 0) {
                    pts.add(new Trace.Breakpoint(singletonValue[t], singletonDegree[t]));
                }
            }
            trace.add(new Trace.AccumulatedSet(o.variable(), true, pts));
        }
        return den > 0 ? num / den : Double.NaN;
    }

    /** fuzzylite's COGSS: Σ u·μ, not divided by Σ μ; NaN when every degree is 0 (nothing fired). */
    private double weightedSumOfSingletons(int terms) {
        double num = 0;
        boolean any = false;
        for (int t = 0; t < terms; t++) {
            num += singletonValue[t] * singletonDegree[t];
            any |= singletonDegree[t] != 0;
        }
        return any ? num : Double.NaN;
    }

    private double centreOfGravityForSingletons(int terms) {
        double num = 0;
        double den = 0;
        for (int t = 0; t < terms; t++) {
            num += singletonValue[t] * singletonDegree[t];
            den += singletonDegree[t];
        }
        return den > 0 ? num / den : Double.NaN;
    }

    private double extremeSingleton(int terms, boolean leftmost) {
        double sup = 0;
        for (int t = 0; t < terms; t++) {
            sup = Math.max(sup, singletonDegree[t]);
        }
        if (!(sup > 0)) {
            return Double.NaN;
        }
        double best = leftmost ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        for (int t = 0; t < terms; t++) {
            if (singletonDegree[t] >= sup * (1 - Defuzzifier.TIE)) {
                best = leftmost ? Math.min(best, singletonValue[t]) : Math.max(best, singletonValue[t]);
            }
        }
        return best;
    }

    /**
     * MoM on singletons (Open Level, O-MOM): the mean of the distinct values of the singletons whose
     * accumulated degree is the supremum (two terms at one value count once, as one point of the set).
     */
    private double meanOfMaximalSingletons(int terms) {
        double sup = 0;
        for (int t = 0; t < terms; t++) {
            sup = Math.max(sup, singletonDegree[t]);
        }
        if (!(sup > 0)) {
            return Double.NaN;
        }
        double sum = 0;
        int count = 0;
        for (int t = 0; t < terms; t++) {
            if (singletonDegree[t] >= sup * (1 - Defuzzifier.TIE) && !maximalValueBefore(t, sup)) {
                sum += singletonValue[t];
                count++;
            }
        }
        return sum / count;
    }

    private boolean maximalValueBefore(int t, double sup) {
        for (int s = 0; s < t; s++) {
            if (singletonValue[s] == singletonValue[t] && singletonDegree[s] >= sup * (1 - Defuzzifier.TIE)) {
                return true;
            }
        }
        return false;
    }

    /** Point-term outputs: the exact accumulated set, then CoG, CoA, LM or RM on it. NaN if empty. */
    private double pointSet(OutputPlan o, Trace trace) throws EvaluationException {
        collect(o, set.act);
        double lo = o.rangeMin();
        double hi = o.rangeMax();
        if (!o.hasRange()) {
            for (int j = 0; j < set.act.n; j++) {
                int s = set.act.shape[j];
                int n = plan.shapes[s].n;
                if (curY[s][0] > 0 || curY[s][n - 1] > 0) {
                    throw EvaluationException.unbounded(o.variable(), curY[s][0] > 0 ? curX[s][0] : curX[s][n - 1]);
                }
            }
            lo = Double.POSITIVE_INFINITY;
            hi = Double.NEGATIVE_INFINITY;
            for (int s : o.termShapes()) {
                lo = Math.min(lo, curX[s][0]);
                hi = Math.max(hi, curX[s][plan.shapes[s].n - 1]);
            }
        }
        set.build(o.accumulation(), lo, hi, curX, curY, plan.shapes);
        if (trace != null) {
            List<Trace.Breakpoint> pts = new ArrayList<>();
            for (int j = 0; j < set.np; j++) {
                pts.add(new Trace.Breakpoint(set.px[j], set.py[j]));
            }
            trace.add(new Trace.AccumulatedSet(o.variable(), false, pts));
        }
        return defuzzifySet(o.method());
    }

    /** The contributions to o's set that fired (degree · weight > 0), in place of those collected before. */
    private void collect(OutputPlan o, Activations into) {
        into.clear();
        int[] cs = o.contributions();
        for (int i = 0; i < cs.length; i++) {
            double d = contributionDegree[cs[i]];
            double w = contributionWeight[cs[i]];
            if (d * w > 0) {
                into.add(o.termShapes()[o.contributionTerm()[i]], d, w, o.contributionActivation()[i]);
            }
        }
    }

    /** Outputs whose set is not piece-wise linear: accumulation and defuzzification by SmoothSet. */
    private double smoothSet(OutputPlan o, SmoothSet smooth, Trace trace) {
        collect(o, smooth.act);
        double result = smooth.defuzzify(o.method(), o.accumulation(), o.rangeMin(), o.rangeMax(), plan.shapes,
                curX, curY);
        if (trace != null) {
            List<Trace.Breakpoint> pts = new ArrayList<>();
            int n = 64;
            for (int j = 0; j <= n && smooth.act.n > 0; j++) {
                double u = o.rangeMin() + (o.rangeMax() - o.rangeMin()) * j / n;
                pts.add(new Trace.Breakpoint(u, smooth.degree(u)));
            }
            trace.add(new Trace.AccumulatedSet(o.variable(), false, pts));
        }
        return result;
    }

    private double defuzzifySet(DefuzzificationMethod method) {
        return switch (method) {
            case COA -> Defuzzifier.centreOfArea(set.px, set.py, set.np);
            case LM -> Defuzzifier.leftmostMaximum(set.px, set.py, set.np);
            case RM -> Defuzzifier.rightmostMaximum(set.px, set.py, set.np);
            case MOM -> Defuzzifier.meanOfMaximum(set.px, set.py, set.np);
            // BlockCompiler refuses COGSS (like CoGS) on an output with point terms, so no point set reaches here
            case COGSS -> throw new AssertionError("COGSS on a point set: BlockCompiler admits it only on singletons");
            default -> Defuzzifier.centreOfGravity(set.px, set.py, set.np);
        };
    }
}
