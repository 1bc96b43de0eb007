package org.fclcert.eval;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.eval.BlockPlan.RuleBlockPlan;
import org.fclcert.eval.BlockPlan.SubconclusionPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DataType;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Names;

/**
 * The fast path of the reference evaluator: one instance of a function block with an index-based
 * interface (resolve names once with {@link #inputIndex}/{@link #outputIndex}, then
 * {@link #setInput(int, double)}, {@link #evaluate()}, {@link #output(int)}), computing the same exact
 * closed-form results as {@link FunctionBlockInstance}.
 *
 * <p>The block is compiled into flat arrays: the input terms grouped by shape ({@link TermDegrees}), each
 * rule as one opcode (the AND or OR algorithm fused with the rule's shape, e.g. "MIN over these degrees")
 * over indices into a degree array that also holds 1 − μ for negated terms, and each subconclusion as an
 * index into its output's accumulator. {@link #evaluate()} does no name lookup and no allocation. With
 * ACCU MAX the contributions to one output term (same weight and activation) are merged into one
 * activation level before the accumulated set is built, since max(min(l1, μ), min(l2, μ)) =
 * min(max(l1, l2), μ) exactly: the set has the same values and fewer breakpoints, so its CoG, CoA, LM and
 * RM are the reference's up to the rounding of a shorter sum (agreement documented in
 * docs/performance.md and tested in CompiledEvaluatorAgreementTest). A CoG over terms that form a chain
 * (a fuzzy partition) is computed by {@link ClippedChain} in time linear in the active terms.
 *
 * <p>A MIN/MAX block (the usual Mamdani block) that has been evaluated a couple of thousand times gets
 * code of its own ({@link MinMaxKernel}): the same arithmetic, bit for bit, without the loads of an
 * interpreted plan. Short-lived instances (a certification case, a fuzzed program) never pay for it.
 *
 * <p>This file is larger than the project's usual size: it is the one place where the flat plan is both
 * compiled and run, and splitting compilation from the loops that read its arrays would spread one
 * data layout over several files.
 *
 * <p>Blocks using what the flat plan does not cover (term points from variables, smooth named shapes,
 * bare-variable conclusions or subconditions, variable weights) are evaluated by a wrapped
 * {@link FunctionBlockInstance}: the interface and the results are the same, only slower
 * ({@link #isCompiled()} tells which). Not thread-safe; one instance per thread.
 */
public final class CompiledEvaluator {
    // rule opcodes: the rule's shape fused with its block's operator
    private static final int SINGLE = 0;
    private static final int AND_MIN = 1;
    private static final int AND_PROD = 2;
    private static final int AND_BDIF = 3;
    private static final int OR_MAX = 4;
    private static final int OR_ASUM = 5;
    private static final int OR_BSUM = 6;
    private static final int GENERAL = 7;

    // output kinds
    private static final int OUT_GENERAL = 0;
    private static final int OUT_COGS = 1;
    private static final int OUT_CHAIN = 2;

    // subconclusion kinds
    private static final int ACC_SINGLETON = 0;
    private static final int LEVEL_MAX = 1;
    private static final int RECORD = 2;

    private static final org.fclcert.model.Hedge[] HEDGES = org.fclcert.model.Hedge.values();

    static {
        // the int switches below use these ordinals
        if (AccumulationMethod.PROBOR.ordinal() != 3 || AccumulationMethod.BSUM.ordinal() != 1
                || AccumulationMethod.MAX.ordinal() != 0 || org.fclcert.model.AndAlgorithm.PROD.ordinal() != 1
                || org.fclcert.model.AndAlgorithm.MIN.ordinal() != 0 || org.fclcert.model.OrAlgorithm.MAX.ordinal() != 0
                || org.fclcert.model.OrAlgorithm.ASUM.ordinal() != 1) {
            throw new ExceptionInInitializerError("operator ordinals changed: update CompiledEvaluator");
        }
    }

    private final BlockPlan plan;
    private final FunctionBlockInstance fallback;
    private final int[] inputSlots;
    private final int[] outputSlots;
    /** Slot to input / output index, -1 where the slot is not one. */
    private final int[] inputOfSlot;
    private final int[] outputOfSlot;
    private final double[] values;
    /** Per slot: integer type (rounded on store), and the type's bounds, so that a store is two compares. */
    private final boolean[] integerSlot;
    private final double[] minSlot;
    private final double[] maxSlot;
    /**
     * Per input: the bound b such that a value with |value| &lt;= b is stored without further checks (real types
     * are symmetric; NaN where every value is checked, and NaN or ±∞ values fail the one compare).
     */
    private final double[] directBound;

    // fuzzification
    private TermDegrees terms;
    private int termCount;
    /** Degrees: [0, termCount) the terms, then 1 − μ for each term in negatedTerms, in that order. */
    private double[] deg;
    private int[] negatedTerms;

