package org.fclcert.eval;

import java.util.List;
import java.util.Map;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DataType;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;

/**
 * One function block compiled to arrays and indices (immutable; shared by all its instances).
 * Variables live in slots (their declaration index); input terms have degree indices; each
 * {@code IS} subconclusion is a numbered contribution to its output's accumulation.
 */
final class BlockPlan {
    final String name;
    final String[] variableNames;
    final DataType[] types;
    final boolean[] isInput;
    final double[] initialValues;
    /** Declared name and upper-case key of each variable, to its slot. */
    final Map<String, Integer> slotByName;
    final List<String> inputNames;
    final List<String> outputNames;
    final int[] outputSlots;

    final Shape[] shapes;
    /** Per input term (degree index): the variable slot, its shape, and names for the trace. */
    final int[] termVariableSlot;
    final int[] termShape;
    final String[] termVariableName;
    final String[] termName;

    final RuleBlockPlan[] ruleBlocks;
    final OutputPlan[] outputs;
    /**
     * Per output: true when its accumulated set is not piece-wise linear (smooth shapes, PROBOR and the dialects'
     * other accumulations and activations): SmoothSet.
     */
    final boolean[] smoothOutputs;
    /** Number of IS subconclusions; each has an entry in the instance's degree/weight arrays. */
    final int contributionCount;
    /**
     * Dialects (fuzzylite's 'output IS term' in a condition): per contribution, the entry of the degrees after
     * the input terms' that accumulates it, or -1; with the accumulation of each contribution and the count.
     */
    final int[] chainedDegree;
    final org.fclcert.model.AccumulationMethod[] chainedAccumulation;
    final int chainedTerms;
    /**
     * jFuzzyLogic's reading of 'output IS term' in a condition (O-OUTPUT-VALUE-CONDITION), per chained degree: the
     * output term's shape, the output's slot, and the value it starts each evaluation with (its DEFAULT; NaN: its
     * value, DEFAULT NC); null in fuzzylite's reading, where contributions accumulate into the chained degrees.
     */
    final int[] valueTermShape;
    final int[] valueTermSlot;
    final double[] valueTermStart;
    /** Dialects (fuzzylite hedges in conclusions): per contribution, the hedges applied to the rule's degree, or null. */
    final org.fclcert.model.Hedge[][] contributionHedges;
    final int maxStack;
    final int maxBareTargets;

    BlockPlan(Builder b) {
        name = b.name;
        variableNames = b.variableNames;
        types = b.types;
        isInput = b.isInput;
        initialValues = b.initialValues;
        // a HashMap behind a read-only view: Map.copyOf probes badly on 10^5 similar names (x1, x2, ...)
        slotByName = java.util.Collections.unmodifiableMap(new java.util.HashMap<>(b.slotByName));
        inputNames = List.copyOf(b.inputNames);
        outputNames = List.copyOf(b.outputNames);
        outputSlots = b.outputSlots;
        shapes = b.shapes;
        termVariableSlot = b.termVariableSlot;
        termShape = b.termShape;
        termVariableName = b.termVariableName;
        termName = b.termName;
        ruleBlocks = b.ruleBlocks;
        outputs = b.outputs;
        smoothOutputs = b.smoothOutputs;
        contributionCount = b.contributionCount;
        chainedDegree = b.chainedDegree != null ? b.chainedDegree : new int[0];
        chainedAccumulation = b.chainedAccumulation != null ? b.chainedAccumulation
                : new org.fclcert.model.AccumulationMethod[0];
        chainedTerms = b.chainedTerms;
        contributionHedges = b.contributionHedges != null ? b.contributionHedges : new org.fclcert.model.Hedge[0][];
        valueTermShape = b.valueTermShape;
        valueTermSlot = b.valueTermSlot;
        valueTermStart = b.valueTermStart;
        int stack = 1;
        int bare = 0;
        for (RuleBlockPlan rb : ruleBlocks) {
            for (ConditionCode c : rb.conditions) {
                stack = Math.max(stack, c.maxStack);
            }
            bare = Math.max(bare, rb.bareTargetSlots.length);
        }
        maxStack = stack;
        maxBareTargets = bare;
    }