    // rules
    private int[] ruleOp;
    private int[] ruleStart;
    private int[] ruleEnd;
    private int[] operand;
    private ConditionCode[] general;
    private int[] generalAnd;
    private int[] generalOr;
    private double[] stack;
    private int[] conclusionStart;
    private int[] conclusionKind;
    private int[] conclusionTarget;
    private double[] conclusionWeight;

    // outputs
    private OutputPlan[] outputs;
    private int[] outputAccu;
    /** Per output: its accumulator range in acc (per term for singletons and merged point outputs). */
    private int[] accStart;
    private double[] acc;
    /** The singleton value of each singleton accumulator. */
    private double[] accValue;
    /** Per output: true when its contributions are merged per term (ACCU MAX, uniform weight/ACT). */
    private boolean[] merged;
    private double[] mergedWeight;
    private boolean[] mergedProd;
    private double[] recorded;
    private double[] contributionWeight;
    private double[][] shapeX;
    private double[][] shapeY;
    private double[] lo;
    private double[] hi;
    /** Per output: its CoG in closed form over a chain of terms ({@link ClippedChain}), else null. */
    private ClippedChain[] chains;
    /** Per output: OUT_COGS (singletons, ACCU MAX, CoGS), OUT_CHAIN (chains[o]) or OUT_GENERAL. */
    private int[] outKind;
    private final SetBuilder set = new SetBuilder();

    CompiledEvaluator(BlockPlan plan) {
        this.plan = plan;
        this.values = plan.initialValues.clone();
        int nIn = plan.inputNames.size();
        this.inputSlots = new int[nIn];
        for (int i = 0; i < nIn; i++) {
            inputSlots[i] = plan.slotByName.get(plan.inputNames.get(i));
        }
        this.outputSlots = plan.outputSlots.clone();
        this.inputOfSlot = new int[values.length];
        this.outputOfSlot = new int[values.length];
        java.util.Arrays.fill(inputOfSlot, -1);
        java.util.Arrays.fill(outputOfSlot, -1);
        for (int i = 0; i < nIn; i++) {
            inputOfSlot[inputSlots[i]] = i;
        }
        for (int i = 0; i < outputSlots.length; i++) {
            outputOfSlot[outputSlots[i]] = i;
        }
        int slots = values.length;
        this.integerSlot = new boolean[slots];
        this.minSlot = new double[slots];
        this.maxSlot = new double[slots];
        for (int s = 0; s < slots; s++) {
            integerSlot[s] = plan.types[s].isInteger();
            minSlot[s] = plan.types[s].min();
            maxSlot[s] = plan.types[s].max();
        }
        boolean flat = flat(plan);
        this.directBound = new double[nIn];
        for (int i = 0; i < nIn; i++) {
            // a NaN bound sends every value to setInputChecked: integer inputs (rounded) and the wrapped instance
            int s = inputSlots[i];
            boolean direct = !integerSlot[s] && flat && minSlot[s] == -maxSlot[s];
            directBound[i] = direct ? maxSlot[s] : Double.NaN;
        }
        if (flat) {
            this.fallback = null;
            compileTerms();
            compileRules();
            compileOutputs();
        } else {
            this.fallback = new FunctionBlockInstance(plan);
        }
    }