    /** The slot of a variable by its declared name or, case-insensitively, its key; UNKNOWN_NAME otherwise. */
    int slot(String name) throws EvaluationException {
        Integer slot = slotByName.get(name);
        if (slot == null) {
            slot = slotByName.get(Names.key(name));
        }
        if (slot == null) {
            throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                    "function block '" + this.name + "' has no variable '" + name + "'");
        }
        return slot;
    }

    /**
     * The slot of the VAR_INPUT {@code name} about to be given {@code value}: refused when the variable is not an
     * input (NOT_AN_INPUT) or the value not finite (NOT_FINITE). Both instances set inputs through it.
     */
    int inputSlot(String name, double value) throws EvaluationException {
        int slot = slot(name);
        if (!isInput[slot]) {
            throw notAnInput(slot);
        }
        requireFinite(slot, value);
        return slot;
    }

    /** NOT_AN_INPUT for the variable in {@code slot}. */
    EvaluationException notAnInput(int slot) {
        return new EvaluationException(EvaluationCode.NOT_AN_INPUT,
                "'" + variableNames[slot] + "' is not a VAR_INPUT and cannot be set");
    }

    /** NOT_FINITE unless the value for the input in {@code slot} is a finite number. */
    void requireFinite(int slot, double value) throws EvaluationException {
        if (!Double.isFinite(value)) {
            throw new EvaluationException(EvaluationCode.NOT_FINITE,
                    "input '" + variableNames[slot] + "' must be a finite number, not " + value);
        }
    }

    /** The compiled kernel, generated when an instance first asks for it (KernelCompiler); see {@link #kernel}. */
    private KernelCompiler.Compiled kernel;
    private boolean kernelTried;

    private StaticFilter staticFilter;
    private boolean staticTried;
    private TermChain[] chains;

    /** Per output: the chain of its terms for CoG ({@link TermChain}), null for another method or layout; once. */
    synchronized TermChain[] chains() {
        if (chains == null) {
            chains = new TermChain[outputs.length];
            for (int i = 0; i < outputs.length; i++) {
                chains[i] = outputs[i].method() == org.fclcert.model.DefuzzificationMethod.COG && !smoothOutputs[i]
                        ? TermChain.of(outputs[i], shapes) : null;
            }
        }
        return chains;
    }

    /** The block's static filter (StaticFilter.build over the kernel's outputs), once; null when not covered. */
    synchronized StaticFilter staticFilter() {
        if (!staticTried) {
            staticTried = true;
            KernelCompiler.Compiled k = kernel();
            staticFilter = k == null ? null : StaticFilter.build(this, k);
        }
        return staticFilter;
    }

    /** The block's compiled kernel, generated once and shared by its instances; null when the plan is not covered. */
    synchronized KernelCompiler.Compiled kernel() {
        if (!kernelTried) {
            kernelTried = true;
            kernel = KernelCompiler.compile(this);
        }
        return kernel;
    }

    /** Mutable holder the compiler fills. */
    static final class Builder {
        String name;
        String[] variableNames;
        DataType[] types;
        boolean[] isInput;
        double[] initialValues;
        Map<String, Integer> slotByName;
        List<String> inputNames;
        List<String> outputNames;
        int[] outputSlots;
        Shape[] shapes;
        int[] termVariableSlot;
        int[] termShape;
        String[] termVariableName;
        String[] termName;
        RuleBlockPlan[] ruleBlocks;
        OutputPlan[] outputs;
        boolean[] smoothOutputs;
        int contributionCount;
        int[] chainedDegree;
        org.fclcert.model.AccumulationMethod[] chainedAccumulation;
        int chainedTerms;
        org.fclcert.model.Hedge[][] contributionHedges;
        int[] valueTermShape;
        int[] valueTermSlot;
        double[] valueTermStart;
    }

    /** One rule block: operators, methods, and per rule its condition and subconclusions. */
    record RuleBlockPlan(
            String name,
            AndAlgorithm and,
            OrAlgorithm or,
            ActivationMethod activation,
            AccumulationMethod accumulation,
            String[] ruleNames,
            ConditionCode[] conditions,
            SubconclusionPlan[][] conclusions,
            int[] bareTargetSlots) {
    }

    /**
     * One subconclusion. {@code contribution} &gt;= 0 for {@code v IS t} (index into the
     * contribution arrays); otherwise {@code bareTarget} indexes the block's bare-variable targets.
     * The weight is {@code weightConst} or, when {@code weightSlot} &gt;= 0, an input variable.
     */
    record SubconclusionPlan(
            String variable, String term, int contribution, int bareTarget, double weightConst, int weightSlot) {
    }

    /** One defuzzified output variable. */
    record OutputPlan(
            String variable,
            int slot,
            DefuzzificationMethod method,
            boolean singletons,
            boolean hasRange,
            double rangeMin,
            double rangeMax,
            int[] termShapes,
            String[] termNames,
            boolean noChange,
            double defaultValue,
            AccumulationMethod accumulation,
            int[] contributions,
            int[] contributionTerm,
            boolean[] contributionProd,
            int maxPoints,
            ActivationMethod[] contributionActivation) {
    }
}