    /** Whether the block fits the flat plan (else the wrapped reference instance evaluates it). */
    private static boolean flat(BlockPlan plan) {
        if (plan.chainedTerms > 0 || plan.contributionHedges.length > 0) {
            return false;       // dialect constructs (fuzzylite): the reference instance evaluates them
        }
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            if (!rb.and().standard() || !rb.or().standard() || !rb.activation().standard()
                    || rb.accumulation().otherNorm().isPresent()) {
                return false;   // the dialects' other norms: fold below knows Table 3, 4 and PROBOR/SUM only
            }
        }
        for (OutputPlan o : plan.outputs) {
            if (o.method() == DefuzzificationMethod.TSUKAMOTO) {
                return false;   // fuzzylite's Tsukamoto method: the reference instance inverts the terms
            }
        }
        for (Shape s : plan.shapes) {
            if (!s.constant || s.kind != null) {
                return false;
            }
        }
        for (boolean smooth : plan.smoothOutputs) {
            if (smooth) {
                return false;
            }
        }
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            if (rb.bareTargetSlots().length > 0) {
                return false;
            }
            for (ConditionCode c : rb.conditions()) {
                for (int op : c.ops) {
                    if (op == ConditionCode.VARIABLE) {
                        return false;
                    }
                }
            }
            for (SubconclusionPlan[] scs : rb.conclusions()) {
                for (SubconclusionPlan sc : scs) {
                    if (sc.weightSlot() >= 0 || sc.contribution() < 0) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    // ---------------------------------------------------------------- compilation

    private void compileTerms() {
        terms = new TermDegrees(plan);
        termCount = terms.count;
    }

    private void compileRules() {
        Map<Integer, Integer> negIndex = new HashMap<>();
        List<Integer> negated = new ArrayList<>();
        List<Integer> ops = new ArrayList<>();
        List<Integer> operands = new ArrayList<>();
        List<Integer> starts = new ArrayList<>();
        List<Integer> ends = new ArrayList<>();
        List<ConditionCode> generals = new ArrayList<>();
        List<Integer> gAnd = new ArrayList<>();
        List<Integer> gOr = new ArrayList<>();
        int maxStack = 1;
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            for (ConditionCode code : rb.conditions()) {
                maxStack = Math.max(maxStack, code.maxStack);
                int op = simpleOp(code, rb);
                starts.add(operands.size());
                if (op == GENERAL) {
                    operands.add(generals.size());
                    generals.add(code);
                    gAnd.add(rb.and().ordinal());
                    gOr.add(rb.or().ordinal());
                } else {
                    int n = op == SINGLE ? 1 : code.ops.length - 1;
                    for (int i = 0; i < n; i++) {
                        int t = code.args[i];
                        if (code.ops[i] == ConditionCode.TERM_NOT) {
                            Integer k = negIndex.get(t);
                            if (k == null) {
                                k = negated.size();
                                negIndex.put(t, k);
                                negated.add(t);
                            }
                            operands.add(termCount + k);
                        } else {
                            operands.add(t);
                        }
                    }
                }
                ends.add(operands.size());
                ops.add(op);
            }
        }
        ruleOp = ops.stream().mapToInt(Integer::intValue).toArray();
        ruleStart = starts.stream().mapToInt(Integer::intValue).toArray();
        ruleEnd = ends.stream().mapToInt(Integer::intValue).toArray();
        operand = operands.stream().mapToInt(Integer::intValue).toArray();
        general = generals.toArray(ConditionCode[]::new);
        generalAnd = gAnd.stream().mapToInt(Integer::intValue).toArray();
        generalOr = gOr.stream().mapToInt(Integer::intValue).toArray();
        negatedTerms = negated.stream().mapToInt(Integer::intValue).toArray();
        deg = new double[termCount + negatedTerms.length];
        stack = new double[maxStack];
    }

    /** The fused opcode of a condition that is one term, or one AND/OR over (negated) terms; else GENERAL. */
    private static int simpleOp(ConditionCode code, RuleBlockPlan rb) {
        int n = code.ops.length;
        for (int i = 0; i < n - 1; i++) {
            if (code.ops[i] != ConditionCode.TERM && code.ops[i] != ConditionCode.TERM_NOT) {
                return GENERAL;
            }
        }
        int last = code.ops[n - 1];
        if (n == 1) {
            return last == ConditionCode.TERM || last == ConditionCode.TERM_NOT ? SINGLE : GENERAL;
        }
        if (code.args[n - 1] != n - 1) {
            return GENERAL;
        }
        if (last == ConditionCode.AND) {
            return switch (rb.and()) {
                case MIN -> AND_MIN;
                case PROD -> AND_PROD;
                case BDIF -> AND_BDIF;
                default -> GENERAL;     // the dialects' other norms
            };
        }
        if (last == ConditionCode.OR) {
            return switch (rb.or()) {
                case MAX -> OR_MAX;
                case ASUM -> OR_ASUM;
                case BSUM -> OR_BSUM;
                default -> GENERAL;
            };
        }
        return GENERAL;
    }

    private void compileOutputs() {
        outputs = plan.outputs;
        int n = outputs.length;
        outputAccu = new int[n];
        accStart = new int[n + 1];
        merged = new boolean[n];
        lo = new double[n];
        hi = new double[n];
        // contribution id -> (output, term within output)
        int[] contributionOutput = new int[plan.contributionCount];
        int[] contributionTerm = new int[plan.contributionCount];
        double[] weightOf = new double[plan.contributionCount];
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            for (SubconclusionPlan[] scs : rb.conclusions()) {
                for (SubconclusionPlan sc : scs) {
                    weightOf[sc.contribution()] = sc.weightConst();
                }
            }
        }
        List<Double> mw = new ArrayList<>();
        List<Boolean> mp = new ArrayList<>();
        int accAt = 0;
        for (int o = 0; o < n; o++) {
            OutputPlan out = outputs[o];
            outputAccu[o] = out.accumulation().ordinal();
            int terms = out.termShapes().length;
            int[] cs = out.contributions();
            for (int i = 0; i < cs.length; i++) {
                contributionOutput[cs[i]] = o;
                contributionTerm[cs[i]] = out.contributionTerm()[i];
            }
            boolean merge = !out.singletons() && out.accumulation() == AccumulationMethod.MAX;
            double[] w = new double[terms];
            int[] prod = new int[terms];
            java.util.Arrays.fill(w, Double.NaN);
            for (int i = 0; i < cs.length && merge; i++) {
                int t = out.contributionTerm()[i];
                int p = out.contributionProd()[i] ? 1 : 2;
                if (Double.isNaN(w[t])) {
                    w[t] = weightOf[cs[i]];
                    prod[t] = p;
                } else if (w[t] != weightOf[cs[i]] || prod[t] != p) {
                    merge = false;
                }
            }
            merged[o] = merge;
            accStart[o] = accAt;
            if (out.singletons() || merge) {
                accAt += terms;
                for (int t = 0; t < terms; t++) {
                    mw.add(Double.isNaN(w[t]) ? 0.0 : w[t]);
                    mp.add(prod[t] == 1);
                }
            }
            if (!out.singletons()) {
                double l = out.rangeMin();
                double h = out.rangeMax();
                if (!out.hasRange()) {
                    l = Double.POSITIVE_INFINITY;
                    h = Double.NEGATIVE_INFINITY;
                    for (int s : out.termShapes()) {
                        l = Math.min(l, plan.shapes[s].sortedX[0]);
                        h = Math.max(h, plan.shapes[s].sortedX[plan.shapes[s].n - 1]);
                    }
                }
                lo[o] = l;
                hi[o] = h;
            }
        }
        accStart[n] = accAt;
        chains = new ClippedChain[n];
        outKind = new int[n];
        for (int o = 0; o < n; o++) {
            OutputPlan out = outputs[o];
            if (out.singletons() && out.accumulation() == AccumulationMethod.MAX
                    && (out.method() == DefuzzificationMethod.COGS || out.method() == DefuzzificationMethod.COG)) {
                outKind[o] = OUT_COGS;
            } else if (merged[o] && out.method() == DefuzzificationMethod.COG) {
                Shape[] shapes = new Shape[out.termShapes().length];
                for (int t = 0; t < shapes.length; t++) {
                    shapes[t] = plan.shapes[out.termShapes()[t]];
                }
                chains[o] = ClippedChain.of(shapes, lo[o], hi[o]);
                outKind[o] = chains[o] != null ? OUT_CHAIN : OUT_GENERAL;
            }
        }
        acc = new double[accAt];
        accValue = new double[accAt];
        for (int o = 0; o < n; o++) {
            if (outputs[o].singletons()) {
                int[] shapes = outputs[o].termShapes();
                for (int t = 0; t < shapes.length; t++) {
                    accValue[accStart[o] + t] = plan.shapes[shapes[t]].sortedX[0];
                }
            }
        }
        mergedWeight = mw.stream().mapToDouble(Double::doubleValue).toArray();
        mergedProd = new boolean[mp.size()];
        for (int i = 0; i < mergedProd.length; i++) {
            mergedProd[i] = mp.get(i);
        }
        recorded = new double[plan.contributionCount];
        contributionWeight = weightOf;
        shapeX = new double[plan.shapes.length][];
        shapeY = new double[plan.shapes.length][];
        for (int s = 0; s < plan.shapes.length; s++) {
            shapeX[s] = plan.shapes[s].sortedX;
            shapeY[s] = plan.shapes[s].sortedY;
        }

        List<Integer> kinds = new ArrayList<>();
        List<Integer> targets = new ArrayList<>();
        List<Double> weights = new ArrayList<>();
        List<Integer> starts = new ArrayList<>();
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            for (SubconclusionPlan[] scs : rb.conclusions()) {
                starts.add(kinds.size());
                for (SubconclusionPlan sc : scs) {
                    int c = sc.contribution();
                    int o = contributionOutput[c];
                    if (outputs[o].singletons()) {
                        kinds.add(ACC_SINGLETON);
                        targets.add(accStart[o] + contributionTerm[c]);
                    } else if (merged[o]) {
                        kinds.add(LEVEL_MAX);
                        targets.add(accStart[o] + contributionTerm[c]);
                    } else {
                        kinds.add(RECORD);
                        targets.add(c);
                    }
                    weights.add(sc.weightConst());
                }
            }
        }
        starts.add(kinds.size());
        conclusionStart = starts.stream().mapToInt(Integer::intValue).toArray();
        conclusionKind = kinds.stream().mapToInt(Integer::intValue).toArray();
        conclusionTarget = targets.stream().mapToInt(Integer::intValue).toArray();
        conclusionWeight = weights.stream().mapToDouble(Double::doubleValue).toArray();
        // the accumulation method of the output each singleton accumulator belongs to
        accAccu = new int[accAt];
        for (int o = 0; o < n; o++) {
            for (int k = accStart[o]; k < accStart[o] + (outputs[o].singletons() || merged[o]
                    ? outputs[o].termShapes().length : 0); k++) {
                accAccu[k] = outputAccu[o];
            }
        }
        minMax = true;
        for (int op : ruleOp) {
            minMax &= op == SINGLE || op == AND_MIN;
        }
        minMaxWeight = new double[conclusionKind.length];
        for (int c = 0; c < conclusionKind.length; c++) {
            boolean maxAcc = conclusionKind[c] == LEVEL_MAX
                    || conclusionKind[c] == ACC_SINGLETON && accAccu[conclusionTarget[c]] == 0;
            minMax &= maxAcc;
            // max(acc, 1.0 * a) is max(acc, a) exactly, so a merged level needs no case of its own
            minMaxWeight[c] = conclusionKind[c] == LEVEL_MAX ? 1.0 : conclusionWeight[c];
        }
    }

    private int[] accAccu;
    /**
     * Evaluations of a MIN/MAX block on the array loops before its straight-line code is generated: an
     * instance used for a few steps (a certification case, a fuzzed program) never pays for generating it.
     */
    private static final int KERNEL_AFTER = 2000;
    private int kernelAfter = KERNEL_AFTER;
    private int evaluations;
    /** The block as straight-line code ({@link MinMaxKernel}), once generated; null before or when too large. */
    private MinMaxKernel kernel;
    private boolean othersToFuzzify;
    /**
     * True when every rule is one term or an AND MIN over terms and every subconclusion accumulates by MAX
     * (the usual Mamdani block): then {@link #runMinMaxRules} runs them without any opcode dispatch.
     */
    private boolean minMax;
    /** For the MIN/MAX plan: the weight each subconclusion multiplies by (1 for merged point outputs). */
    private double[] minMaxWeight;

    /** For tests: generate the straight-line code at the next evaluation (false when the block has none). */
    boolean generateAtNextEvaluation() {
        kernelAfter = evaluations + 1;
        return fallback == null && minMax;
    }

    /** For tests: whether output {@code index}'s CoG is computed on a chain of terms ({@link ClippedChain}). */
    boolean usesChain(int index) {
        return fallback == null && outKind[index] == OUT_CHAIN;
    }

    /** For tests: whether the generated code evaluates this instance. */
    boolean generated() {
        return kernel != null;
    }

    // ---------------------------------------------------------------- interface

    /** Whether the flat plan evaluates this block (false: the wrapped reference instance does). */
    public boolean isCompiled() {
        return fallback == null;
    }

    /** The function block's name as declared. */
    public String functionBlockName() {
        return plan.name;
    }

    /** VAR_INPUT names in declaration order: index i of {@link #setInput} is the i-th. */
    public List<String> inputNames() {
        return plan.inputNames;
    }

    /** VAR_OUTPUT names in declaration order: index i of {@link #output} is the i-th. */
    public List<String> outputNames() {
        return plan.outputNames;
    }

    /** The index of a VAR_INPUT (case-insensitive name), for {@link #setInput(int, double)}. */
    public int inputIndex(String name) throws EvaluationException {
        int slot = slot(name);
        if (inputOfSlot[slot] >= 0) {
            return inputOfSlot[slot];
        }
        throw new EvaluationException(EvaluationCode.NOT_AN_INPUT,
                "'" + plan.variableNames[slot] + "' is not a VAR_INPUT and cannot be set");
    }

    /** The index of a VAR_OUTPUT (case-insensitive name), for {@link #output(int)}. */
    public int outputIndex(String name) throws EvaluationException {
        int slot = slot(name);
        if (outputOfSlot[slot] >= 0) {
            return outputOfSlot[slot];
        }
        throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                "'" + plan.variableNames[slot] + "' is not a VAR_OUTPUT of function block '" + plan.name + "'");
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

    /**
     * Sets input {@code index} (as {@link FunctionBlockInstance#set}: finite values only, integer types
     * rounded half away from zero and range-checked).
     */
    public void setInput(int index, double value) throws EvaluationException {
        if (Math.abs(value) <= directBound[index]) {
            values[inputSlots[index]] = value;   // the common case: a real in range
        } else {
            setInputChecked(index, value);
        }
    }

    /**
     * Sets every input, in declaration order ({@link #inputNames()}): {@code values[i]} as
     * {@link #setInput(int, double)} sets input i. Stops at the first value refused, with its error.
     */
    public void setInputs(double... values) throws EvaluationException {
        if (values.length != inputSlots.length) {
            throw new IllegalArgumentException(values.length + " values for " + inputSlots.length + " inputs");
        }
        for (int i = 0; i < values.length; i++) {
            setInput(i, values[i]);
        }
    }

    private void setInputChecked(int index, double value) throws EvaluationException {
        if (fallback != null) {
            fallback.set(plan.inputNames.get(index), value);
            return;
        }
        int slot = inputSlots[index];
        if (!Double.isFinite(value)) {
            throw new EvaluationException(EvaluationCode.NOT_FINITE,
                    "input '" + plan.variableNames[slot] + "' must be a finite number, not " + value);
        }
        store(slot, value);
    }

    /** The current value of input {@code index}. */
    public double input(int index) throws EvaluationException {
        return fallback != null ? fallback.get(plan.inputNames.get(index)) : values[inputSlots[index]];
    }

    /** The value of output {@code index} after the last evaluation (its initial value before any). */
    public double output(int index) throws EvaluationException {
        return fallback != null ? fallback.get(plan.outputNames.get(index)) : values[outputSlots[index]];
    }

    /** Back to the state of a fresh instance. */
    public void reset() {
        if (fallback != null) {
            fallback.reset();
        } else {
            System.arraycopy(plan.initialValues, 0, values, 0, values.length);
        }
    }

    private void store(int slot, double value) throws EvaluationException {
        double v = integerSlot[slot] ? Conversions.roundHalfAwayFromZero(value) : value;
        if (v < minSlot[slot] || v > maxSlot[slot]) {
            DataType type = plan.types[slot];
            throw new EvaluationException(EvaluationCode.OUT_OF_RANGE, "value " + value + " of '"
                    + plan.variableNames[slot] + "' does not fit its data type " + type);
        }
        values[slot] = v;
    }

    // ---------------------------------------------------------------- evaluation

    /** One evaluation: fuzzification, every rule block in textual order, defuzzification. */
    public void evaluate() throws EvaluationException {
        if (kernel != null) {
            evaluateKernel();     // first, and the rest out of line, so that this method is small enough to inline
        } else if (fallback != null) {
            fallback.evaluate();
        } else {
            evaluateOnArrays();
        }
    }

    private void evaluateOnArrays() throws EvaluationException {
        fuzzify();
        java.util.Arrays.fill(acc, 0.0);
        if (recorded.length > 0) {
            java.util.Arrays.fill(recorded, 0.0);
        }
        if (minMax) {
            runMinMaxRules();
            if (++evaluations == kernelAfter) {
                kernel = generateKernel();
            }
        } else {
            runRules();
        }
        for (int o = 0; o < outputs.length; o++) {
            defuzzify(o);
        }
    }

    /** 5.2.2 ({@link TermDegrees}: the reference's arithmetic, so the same degrees), then 1 − μ for NOT. */
    private void fuzzify() {
        final double[] d = deg;
        terms.fuzzify(values, d);
        int[] neg = negatedTerms;
        for (int k = 0; k < neg.length; k++) {
            d[termCount + k] = 1.0 - d[neg[k]];
        }
    }

    /** Aggregation (Table 3, folded left to right as the reference does) and the conclusions of every rule. */
    private void runRules() {
        final double[] d = deg;
        final int[] opd = operand;
        final int[] ops = ruleOp;
        for (int r = 0; r < ops.length; r++) {
            int s = ruleStart[r];
            int e = ruleEnd[r];
            double a;
            switch (ops[r]) {
                case SINGLE -> a = d[opd[s]];
                case AND_MIN -> {
                    a = d[opd[s]];
                    for (int k = s + 1; k < e && a > 0; k++) {
                        a = Math.min(a, d[opd[k]]);
                    }
                }
                case AND_PROD -> {
                    a = d[opd[s]];
                    for (int k = s + 1; k < e && a > 0; k++) {
                        a = a * d[opd[k]];
                    }
                }
                case AND_BDIF -> {
                    a = d[opd[s]];
                    for (int k = s + 1; k < e && a > 0; k++) {
                        a = Math.max(0.0, a + d[opd[k]] - 1.0);
                    }
                }
                case OR_MAX -> {
                    a = d[opd[s]];
                    for (int k = s + 1; k < e; k++) {
                        a = Math.max(a, d[opd[k]]);
                    }
                }
                case OR_ASUM -> {
                    a = d[opd[s]];
                    for (int k = s + 1; k < e; k++) {
                        double b = d[opd[k]];
                        a = a + b - a * b;
                    }
                }
                case OR_BSUM -> {
                    a = d[opd[s]];
                    for (int k = s + 1; k < e; k++) {
                        a = Math.min(1.0, a + d[opd[k]]);
                    }
                }
                default -> a = general(opd[s]);
            }
            if (a == 0) {
                // w * 0 leaves every accumulator as it is (max, bounded or plain sums, PROBOR), and the
                // recorded degrees were cleared: a rule that does not fire has nothing to conclude
                continue;
            }
            for (int c = conclusionStart[r]; c < conclusionStart[r + 1]; c++) {
                int target = conclusionTarget[c];
                switch (conclusionKind[c]) {
                    case ACC_SINGLETON -> acc[target] = accumulate(accAccu[target], acc[target], conclusionWeight[c] * a);
                    case LEVEL_MAX -> acc[target] = Math.max(acc[target], a);
                    default -> recorded[target] = a;
                }
            }
        }
    }

    /** {@link #runRules} for a block of MIN conditions and MAX accumulation: the same arithmetic, no dispatch. */
    private void runMinMaxRules() {
        final double[] d = deg;
        final int[] opd = operand;
        final int[] starts = ruleStart;
        final int[] ends = ruleEnd;
        final int[] cs = conclusionStart;
        final int[] target = conclusionTarget;
        final double[] w = minMaxWeight;
        final double[] a = acc;
        int rules = starts.length;
        // no test of m: max(acc, w * 0) is acc (acc >= 0), and a branch on the data costs more than the work
        for (int r = 0; r < rules; r++) {
            int e = ends[r];
            double m = d[opd[starts[r]]];
            for (int k = starts[r] + 1; k < e; k++) {
                m = Math.min(m, d[opd[k]]);
            }
            for (int c = cs[r]; c < cs[r + 1]; c++) {
                int t = target[c];
                a[t] = Math.max(a[t], w[c] * m);
            }
        }
    }

    /** A condition that is not a flat AND/OR over terms: its postfix code, as FunctionBlockInstance runs it. */
    private double general(int g) {
        ConditionCode code = general[g];
        int[] ops = code.ops;
        int[] args = code.args;
        double[] st = stack;
        int and = generalAnd[g];
        int or = generalOr[g];
        int sp = 0;
        for (int i = 0; i < ops.length; i++) {
            switch (ops[i]) {
                case ConditionCode.TERM -> st[sp++] = deg[args[i]];
                case ConditionCode.TERM_NOT -> st[sp++] = 1.0 - deg[args[i]];
                case ConditionCode.NOT -> st[sp - 1] = 1.0 - st[sp - 1];
                case ConditionCode.HEDGE -> st[sp - 1] = HEDGES[args[i]].apply(st[sp - 1]);
                case ConditionCode.ONE -> st[sp++] = 1.0;
                case ConditionCode.AND -> sp = fold(st, sp, args[i], true, and, or);
                default -> sp = fold(st, sp, args[i], false, and, or);
            }
        }
        return st[0];
    }

    private static int fold(double[] st, int sp, int n, boolean isAnd, int and, int or) {
        int base = sp - n;
        double a = st[base];
        for (int j = base + 1; j < sp; j++) {
            double b = st[j];
            if (isAnd) {
                a = switch (and) {
                    case 0 -> Math.min(a, b);           // MIN
                    case 1 -> a * b;                    // PROD
                    default -> Math.max(0.0, a + b - 1.0); // BDIF
                };
            } else {
                a = switch (or) {
                    case 0 -> Math.max(a, b);           // MAX
                    case 1 -> a + b - a * b;            // ASUM
                    default -> Math.min(1.0, a + b);    // BSUM
                };
            }
        }
        st[base] = a;
        return base + 1;
    }

    /** Table 5 on two degrees (ordinal of AccumulationMethod, checked in the static block); NSUM sums here. */
    private static double accumulate(int accu, double a, double b) {
        return switch (accu) {
            case 0 -> Math.max(a, b);                // MAX
            case 1 -> Math.min(1.0, a + b);          // BSUM
            case 3 -> a + b - a * b;                 // PROBOR
            default -> a + b;                        // NSUM, SUM
        };
    }

    /** {@link #evaluate} by the generated code, which also stores the usual CoGS results itself. */
    private void evaluateKernel() throws EvaluationException {
        if (othersToFuzzify) {
            terms.fuzzifyOthers(values, deg);
        }
        if (kernel.run(values, deg, acc) > 0) {
            for (int o = 0; o < outputs.length; o++) {
                defuzzify(o);       // outputs the kernel left (a stored CoGS is stored again, the same)
            }
        }
    }

    /** The straight-line code of this MIN/MAX block, storing REAL CoGS outputs too; null when too large. */
    private MinMaxKernel generateKernel() {
        int n = outputs.length;
        int[] slot = new int[n];
        int[] from = new int[n];
        int[] to = new int[n];
        double[] min = new double[n];
        double[] max = new double[n];
        for (int o = 0; o < n; o++) {
            int s = outputs[o].slot();
            slot[o] = outKind[o] == OUT_COGS && !integerSlot[s] ? s : -1;
            from[o] = accStart[o];
            to[o] = accStart[o + 1];
            min[o] = minSlot[s];
            max[o] = maxSlot[s];
        }
        othersToFuzzify = terms.hasOthers();
        return MinMaxKernel.generate(new MinMaxKernel.Block(terms, negatedTerms, ruleStart, ruleEnd, operand,
                conclusionStart, conclusionTarget, minMaxWeight, acc.length, slot, from, to, accValue, min, max));
    }

    private void defuzzify(int o) throws EvaluationException {
        OutputPlan out = outputs[o];
        double result;
        boolean empty;
        if (outKind[o] == OUT_COGS) {
            // CoGS (Σ v·μ / Σ μ) over degrees accumulated by MAX, so Σ μ is 0 only when every μ is
            int b = accStart[o];
            int e = accStart[o + 1];
            final double[] a = acc;
            final double[] v = accValue;
            double num = 0;
            double den = 0;
            for (int k = b; k < e; k++) {
                num += v[k] * a[k];
                den += a[k];
            }
            result = num / den;
            int slot = out.slot();
            if (den > 0 && result >= minSlot[slot] && result <= maxSlot[slot] && !integerSlot[slot]) {
                values[slot] = result;   // the common case: a real in range (NaN fails the compares)
                return;
            }
            empty = den == 0;
            result = empty ? Double.NaN : result;
        } else if (outKind[o] == OUT_CHAIN) {
            ClippedChain chain = chains[o];
            result = chain.centreOfGravity(acc, mergedWeight, mergedProd, accStart[o]);
            empty = chain.empty();
        } else if (out.singletons()) {
            result = singletons(o, out);
            empty = true;
            for (int k = accStart[o]; k < accStart[o + 1] && Double.isNaN(result); k++) {
                empty &= acc[k] == 0;
            }
        } else {
            result = pointSet(o, out);
            boolean byArea = out.method() == DefuzzificationMethod.COG || out.method() == DefuzzificationMethod.COA;
            empty = Double.isNaN(result) && (byArea ? Defuzzifier.area(set.px, set.py, set.np) == 0
                    : Defuzzifier.supremum(set.py, set.np) == 0);
        }
        if (Double.isNaN(result)) {
            if (!empty) {
                throw new EvaluationException(EvaluationCode.NO_RESULT, "defuzzification of '"
                        + out.variable() + "' has no numeric result (the arithmetic overflowed)");
            }
            if (out.noChange()) {
                return;
            }
            result = out.defaultValue();
            if (Double.isNaN(result)) {
                values[out.slot()] = result;   // DEFAULT := nan (fuzzylite)
                return;
            }
        }
        if (!Double.isFinite(result)) {
            throw new EvaluationException(EvaluationCode.NO_RESULT,
                    "defuzzification of '" + out.variable() + "' overflowed (result " + result + ")");
        }
        store(out.slot(), result);
    }

    private double singletons(int o, OutputPlan out) {
        int b = accStart[o];
        int terms = accStart[o + 1] - b;
        double[] a = acc;
        if (out.accumulation() == AccumulationMethod.NSUM) {
            double max = 1.0;
            for (int t = 0; t < terms; t++) {
                max = Math.max(max, a[b + t]);
            }
            for (int t = 0; t < terms; t++) {
                a[b + t] /= max;
            }
        }
        int[] shapes = out.termShapes();
        double[] v = accValue;
        DefuzzificationMethod m = out.method();
        if (m == DefuzzificationMethod.COGS || m == DefuzzificationMethod.COG) {
            double num = 0;
            double den = 0;
            for (int k = b; k < b + terms; k++) {
                num += v[k] * a[k];
                den += a[k];
            }
            return den > 0 ? num / den : Double.NaN;
        }
        if (m == DefuzzificationMethod.COGSS) {
            double num = 0;
            boolean any = false;
            for (int k = b; k < b + terms; k++) {
                num += v[k] * a[k];
                any |= a[k] != 0;
            }
            return any ? num : Double.NaN;
        }
        return extremes(m, b, terms, shapes);
    }

    /** LM, RM and MoM on singletons, as FunctionBlockInstance computes them. */
    private double extremes(DefuzzificationMethod method, int b, int terms, int[] shapes) {
        double sup = 0;
        for (int t = 0; t < terms; t++) {
            sup = Math.max(sup, acc[b + t]);
        }
        if (!(sup > 0)) {
            return Double.NaN;
        }
        double level = sup * (1 - Defuzzifier.TIE);
        if (method == DefuzzificationMethod.MOM) {
            double sum = 0;
            int count = 0;
            for (int t = 0; t < terms; t++) {
                double v = plan.shapes[shapes[t]].sortedX[0];
                boolean before = false;
                for (int s = 0; s < t && !before; s++) {
                    before = plan.shapes[shapes[s]].sortedX[0] == v && acc[b + s] >= level;
                }
                if (acc[b + t] >= level && !before) {
                    sum += v;
                    count++;
                }
            }
            return sum / count;
        }
        boolean leftmost = method == DefuzzificationMethod.LM;
        double best = leftmost ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        for (int t = 0; t < terms; t++) {
            if (acc[b + t] >= level) {
                double v = plan.shapes[shapes[t]].sortedX[0];
                best = leftmost ? Math.min(best, v) : Math.max(best, v);
            }
        }
        return best;
    }

    private double pointSet(int o, OutputPlan out) {
        Activations act = set.act;
        act.clear();
        int[] shapes = out.termShapes();
        if (merged[o]) {
            int b = accStart[o];
            for (int t = 0; t < shapes.length; t++) {
                double level = acc[b + t];
                double w = mergedWeight[b + t];
                if (level * w > 0) {
                    act.add(shapes[t], level, w, mergedProd[b + t]);
                }
            }
        } else {
            int[] cs = out.contributions();
            for (int i = 0; i < cs.length; i++) {
                double level = recorded[cs[i]];
                double w = contributionWeight[cs[i]];
                if (level * w > 0) {
                    act.add(shapes[out.contributionTerm()[i]], level, w, out.contributionProd()[i]);
                }
            }
        }
        set.build(out.accumulation(), lo[o], hi[o], shapeX, shapeY, plan.shapes);
        return switch (out.method()) {
            case COA -> Defuzzifier.centreOfArea(set.px, set.py, set.np);
            case LM -> Defuzzifier.leftmostMaximum(set.px, set.py, set.np);
            case RM -> Defuzzifier.rightmostMaximum(set.px, set.py, set.np);
            case MOM -> Defuzzifier.meanOfMaximum(set.px, set.py, set.np);
            default -> Defuzzifier.centreOfGravity(set.px, set.py, set.np);
        };
    }
}
