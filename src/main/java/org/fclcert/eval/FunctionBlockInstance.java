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
import org.fclcert.model.OrAlgorithm;

/**
 * The reference evaluator: one instance of a fuzzy function block (IEC 61131-3 instance semantics). It keeps
 * its variable values between evaluations, so unset inputs keep their last value and DEFAULT NC keeps the last
 * output. Not thread-safe; create one instance per thread.
 *
 * <p>Filtered exact evaluation (docs/semantics.md, "Filtered exact evaluation"): every degree is computed in
 * doubles together with a bound on its distance from the exact value ({@link Norms}); at every decision point
 * (a degree against 0, 1 or another degree, whether a rule fired, a tie for LM/RM/MoM, a clip at a vertex, an
 * INT rounding at .5) a decision the bounds cannot settle makes the evaluation be redone in exact rational
 * arithmetic ({@link ExactInstance}, from the same state), and its results are taken. So every discrete outcome
 * is the exact one and a REAL output is within {@link #bound(String)} of it. {@link #fallbacks()} counts the
 * evaluations redone. {@link #evaluate()} does no name lookup and allocates nothing when it does not fall back.
 *
 * <p>From its {@link #KERNEL_AFTER}th evaluation an instance of a block the compiled kernel covers runs
 * fuzzification, the rule blocks and singleton outputs as generated code ({@link KernelCompiler}) that computes
 * the same doubles and bounds as the code here, bit for bit; the decisions stay here. For a block whose outputs the
 * kernel computes whole (or are CoG over a chain of terms, {@link TermChain}), the static filter ({@link StaticFilter})
 * decides most steps with constant bounds and the doubles alone; such a step's running bounds are computed when
 * {@link #bound} (or {@link #reset}) asks.
 *
 * <p>Its size (about 1 600 lines, above the project's 700) is earned: every stage of Tables 3–6 in doubles sits
 * here with its error bound and the decision points that read it, so that a bound and the decision it settles
 * cannot drift apart; the operators' formulas themselves are in {@link Norms}, the exact arithmetic in
 * {@link ExactInstance}.
 */
public final class FunctionBlockInstance {
    private final BlockPlan plan;
    private final double[] values;
    private final double[] termDegrees;
    /** Per term degree, per stack entry, per contribution: the bound of its error (docs/semantics.md). */
    private final double[] termErrors;
    private final double[] stackErrors;
    private final double[] contributionError;
    private final double[] contributionDegreeError;
    private final double[] singletonError;
    private final double[] bareErrors;
    /** Per output: the bound of the last value's distance from the exact value (0 when decided exactly). */
    private final double[] bounds;
    /** Whether decisions the bounds cannot settle are redone exactly (false: plain doubles, for FairVectors). */
    private final boolean filtered;
    /** Set by a decision the bounds could not settle, during one evaluation. */
    private boolean undecided;
    private String lastDecision;
    private ExactInstance exact;
    private boolean exactUnavailable;
    private final double[] before;
    /** Per shape and point: the distance of x and y from their decimal readings (constant shapes: once). */
    private final double[][] repX;
    private final double[][] repY;
    /** Per variable slot: the distance of its value from its decimal reading, kept by store. */
    private final double[] valueRep;
    /** Per singleton term of the output being defuzzified: its value's distance from its decimal reading. */
    private final double[] singletonRep;
    /** Per variable slot: the bound of a value written in this evaluation (bare conclusions, outputs), else 0. */
    private final double[] slotErrors;
    /** The slot of each VAR_INPUT, in declaration order. */
    private final int[] inputSlots;
    /** Per VAR_INPUT: its type's range, empty (+inf, -inf) for an integer type, for setInputs' lean path. */
    private final double[] leanMin;
    private final double[] leanMax;
    /** Per slot: its data type's integer flag and range, read by {@link #store} without the DataType. */
    private final boolean[] integerSlot;
    private final double[] slotMin;
    private final double[] slotMax;
    private long evaluations;
    private long fallbacks;
    private long undecidedWithoutExact;
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
    /** Per output: its chain of terms for CoG ({@link TermChain}), or null. */
    private final TermChain[] chains;
    private static final org.fclcert.model.Hedge[] HEDGES = org.fclcert.model.Hedge.values();
    /**
     * Per output: its value when this evaluation began, which DEFAULT NC keeps (point 6) even when a bare
     * conclusion on the same variable wrote to it during the rule blocks.
     */
    private final double[] previous;
    /**
     * Per rule block, per rule: whether an exact 0 as its first term's degree settles the rule (a lone term, or an
     * AND by MIN or PROD of terms) and its subconclusions are plain contributions (constant weight, no hedge, not
     * chained), so that {@link #runRuleBlock} writes their zeros without the steps. Most rules of a large rule
     * base are settled so: their first input's term is 0 there.
     */
    private final java.util.IdentityHashMap<RuleBlockPlan, ZeroSkip> zeroSkip = new java.util.IdentityHashMap<>();

    /**
     * The rules {@link #runRuleBlock} may settle by an exact 0, in flat arrays (a large rule base is walked without
     * touching its condition and subconclusion objects): per rule the degree index of its first term, or -1; the
     * range of its subconclusions in {@code contribution} and {@code weight}.
     */
    private record ZeroSkip(int[] firstTerm, int[] from, int[] contribution, double[] weight) {
    }

    /** Shapes with points from variables, re-read at each evaluation. */
    private final int[] variableShapes;

    /**
     * The compiled kernel once it is in use (null before, and for a plan it does not cover): fuzzification and the
     * rule blocks, and the outputs marked in {@link #kernelOutputs}, as generated code computing the same doubles
     * and bounds (docs/semantics.md, "The compiled kernel"). Taken at the {@link #KERNEL_AFTER}th evaluation.
     */
    private CompiledKernel kernel;
    private boolean[] kernelOutputs;
    private final double[] kernelScratch = new double[2];
    /**
     * The contributions the kernel wrote in this evaluation, ascending ({@code liveCount} of them; -1 when the
     * interpreter ran). The kernel writes nothing for a rule its ZeroSkip settles: {@link #clearLive} sets the
     * contributions of the step before to that rule's exact 0 first, so every other contribution holds it already.
     * {@link #collect} walks only the live ones, since an exact 0 (degree 0, bound 0) changes nothing there. Per
     * contribution its output, its position in that output's list and its constant weight (NaN for a variable).
     */
    private final int[] live;
    private int liveCount = -1;
    private final int[] contributionOutput;
    private final int[] contributionPosition;
    private final double[] constantWeight;
    /** Whether this instance still waits to take the kernel ({@link #KERNEL_AFTER}); false once decided either way. */
    private boolean kernelPending = true;
    private long compiledEvaluations;
    /**
     * The block's static filter once the kernel is in use (null when it does not cover the block): a step whose
     * static tests all pass computes only the doubles ({@link StaticFilter#step}); its running bounds are computed
     * when {@link #bound}, {@link #internals} or {@link #reset} asks ({@link #settleBounds}).
     */
    private StaticFilter staticFilter;
    /** Its generated step (null: {@link StaticFilter#step} interprets it), for the tests to switch off. */
    private StaticFilter.Step staticCode;
    /** Its generated front for a block with chain outputs (null: interpreted), for the tests to switch off. */
    private StaticFilter.Front staticFront;
    private double[] staticTd;
    private double[] staticRd;
    private double[] staticSd;
    private double[] staticOut;
    /** The inputs of the last step when the static filter decided it (its bounds not yet computed), else unused. */
    private double[] staticInputs;
    private boolean boundsPending;
    private long staticEvaluations;
    /** Steps of {@link #evaluate()}'s lean path (counted in evaluations and staticEvaluations, not in those fields). */
    private long leanSteps;
    /**
     * The evaluation at which an instance takes its block's kernel: a step or a program evaluated only a few times
     * (certify's vectors, the fuzzer) stays with the interpreter and never pays for generating the class. The results
     * do not depend on it: the kernel's are the interpreter's bit for bit.
     */
    static final int KERNEL_AFTER = 64;

    FunctionBlockInstance(BlockPlan plan) {
        this(plan, true);
    }

    FunctionBlockInstance(BlockPlan plan, boolean filtered) {
        this.plan = plan;
        this.filtered = filtered;
        this.values = plan.initialValues.clone();
        this.before = new double[values.length];
        this.slotErrors = new double[values.length];
        this.inputSlots = plan.inputNames.stream().mapToInt(plan.slotByName::get).toArray();
        this.integerSlot = new boolean[values.length];
        this.slotMin = new double[values.length];
        this.slotMax = new double[values.length];
        for (int i = 0; i < values.length; i++) {
            integerSlot[i] = plan.types[i].isInteger();
            slotMin[i] = plan.types[i].min();
            slotMax[i] = plan.types[i].max();
        }
        this.leanMin = new double[inputSlots.length];
        this.leanMax = new double[inputSlots.length];
        for (int i = 0; i < inputSlots.length; i++) {
            boolean integer = integerSlot[inputSlots[i]];
            leanMin[i] = integer ? Double.POSITIVE_INFINITY : slotMin[inputSlots[i]];
            leanMax[i] = integer ? Double.NEGATIVE_INFINITY : slotMax[inputSlots[i]];
        }
        this.termDegrees = new double[plan.termShape.length + plan.chainedTerms];
        this.termErrors = new double[termDegrees.length];
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
        this.repX = new double[shapes][];
        this.repY = new double[shapes][];
        for (int s = 0; s < shapes; s++) {
            repX[s] = new double[curX[s].length];
            repY[s] = new double[curY[s].length];
            representations(s);
        }
        this.valueRep = new double[values.length];
        for (int i = 0; i < values.length; i++) {
            valueRep[i] = representation(values[i]);
        }
        this.stack = new double[plan.maxStack];
        this.stackErrors = new double[plan.maxStack];
        this.bare = new double[Math.max(1, plan.maxBareTargets)];
        this.bareErrors = new double[bare.length];
        int terms = 0;
        for (OutputPlan o : plan.outputs) {
            terms = Math.max(terms, o.termShapes().length);
        }
        this.contributionDegree = new double[plan.contributionCount];
        this.contributionWeight = new double[plan.contributionCount];
        this.contributionError = new double[plan.contributionCount];
        this.contributionDegreeError = new double[plan.contributionCount];
        this.singletonDegree = new double[terms];
        this.singletonError = new double[terms];
        this.singletonRep = new double[terms];
        this.bounds = new double[plan.outputs.length];
        this.singletonValue = new double[terms];
        this.previous = new double[plan.outputs.length];
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            zeroSkip.put(rb, zeroSkip(rb));
        }
        this.live = new int[plan.contributionCount];
        this.constantWeight = new double[plan.contributionCount];
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            for (SubconclusionPlan[] scs : rb.conclusions()) {
                for (SubconclusionPlan sc : scs) {
                    if (sc.contribution() >= 0) {
                        constantWeight[sc.contribution()] = sc.weightSlot() < 0 ? sc.weightConst() : Double.NaN;
                    }
                }
            }
        }
        this.contributionOutput = new int[plan.contributionCount];
        this.contributionPosition = new int[plan.contributionCount];
        for (int i = 0; i < plan.outputs.length; i++) {
            int[] cs = plan.outputs[i].contributions();
            for (int k = 0; k < cs.length; k++) {
                contributionOutput[cs[k]] = i;
                contributionPosition[cs[k]] = k;
            }
        }
        this.smoothSets = new SmoothSet[plan.outputs.length];
        this.chains = plan.chains();
        for (int i = 0; i < smoothSets.length; i++) {
            smoothSets[i] = plan.smoothOutputs[i] ? new SmoothSet() : null;
        }
    }

    private ZeroSkip zeroSkip(RuleBlockPlan rb) {
        boolean absorbs = rb.and() == AndAlgorithm.MIN || rb.and() == AndAlgorithm.PROD;
        int rules = rb.conditions().length;
        int[] first = new int[rules];
        int[] from = new int[rules + 1];
        int total = 0;
        for (SubconclusionPlan[] scs : rb.conclusions()) {
            total += scs.length;
        }
        int[] contribution = new int[total];
        double[] weight = new double[total];
        int k = 0;
        for (int r = 0; r < rules; r++) {
            ConditionCode code = rb.conditions()[r];
            int n = code.flatTerms;
            boolean ok = n > 0 && code.ops[0] == ConditionCode.TERM
                    && (n == 1 || code.ops[n] == ConditionCode.AND && absorbs);
            for (SubconclusionPlan sc : rb.conclusions()[r]) {
                int c = sc.contribution();
                ok &= c >= 0 && sc.weightSlot() < 0
                        && (plan.contributionHedges.length == 0 || plan.contributionHedges[c] == null)
                        && plan.chainedDegree[c] < 0;     // BlockCompiler gives every contribution an entry
            }
            first[r] = ok ? code.args[0] : -1;
            from[r] = k;
            for (SubconclusionPlan sc : rb.conclusions()[r]) {
                contribution[k] = sc.contribution();
                weight[k++] = sc.weightConst();
            }
        }
        from[rules] = k;
        return new ZeroSkip(first, from, contribution, weight);
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
        store(plan.inputSlot(name, value), value);
    }

    /** The index of a VAR_INPUT (case-insensitive name), for {@link #setInput(int, double)}. */
    public int inputIndex(String name) throws EvaluationException {
        int slot = plan.slot(name);
        for (int i = 0; i < inputSlots.length; i++) {
            if (inputSlots[i] == slot) {
                return i;
            }
        }
        throw plan.notAnInput(slot);
    }

    /** The index of a VAR_OUTPUT (case-insensitive name), for {@link #output(int)}. */
    public int outputIndex(String name) throws EvaluationException {
        int slot = plan.slot(name);
        for (int i = 0; i < plan.outputSlots.length; i++) {
            if (plan.outputSlots[i] == slot) {
                return i;
            }
        }
        throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                "'" + plan.variableNames[slot] + "' is not a VAR_OUTPUT of function block '" + plan.name + "'");
    }

    /** Sets the input of that index (declaration order), as {@link #set(String, double)} does. */
    public void setInput(int index, double value) throws EvaluationException {
        int slot = inputSlots[index];
        plan.requireFinite(slot, value);
        store(slot, value);
    }

    /** Sets every input, {@code values} in declaration order. */
    public void setInputs(double... values) throws EvaluationException {
        if (values.length != inputSlots.length) {
            throw new IllegalArgumentException(values.length + " values for " + inputSlots.length + " inputs");
        }
        for (int i = 0; i < values.length; i++) {
            double v = values[i];
            // the common case without store's conversion: a real within its type's range (an integer input has an
            // empty range here); the representation distance is computed when a step needs it
            if (v >= leanMin[i] && v <= leanMax[i]) {
                this.values[inputSlots[i]] = v;
            } else {
                setInput(i, v);
            }
        }
    }

    /** The value of the output of that index (declaration order). */
    public double output(int index) {
        return values[plan.outputSlots[index]];
    }

    /**
     * The bound of the last value of an output: its distance from the exact value is at most this (0 when the
     * evaluation fell back to exact arithmetic, whose result is then the double nearest the exact value; NaN
     * for an output whose method the exact path computes in floating point too: smooth sets, Tsukamoto). For a
     * variable that bare conclusions wrote, the bound of that value.
     */
    public double bound(String output) throws EvaluationException {
        int slot = plan.slot(output);
        settleBounds();
        for (int i = 0; i < plan.outputs.length; i++) {
            if (plan.outputs[i].slot() == slot) {
                return bounds[i];
            }
        }
        return slotErrors[slot];       // a variable written by bare conclusions (or not written: 0)
    }

    /** Evaluations so far. */
    public long evaluations() {
        return evaluations + leanSteps;
    }

    /** Evaluations redone in exact arithmetic because a decision was too close for the error bounds. */
    public long fallbacks() {
        return fallbacks;
    }

    /**
     * Evaluations with such a decision that could not be redone exactly: the block uses a dialect construct the
     * exact path does not evaluate (Takagi–Sugeno terms, hedges in conclusions, output terms in conditions,
     * Tsukamoto, activations outside Table 4), so the double result stands.
     */
    public long undecidedWithoutExact() {
        return undecidedWithoutExact;
    }

    /** The current value of any variable (input, output or local), by case-insensitive name. */
    public double get(String name) throws EvaluationException {
        return values[plan.slot(name)];
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
        settleBounds();
        System.arraycopy(plan.initialValues, 0, values, 0, values.length);
        refreshRepresentations();
    }

    public void evaluate() throws EvaluationException {
        StaticFilter.Step code = staticCode;
        if (code != null && code.step(values, staticInputs)) {
            // the lean path of a block the static filter decides: its generated step alone (see staticStep)
            leanSteps++;
            boundsPending = true;
            return;
        }
        evaluate(null, code == null);
    }

    /**
     * One evaluation: fuzzification, the rule blocks in textual order, then defuzzification; redone exactly when a
     * decision is too close for the error bounds.
     */
    public void evaluate(Trace trace) throws EvaluationException {
        evaluate(trace, true);
    }

    /** {@link #evaluate(Trace)}; {@code tryStatic} false when the static step has just failed on this step. */
    private void evaluate(Trace trace, boolean tryStatic) throws EvaluationException {
        evaluations++;
        if (kernelPending && evaluations > KERNEL_AFTER && filtered) {
            useKernel();
        }
        if (tryStatic && staticFilter != null && trace == null && staticStep()) {
            return;
        }
        boundsPending = false;
        if (!filtered) {
            evaluateInDoubles(trace);
            return;
        }
        System.arraycopy(values, 0, before, 0, values.length);
        undecided = false;
        EvaluationException failed = null;
        try {
            evaluateInDoubles(trace);
        } catch (EvaluationException e) {
            if (!undecided) {
                throw e;
            }
            failed = e;
        }
        if (undecided) {
            ExactInstance judge = exactInstance();
            if (judge == null) {
                undecidedWithoutExact++;
                if (failed != null) {
                    throw failed;
                }
                return;
            }
            fallbacks++;
            judge.evaluateFrom(before);
            judge.copyState(values, plan.isInput);
            java.util.Arrays.fill(bounds, 0.0);
            java.util.Arrays.fill(slotErrors, 0.0);
            if (trace != null) {
                trace.decidedExactly(judge.results());
            }
        }
    }

    /** Takes the block's compiled kernel, if its plan is covered; returns whether it did (also for the tests). */
    boolean useKernel() {
        kernelPending = false;
        KernelCompiler.Compiled compiled = plan.kernel();
        if (compiled != null) {
            kernel = compiled.kernel();
            kernelOutputs = compiled.outputs();
            staticFilter = plan.staticFilter();
            if (staticFilter != null) {
                staticCode = staticFilter.compiled;
                staticFront = staticFilter.front;
                staticTd = new double[staticFilter.terms];
                staticRd = new double[staticFilter.rules];
                staticSd = new double[staticFilter.maxOutputTerms];
                staticOut = new double[staticFilter.outputSlot.length];
                staticInputs = new double[inputSlots.length];
            }
        }
        return kernel != null;
    }

    /**
     * A step decided by the static filter: the outputs stored, the bounds left for {@link #settleBounds}; false (and
     * nothing changed) when a static test fails or an output would not fit its type, so that the step is evaluated
     * with the running bounds.
     */
    private boolean staticStep() {
        StaticFilter.Step code = staticCode;
        if (!(code != null ? code.step(values, staticInputs)
                : staticFilter.step(values, staticInputs, staticTd, staticRd, staticSd, staticOut, staticFront, set,
                        setArea))) {
            return false;
        }
        boundsPending = true;
        staticEvaluations++;
        return true;
    }

    /**
     * The running bounds of the last step when the static filter decided it: the step evaluated again from its
     * inputs with the running bounds (the kernel's path; the same doubles), counters and the current inputs kept.
     * The static bounds dominate the running ones, so the running bounds decide it too and give the same outputs;
     * anything else is a fault of the static bounds and is reported as one.
     */
    private void settleBounds() {
        if (!boundsPending) {
            return;
        }
        boundsPending = false;
        double[] current = new double[inputSlots.length];
        for (int k = 0; k < inputSlots.length; k++) {
            current[k] = values[inputSlots[k]];
            values[inputSlots[k]] = staticInputs[k];
        }
        int[] slots = staticFilter.outputSlot;
        double[] decided = new double[slots.length];
        for (int i = 0; i < slots.length; i++) {
            decided[i] = values[slots[i]];
        }
        long compiledBefore = compiledEvaluations;
        undecided = false;
        try {
            evaluateInDoubles(null);
        } catch (EvaluationException e) {
            throw new IllegalStateException("the static filter decided a step the running bounds reject", e);
        }
        compiledEvaluations = compiledBefore;
        for (int i = 0; i < slots.length; i++) {
            if (undecided || Double.doubleToRawLongBits(decided[i]) != Double.doubleToRawLongBits(values[slots[i]])) {
                throw new IllegalStateException("the static filter decided a step the running bounds do not ("
                        + (undecided ? lastDecision : "output " + decided[i] + " against " + values[slots[i]]) + ")");
            }
        }
        for (int k = 0; k < inputSlots.length; k++) {
            values[inputSlots[k]] = current[k];
        }
        refreshRepresentations();
    }

    /**
     * Evaluations the static filter decided: computed in doubles and compared with constant bounds only, their
     * running bounds computed when asked (docs/semantics.md, "The static filter").
     */
    public long staticEvaluations() {
        return staticEvaluations + leanSteps;
    }

    /** Every slot's representation distance from its current value (setInputs and the static filter leave them). */
    private void refreshRepresentations() {
        for (int i = 0; i < values.length; i++) {
            valueRep[i] = representation(values[i]);
        }
    }

    /** The static filter in use, or null (for the tests). */
    StaticFilter staticFilter() {
        return staticFilter;
    }

    /** Runs the static filter's step as {@link StaticFilter#step} instead of its generated code (for the tests). */
    void interpretStaticStep() {
        staticCode = null;
        staticFront = null;
    }

    /** Never takes the kernel: the interpreter alone (for the agreement tests). */
    void interpretOnly() {
        settleBounds();
        kernelPending = false;
        kernel = null;
        kernelOutputs = null;
        staticFilter = null;
    }

    /**
     * Evaluations whose fuzzification and rule blocks ran as the compiled kernel (the same doubles as the
     * interpreter's; see {@link #KERNEL_AFTER}).
     */
    public long compiledEvaluations() {
        return compiledEvaluations + staticEvaluations + leanSteps;
    }

    /** Whether the kernel computes output {@code index} whole (accumulation and defuzzification too). */
    boolean kernelComputesOutput(int index) {
        return kernelOutputs != null && kernelOutputs[index];
    }

    /** The term degrees and the contributions with their bounds, as the last evaluation left them (for the tests). */
    double[][] internals() {
        settleBounds();
        return new double[][] {termDegrees.clone(), termErrors.clone(), contributionDegree.clone(),
            contributionWeight.clone(), contributionError.clone(), contributionDegreeError.clone(), bounds.clone()};
    }

    /** A copy of every variable's current value, by slot (for the agreement tests: the state a step starts from). */
    double[] state() {
        return values.clone();
    }

    /** The exact path on this block, made when first needed; null when the block uses constructs it lacks. */
    private ExactInstance exactInstance() {
        if (exact == null && !exactUnavailable) {
            try {
                exact = new ExactInstance(plan, NumberReading.DECIMAL);
            } catch (IllegalArgumentException e) {
                exactUnavailable = true;
            }
        }
        return exact;
    }

    /** A decision point the error bounds cannot settle: the evaluation is redone exactly. */
    private void undecided(String decision) {
        if (!undecided) {
            undecided = true;
            lastDecision = decision;
        }
    }

    /** The first decision the bounds could not settle in the last evaluation that fell back (for the tests). */
    String lastUndecided() {
        return lastDecision;
    }

    private void evaluateInDoubles(Trace trace) throws EvaluationException {
        if (trace != null) {
            trace.clear();
        }
        java.util.Arrays.fill(slotErrors, 0.0);
        refreshRepresentations();
        for (int i = 0; i < plan.outputs.length; i++) {
            previous[i] = values[plan.outputs[i].slot()];
        }
        resolveVariableShapes();
        boolean compiled = kernel != null && trace == null;
        if (compiled) {
            // the kernel's plans have no chained terms, output-value conditions nor bare conclusions
            clearLive();
            liveCount = kernel.front(values, valueRep, termDegrees, termErrors, contributionDegree, contributionWeight,
                    contributionError, contributionDegreeError, live);
            compiledEvaluations++;
        } else {
            liveCount = -1;
            fuzzify(trace);
            for (int t = plan.termShape.length; t < termDegrees.length; t++) {
                termDegrees[t] = 0.0;           // 'output IS term' (dialects): nothing concluded yet
                termErrors[t] = 0.0;
            }
            if (plan.valueTermShape != null) {
                valueConditions();
            }
            for (RuleBlockPlan rb : plan.ruleBlocks) {
                runRuleBlock(rb, trace);
            }
        }
        for (int i = 0; i < plan.outputs.length; i++) {
            defuzzify(i, plan.outputs[i], previous[i], smoothSets[i], trace, compiled && kernelOutputs[i]);
        }
    }

    /**
     * Before the kernel runs: every contribution it wrote in the step before (all of them after the interpreter)
     * back to what runRuleBlock's ZeroSkip writes, degree 0, its constant weight, bounds 0.
     */
    private void clearLive() {
        if (liveCount < 0) {
            java.util.Arrays.fill(contributionDegree, 0.0);
            java.util.Arrays.fill(contributionError, 0.0);
            java.util.Arrays.fill(contributionDegreeError, 0.0);
            for (int c = 0; c < constantWeight.length; c++) {
                if (!Double.isNaN(constantWeight[c])) {
                    contributionWeight[c] = constantWeight[c];
                }
            }
            return;
        }
        for (int k = 0; k < liveCount; k++) {
            int c = live[k];
            contributionDegree[c] = 0.0;
            contributionError[c] = 0.0;
            contributionDegreeError[c] = 0.0;     // its weight, if constant, is the constant already
        }
    }

    /** Writes a value, converting to the variable's integer type (8.: half away from zero). */
    private double store(int slot, double value) throws EvaluationException {
        double v = integerSlot[slot] ? Conversions.roundHalfAwayFromZero(value) : value;
        if (v < slotMin[slot] || v > slotMax[slot]) {
            DataType type = plan.types[slot];
            throw new EvaluationException(EvaluationCode.OUT_OF_RANGE, "value " + value + " of '"
                    + plan.variableNames[slot] + "' does not fit its data type " + type);
        }
        values[slot] = v;
        valueRep[slot] = representation(v);
        return v;
    }

    private void resolveVariableShapes() {
        for (int s : variableShapes) {
            plan.shapes[s].resolve(values, curX[s], curY[s]);
            representations(s);
        }
    }

    private void representations(int s) {
        for (int i = 0; i < repX[s].length; i++) {
            repX[s][i] = representation(curX[s][i]);
            repY[s][i] = representation(curY[s][i]);
        }
    }

    /** 5.2.2: the degree of every term of every fuzzified input, with its error bound. */
    private void fuzzify(Trace trace) {
        int[] termShape = plan.termShape;
        for (int t = 0; t < termShape.length; t++) {
            int s = termShape[t];
            double u = values[plan.termVariableSlot[t]];
            termDegrees[t] = degree(s, u, valueRep[plan.termVariableSlot[t]], t);
            if (trace != null) {
                trace.add(new Trace.TermDegree(plan.termVariableName[t], plan.termName[t], termDegrees[t]));
            }
        }
    }

    /**
     * The degree of shape s at u, its error bound into termErrors[t]. The exact path reads every double as its
     * shortest decimal ({@link NumberReading#DECIMAL}), so an input or a point carries the distance between the
     * two ({@link #representation}); comparisons of doubles are exact (the reading keeps their order), so an
     * input at a vertex or a singleton is decided in doubles.
     */
    private double degree(int s, double u, double uRep, int t) {
        Shape shape = plan.shapes[s];
        double[] x = curX[s];
        double[] y = curY[s];
        if (shape.singleton || shape.kind != null) {
            termErrors[t] = 0;              // a named shape: the exact path takes the same double formula's value
            return shape.singleton ? (u == x[0] ? 1.0 : 0.0) : shape.kind.degree(shape.params, u);
        }
        int n = shape.n;
        if (u < x[0]) {
            termErrors[t] = repY[s][0];
            return y[0];
        }
        if (u > x[n - 1]) {
            termErrors[t] = repY[s][n - 1];
            return y[n - 1];
        }
        int i = n <= 8 ? Pwl.linearLowerBound(x, u) : Pwl.lowerBound(x, n, u);
        if (x[i] == u) {
            return degreeAtPoint(s, i, u, t);
        }
        double y0 = y[i - 1];
        double y1 = y[i];
        double d = Pwl.interpolate(x[i - 1], y0, x[i], y1, u);
        double e = Math.max(repY[s][i - 1], repY[s][i]);
        if (y0 != y1 && (uRep != 0 || repX[s][i - 1] != 0 || repX[s][i] != 0)) {
            // the exact inputs may sit up to the representation errors away: t = (u - x0)/(x1 - x0) moves by at most
            // 2·(δu + δx0 + δx1)/(x1 - x0) while the perturbation is under a quarter of the width
            double shift = uRep + repX[s][i - 1] + repX[s][i];
            double width = x[i] - x[i - 1];
            e = 4 * shift < width ? e + Math.abs(y1 - y0) * 2 * shift / width + 2 * Norms.R
                    : Double.POSITIVE_INFINITY;
        } else if (y0 != y1) {
            e += 2 * Norms.R;           // the interpolation's rounding alone (its inputs are exact)
        }
        termErrors[t] = e;
        return d;
    }

    /** {@link #degree} at a point of the shape (the largest degree of the points at u, a jump). */
    private double degreeAtPoint(int s, int i, double u, int t) {
        double[] x = curX[s];
        double[] y = curY[s];
        double max = y[i];
        double e = repY[s][i];
        for (int j = i + 1; j < x.length && x[j] == u; j++) {
            max = Math.max(max, y[j]);
            e = Math.max(e, repY[s][j]);
        }
        termErrors[t] = e;
        return max;
    }

    /**
     * The distance between a double and the shortest decimal that reads as it (the exact path's reading): 0 for
     * an integer below 2^53 and for a multiple of 1/1024 below 2^20 (their decimals are exact), else half an ulp.
     */
    static double representation(double v) {
        double a = Math.abs(v);
        if (a < 0x1.0p20) {
            double s = a * 1024;         // below 2^30: the conversion to long is exact for an integer
            return s == (double) (long) s ? 0 : Math.ulp(v) * 0.5;
        }
        return a < 0x1.0p53 && a == (double) (long) a ? 0 : Math.ulp(v) * 0.5;
    }

    /**
     * jFuzzyLogic's 'output IS term' in a condition: the term's degree at the output's value when the evaluation
     * begins, which is its numeric DEFAULT (jFuzzyLogic resets it so before the rules) or, with DEFAULT NC, the value
     * of the last evaluation.
     */
    private void valueConditions() {
        for (int k = 0; k < plan.valueTermShape.length; k++) {
            double u = Double.isNaN(plan.valueTermStart[k]) ? values[plan.valueTermSlot[k]] : plan.valueTermStart[k];
            termDegrees[plan.termShape.length + k] = degree(plan.valueTermShape[k], u, representation(u),
                    plan.termShape.length + k);
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
            bareErrors[j] = 0;
        }
        ConditionCode[] conditions = rb.conditions();
        AndAlgorithm and = rb.and();
        OrAlgorithm or = rb.or();
        ZeroSkip skip = zeroSkip.get(rb);
        int[] first = skip.firstTerm;
        for (int r = 0; r < conditions.length; r++) {
            int t0 = first[r];
            if (t0 >= 0 && trace == null && termDegrees[t0] == 0 && termErrors[t0] == 0) {
                // what the steps below give for an exact 0 (aggregateTerms stops at it): d = 0, w·d bound 0
                for (int k = skip.from[r]; k < skip.from[r + 1]; k++) {
                    int c = skip.contribution[k];
                    contributionDegree[c] = 0;
                    contributionWeight[c] = skip.weight[k];
                    contributionError[c] = 0;
                    contributionDegreeError[c] = 0;
                }
                continue;
            }
            ConditionCode code = conditions[r];
            double d = code.flatTerms > 0 ? aggregateTerms(code, and, or) : aggregate(code, and, or);
            double ruleDegree = d;
            double ruleError = stackErrors[0];
            double e = ruleError;
            if (trace != null) {
                trace.add(new Trace.RuleDegree(rb.name(), rb.ruleNames()[r], d));
            }
            for (SubconclusionPlan sc : rb.conclusions()[r]) {
                org.fclcert.model.Hedge[] hedged = sc.contribution() < 0 || plan.contributionHedges.length == 0 ? null
                        : plan.contributionHedges[sc.contribution()];
                d = ruleDegree;
                e = ruleError;
                if (hedged != null) {
                    for (int k = hedged.length - 1; k >= 0; k--) {     // as Hedge.applyAll: nearest the term first
                        org.fclcert.model.Hedge h = hedged[k];
                        double hd = h.apply(d);
                        e = Norms.hedgeError(h, d, e, hd);
                        d = hd;
                    }
                }
                double w = sc.weightSlot() < 0 ? sc.weightConst() : clamp01(values[sc.weightSlot()]);
                double ew = sc.weightSlot() < 0 ? representation(w)
                        : (w == values[sc.weightSlot()] ? valueRep[sc.weightSlot()] : 0) + slotErrors[sc.weightSlot()];
                double wd = w * d;
                double ewd = Norms.productError(w, ew, d, e, wd);
                if (sc.contribution() >= 0) {
                    contributionDegree[sc.contribution()] = d;
                    contributionWeight[sc.contribution()] = w;
                    contributionError[sc.contribution()] = ewd;
                    contributionDegreeError[sc.contribution()] = e;
                    int chained = plan.chainedDegree[sc.contribution()];     // -1: not chained
                    if (chained >= 0) {
                        AccumulationMethod accu = plan.chainedAccumulation[sc.contribution()];
                        double acc = Norms.accumulate(accu, termDegrees[chained], wd);
                        termErrors[chained] = Norms.accumulateError(accu, termDegrees[chained], termErrors[chained],
                                wd, ewd, acc);
                        termDegrees[chained] = acc;
                    }
                } else {
                    double acc = Norms.accumulate(rb.accumulation(), bare[sc.bareTarget()], wd);
                    bareErrors[sc.bareTarget()] = Norms.accumulateError(rb.accumulation(), bare[sc.bareTarget()],
                            bareErrors[sc.bareTarget()], wd, ewd, acc);
                    bare[sc.bareTarget()] = acc;
                }
                if (trace != null) {
                    trace.add(new Trace.Activation(rb.name(), rb.ruleNames()[r], sc.variable(),
                            Optional.ofNullable(sc.term()), w, wd));
                }
            }
        }
        for (int j = 0; j < targets; j++) {
            double v = rb.accumulation() == AccumulationMethod.NSUM ? bare[j] / Math.max(1.0, bare[j]) : bare[j];
            int slot = rb.bareTargetSlots()[j];
            double ev = rb.accumulation() == AccumulationMethod.NSUM ? bareErrors[j] * 2 + Norms.R : bareErrors[j];
            if (plan.types[slot].isInteger() && nearHalf(v, ev)) {
                undecided("INT rounding of a bare conclusion");
            }
            double stored = store(slot, v);
            slotErrors[slot] = ev;
            if (trace != null) {
                trace.add(new Trace.Result(plan.variableNames[slot], stored, Trace.Outcome.ASSIGNED));
            }
        }
    }

    /**
     * Whether rounding v (exact value within e of it) to an integer type is undecided: an infinite bound, or a
     * half-integer within the bound (rounding half away from zero decides exactly at .5 itself only when e = 0).
     */
    static boolean nearHalf(double v, double e) {
        if (e == 0) {
            return false;
        }
        if (!(e < Double.POSITIVE_INFINITY)) {
            return true;
        }
        double a = Math.abs(v);
        double f = a - Math.floor(a);
        return Math.abs(f - 0.5) <= e;
    }

    /** Runs a condition's postfix code (Table 3 operators; NOT = 1 − a), the bound of each degree alongside. */
    private double aggregate(ConditionCode code, AndAlgorithm and, OrAlgorithm or) {
        int[] ops = code.ops;
        int[] args = code.args;
        double[] st = stack;
        double[] er = stackErrors;
        int sp = 0;
        for (int i = 0; i < ops.length; i++) {
            switch (ops[i]) {
                case ConditionCode.TERM -> {
                    st[sp] = termDegrees[args[i]];
                    er[sp++] = termErrors[args[i]];
                }
                case ConditionCode.TERM_NOT -> {
                    double d = termDegrees[args[i]];
                    st[sp] = 1.0 - d;
                    er[sp++] = Norms.notError(d, termErrors[args[i]]);
                }
                case ConditionCode.VARIABLE -> {
                    st[sp] = clamp01(values[args[i]]);
                    er[sp] = (st[sp] == values[args[i]] ? valueRep[args[i]] : 0) + slotErrors[args[i]];
                    sp++;
                }
                case ConditionCode.NOT -> {
                    er[sp - 1] = Norms.notError(st[sp - 1], er[sp - 1]);
                    st[sp - 1] = 1.0 - st[sp - 1];
                }
                case ConditionCode.AND -> sp = fold(st, er, sp, args[i], true, and, or);
                case ConditionCode.HEDGE -> {
                    double h = HEDGES[args[i]].apply(st[sp - 1]);
                    er[sp - 1] = Norms.hedgeError(HEDGES[args[i]], st[sp - 1], er[sp - 1], h);
                    st[sp - 1] = h;
                }
                case ConditionCode.ONE -> {
                    st[sp] = 1.0;
                    er[sp++] = 0;
                }
                default -> sp = fold(st, er, sp, args[i], false, and, or);
            }
        }
        return st[0];
    }

    /**
     * {@link #aggregate} for one AND or OR of terms, folded in the same order without the stack. An AND by MIN or
     * PROD stops at an exact 0: every later step would give an exact 0 again.
     */
    private double aggregateTerms(ConditionCode code, AndAlgorithm and, OrAlgorithm or) {
        int[] ops = code.ops;
        int[] args = code.args;
        int n = code.flatTerms;
        boolean isAnd = n > 1 && ops[n] == ConditionCode.AND;
        boolean absorbs = isAnd && (and == AndAlgorithm.MIN || and == AndAlgorithm.PROD);
        double acc = termDegrees[args[0]];
        double e = termErrors[args[0]];
        if (ops[0] == ConditionCode.TERM_NOT) {
            e = Norms.notError(acc, e);
            acc = 1.0 - acc;
        }
        for (int j = 1; j < n; j++) {
            if (absorbs && acc == 0 && e == 0) {
                break;
            }
            double y = termDegrees[args[j]];
            double ey = termErrors[args[j]];
            if (ops[j] == ConditionCode.TERM_NOT) {
                ey = Norms.notError(y, ey);
                y = 1.0 - y;
            }
            double r = isAnd ? Norms.and(and, acc, y) : Norms.or(or, acc, y);
            e = isAnd ? Norms.andError(and, acc, e, y, ey, r) : Norms.orError(or, acc, e, y, ey, r);
            acc = r;
        }
        stackErrors[0] = e;
        return acc;
    }

    private static int fold(double[] st, double[] er, int sp, int n, boolean isAnd, AndAlgorithm and, OrAlgorithm or) {
        int base = sp - n;
        double acc = st[base];
        double e = er[base];
        for (int j = base + 1; j < sp; j++) {
            double r = isAnd ? Norms.and(and, acc, st[j]) : Norms.or(or, acc, st[j]);
            e = isAnd ? Norms.andError(and, acc, e, st[j], er[j], r) : Norms.orError(or, acc, e, st[j], er[j], r);
            acc = r;
        }
        st[base] = acc;
        er[base] = e;
        return base + 1;
    }

    private static double clamp01(double v) {
        return Math.max(0.0, Math.min(1.0, v));
    }

    /** The bound of the value the method just computed (see {@link #bound(String)}). */
    private double methodBound;
    /** The unit roundoff of a double. */
    private static final double U = 0x1.0p-53;
    private static final int[] NONE = {};

    /** Accumulation and defuzzification of one output, or DEFAULT / NC when nothing fired. */
    private void defuzzify(int index, OutputPlan o, double previousValue, SmoothSet smooth, Trace trace,
            boolean compiled) throws EvaluationException {
        for (int s : compiled ? NONE : o.termShapes()) {     // the kernel's outputs have no computed terms
            if (plan.shapes[s].computed != null) {      // Takagi–Sugeno: the value now, after the outputs before it
                plan.shapes[s].resolve(values, curX[s], curY[s]);
                representations(s);
            }
        }
        methodBound = 0;
        double result = compiled ? compiledOutput(index)
                : o.singletons() ? singletons(o, trace)
                : o.method() == DefuzzificationMethod.TSUKAMOTO ? tsukamoto(o, trace)
                : smooth != null ? smoothSet(o, smooth, trace) : pointSet(o, chains[index], trace);
        Trace.Outcome outcome = Trace.Outcome.DEFUZZIFIED;
        if (Double.isNaN(result) && !(smooth != null ? smooth.empty() : nothingFired(o))) {
            undecided("overflow");     // an overflow in doubles: exact arithmetic has the value
            throw new EvaluationException(EvaluationCode.NO_RESULT,
                    "defuzzification of '" + o.variable() + "' has no numeric result (the arithmetic overflowed)");
        }
        if (Double.isNaN(result)) {
            outcome = o.noChange() ? Trace.Outcome.NO_CHANGE : Trace.Outcome.DEFAULT;
            result = o.noChange() ? previousValue : o.defaultValue();
            // the DEFAULT literal is the same number on the exact path; NC keeps the value and its bound
            methodBound = o.noChange() ? bounds[index] : 0;
        }
        boolean nanDefault = Double.isNaN(result) && outcome == Trace.Outcome.DEFAULT;   // DEFAULT := nan (fuzzylite)
        if (!Double.isFinite(result) && !nanDefault) {
            undecided("overflow");
            throw new EvaluationException(EvaluationCode.NO_RESULT,
                    "defuzzification of '" + o.variable() + "' overflowed (result " + result + ")");
        }
        if (integerSlot[o.slot()] && nearHalf(result, methodBound)) {
            undecided("INT rounding at .5");            // half away from zero, within the bound
        }
        bounds[index] = methodBound;
        slotErrors[o.slot()] = methodBound;
        double stored = store(o.slot(), result);
        if (trace != null) {
            trace.add(new Trace.Result(o.variable(), stored, outcome, result));
        }
    }

    /**
     * The kernel's {@link #singletons} for an output it compiled: the same degrees, bounds, value and first
     * undecided decision.
     */
    private double compiledOutput(int index) {
        double result = kernel.output(index, contributionDegree, contributionWeight, contributionError,
                singletonDegree, singletonError, kernelScratch);
        methodBound = kernelScratch[0];
        if (kernelScratch[1] == 1) {
            undecided("whether any rule fired");
        } else if (kernelScratch[1] == 2) {
            undecided("CoGS bound");
        }
        return result;
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

    /**
     * Each term's accumulated degree (point 4: w·d of every subconclusion naming it, NSUM normalised) into
     * singletonDegree, its bound into singletonError; decides whether anything fired.
     */
    private void degreesPerTerm(OutputPlan o) {
        int terms = o.termShapes().length;
        for (int t = 0; t < terms; t++) {
            singletonDegree[t] = 0;
            singletonError[t] = 0;
        }
        int[] cs = o.contributions();
        for (int i = 0; i < cs.length; i++) {
            int t = o.contributionTerm()[i];
            double a = contributionWeight[cs[i]] * contributionDegree[cs[i]];
            double acc = Norms.accumulate(o.accumulation(), singletonDegree[t], a);
            singletonError[t] = Norms.accumulateError(o.accumulation(), singletonDegree[t], singletonError[t], a,
                    contributionError[cs[i]], acc);
            singletonDegree[t] = acc;
        }
        if (o.accumulation() == AccumulationMethod.NSUM) {
            double max = 1.0;
            double maxError = 0;
            for (int t = 0; t < terms; t++) {
                if (singletonDegree[t] > max) {
                    max = singletonDegree[t];
                    maxError = singletonError[t];
                }
            }
            for (int t = 0; t < terms; t++) {
                singletonDegree[t] /= max;
                singletonError[t] = (singletonError[t] + maxError) / max + Norms.R;
            }
        }
        boolean fired = false;
        boolean certainlyEmpty = true;
        for (int t = 0; t < terms; t++) {
            fired |= singletonDegree[t] > singletonError[t];
            certainlyEmpty &= singletonDegree[t] == 0 && singletonError[t] == 0;
        }
        if (!fired && !certainlyEmpty) {
            undecided("whether any rule fired");
        }
    }

    /** Singleton outputs accumulate per term; CoGS (= CoG), LM and RM over the terms. NaN if empty. */
    private double singletons(OutputPlan o, Trace trace) {
        int terms = o.termShapes().length;
        for (int t = 0; t < terms; t++) {
            singletonValue[t] = curX[o.termShapes()[t]][0];
            singletonRep[t] = repX[o.termShapes()[t]][0];
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
     * nothing fired. The exact path does not evaluate it: no bound.
     */
    private double tsukamoto(OutputPlan o, Trace trace) {
        int terms = o.termShapes().length;
        degreesPerTerm(o);
        methodBound = Double.NaN;
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
        double spread = 0;
        double rounding = 0;
        boolean any = false;
        for (int t = 0; t < terms; t++) {
            num += singletonValue[t] * singletonDegree[t];
            any |= singletonDegree[t] != 0;
            spread += Math.abs(singletonValue[t]) * singletonError[t]
                    + singletonDegree[t] * singletonRep[t];
            rounding += Math.abs(singletonValue[t]) * singletonDegree[t];
        }
        methodBound = spread + 2 * (terms + 1) * U * rounding;
        return any ? num : Double.NaN;
    }

    /**
     * CoGS: Σ v·μ / Σ μ. Bound: moving the degrees by their bounds moves the quotient by at most
     * Σ |v − c|·e / (Σ μ − Σ e), the values' decimal readings by their largest distance, the sums' rounding by
     * 2(n + 1)·u·max |v|; undecided when Σ μ does not exceed Σ e.
     */
    private double centreOfGravityForSingletons(int terms) {
        double num = 0;
        double den = 0;
        double errors = 0;
        double maxAbs = 0;
        double maxRep = 0;
        for (int t = 0; t < terms; t++) {
            num += singletonValue[t] * singletonDegree[t];
            den += singletonDegree[t];
            errors += singletonError[t];
            maxAbs = Math.max(maxAbs, Math.abs(singletonValue[t]));
            maxRep = Math.max(maxRep, singletonRep[t]);
        }
        if (!(den > 0)) {
            return Double.NaN;
        }
        double c = num / den;
        if (errors == 0) {
            methodBound = maxRep + 2 * (terms + 1) * U * maxAbs;
        } else if (den > errors) {
            double spread = 0;
            for (int t = 0; t < terms; t++) {
                spread += Math.abs(singletonValue[t] - c) * singletonError[t];
            }
            methodBound = spread / (den - errors) + maxRep + 2 * (terms + 1) * U * maxAbs;
        } else {
            methodBound = Double.POSITIVE_INFINITY;
            undecided("CoGS bound");
        }
        return c;
    }

    /**
     * The index of the largest degree; marks undecided any other singleton whose degree the bounds cannot tell
     * from it (a tie or near tie for LM, RM, MoM), unless both are at the same value (then the tie does not matter).
     */
    private int supremumSingleton(int terms) {
        int m = 0;
        for (int t = 1; t < terms; t++) {
            if (singletonDegree[t] > singletonDegree[m]) {
                m = t;
            }
        }
        double sup = singletonDegree[m];
        for (int t = 0; t < terms; t++) {
            if (t == m || singletonValue[t] == singletonValue[m]) {
                continue;
            }
            double e = singletonError[t] + singletonError[m];
            if (e > 0 && sup - singletonDegree[t] <= e) {
                undecided("tie for the maximum");
            }
        }
        return m;
    }

    private double extremeSingleton(int terms, boolean leftmost) {
        double sup = singletonDegree[supremumSingleton(terms)];
        if (!(sup > 0)) {
            return Double.NaN;
        }
        double best = leftmost ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        for (int t = 0; t < terms; t++) {
            if (singletonDegree[t] == sup) {
                best = leftmost ? Math.min(best, singletonValue[t]) : Math.max(best, singletonValue[t]);
            }
        }
        methodBound = representation(best);
        return best;
    }

    /**
     * MoM on singletons (Open Level, O-MOM): the mean of the distinct values of the singletons whose
     * accumulated degree is the supremum (two terms at one value count once, as one point of the set).
     */
    private double meanOfMaximalSingletons(int terms) {
        double sup = singletonDegree[supremumSingleton(terms)];
        if (!(sup > 0)) {
            return Double.NaN;
        }
        double sum = 0;
        int count = 0;
        double maxAbs = 0;
        for (int t = 0; t < terms; t++) {
            if (singletonDegree[t] == sup && !maximalValueBefore(t, sup)) {
                sum += singletonValue[t];
                count++;
                maxAbs = Math.max(maxAbs, Math.abs(singletonValue[t]) + singletonRep[t]);
            }
        }
        methodBound = 2 * (count + 1) * U * maxAbs + maxAbs * U;
        return sum / count;
    }

    private boolean maximalValueBefore(int t, double sup) {
        for (int s = 0; s < t; s++) {
            if (singletonValue[s] == singletonValue[t] && singletonDegree[s] == sup) {
                return true;
            }
        }
        return false;
    }

    /** Point-term outputs: the exact accumulated set, then CoG, CoA, LM or RM on it. NaN if empty. */
    private double pointSet(OutputPlan o, TermChain chain, Trace trace) throws EvaluationException {
        double spread = collect(o, set.act, true);
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
        boolean chained = chain != null && set.buildChain(chain, lo, hi, curX, curY);
        if (!chained) {
            set.build(o.accumulation(), lo, hi, curX, curY, plan.shapes);
        }
        if (trace != null) {
            List<Trace.Breakpoint> pts = new ArrayList<>();
            for (int j = 0; j < set.np; j++) {
                pts.add(new Trace.Breakpoint(set.px[j], set.py[j]));
            }
            trace.add(new Trace.AccumulatedSet(o.variable(), false, pts));
        }
        double result = defuzzifySet(o.method());
        if (set.act.n > 0) {
            decideSet(o, spread, lo, hi, result);
        }
        return result;
    }

    /**
     * The decisions of a point set's defuzzification and the bound of its value (docs/semantics.md). The degree of
     * the accumulated set is everywhere within {@code spread} of the exact one (MAX: the largest bound of a
     * contribution; the sums: their total).
     * <ul>
     * <li>CoG: ∫|Δμ| ≤ Δ = spread·W + 8(np + 2)·u·M (W the interval's width, M its largest |u|, the last term
     * the rounding of the vertices), so the centre moves by at most W·Δ / (A − Δ), plus the rounding of the sums;
     * undecided unless the area A exceeds 2Δ.</li>
     * <li>CoA: its halving point jumps across gaps of degree 0; always decided exactly.</li>
     * <li>LM, RM, MoM: undecided when a vertex is near the supremum without being equal to it, when a MIN clip
     * level is near a vertex degree of its term (a clip crossing at a vertex), when the points at the supremum
     * form more than one run and a bound is not 0, or for an accumulation other than MAX with a bound not 0.</li>
     * </ul>
     */
    private void decideSet(OutputPlan o, double spread, double lo, double hi, double result) {
        double width = hi - lo;
        double m = setScale(lo, hi);
        double rounding = setRounding(set.np, m);
        switch (o.method()) {
            case COA -> {
                methodBound = Double.POSITIVE_INFINITY;
                undecided("CoA");
            }
            case LM, RM, MOM -> {
                if (o.accumulation() != AccumulationMethod.MAX || !Double.isFinite(spread)) {
                    methodBound = Double.POSITIVE_INFINITY;
                    undecided("LM/RM/MoM on an accumulation other than MAX");
                    return;
                }
                clipsAtVertices(o);
                double steepest = steepestRun;
                double representation = vertexRepresentation;
                double sup = Defuzzifier.supremum(set.py, set.np);
                double band = spread + representation + 4 * Norms.R;
                int runs = 0;
                for (int j = 0; j < set.np; j++) {
                    if (set.py[j] != sup && set.py[j] > sup - band) {
                        undecided("near tie for the maximum");
                    }
                    if (set.py[j] == sup && (j == 0 || set.py[j - 1] != sup)) {
                        runs++;
                    }
                }
                if (runs > 1 && !(spread == 0 && representation == 0 && !roundedLevels)) {
                    undecided("separate maxima");      // equal in doubles, not known to be equal exactly
                }
                methodBound = band * steepest + 4 * Norms.R * m;
            }
            default -> {
                double area = setArea[0];      // Defuzzifier.area of this set, summed by centreOfGravity
                double delta = spread * width + rounding;
                if (area > 2 * delta) {
                    methodBound = width * delta / (area - delta) + rounding;
                } else {
                    methodBound = Double.POSITIVE_INFINITY;
                    undecided("CoG area within the bound");
                }
            }
        }
    }

    /** M of a point set's bounds over [lo, hi]: the largest of the interval's width and its ends' magnitudes. */
    static double setScale(double lo, double hi) {
        return Math.max(Math.max(Math.abs(lo), Math.abs(hi)), hi - lo);
    }

    /**
     * The rounding term of a point set's bounds with np vertices, 8(np + 2)·u·M (docs/semantics.md, point 10; the
     * static filter's CoG test uses it too).
     */
    static double setRounding(int np, double m) {
        return 8 * (np + 2) * U * m;
    }

    /** Set by {@link #clipsAtVertices}: see there. */
    private double steepestRun;
    private double vertexRepresentation;
    private boolean roundedLevels;

    /**
     * Marks undecided a MIN activation whose level the bounds cannot tell from a vertex degree of its term (a clip
     * crossing at a vertex), and maxima of two contributions the bounds cannot tell apart. Sets the largest run over
     * rise |Δx / Δy| of the fired terms' sloped pieces (how far a crossing moves per unit of degree), the largest
     * distance of their vertex degrees from their decimal readings, and whether a fired contribution has a weight
     * other than 1 or PROD activation (its degrees are rounded).
     */
    private void clipsAtVertices(OutputPlan o) {
        double steepest = 0;
        double representation = 0;
        double rounded = 0;
        int[] cs = o.contributions();
        for (int k = 0; k < cs.length; k++) {
            double d = contributionDegree[cs[k]];
            if (!(d * contributionWeight[cs[k]] > 0)) {
                continue;
            }
            int s = o.termShapes()[o.contributionTerm()[k]];
            double[] x = curX[s];
            double[] y = curY[s];
            double ed = contributionDegreeError[cs[k]];
            boolean clipped = o.contributionActivation()[k] == org.fclcert.model.ActivationMethod.MIN;
            if (!clipped || contributionWeight[cs[k]] != 1.0) {
                rounded = 1;
            }
            for (int i = 0; i < plan.shapes[s].n; i++) {
                double ry = repY[s][i];
                representation = Math.max(representation, ry);
                if (clipped && ed + ry > 0 && Math.abs(d - y[i]) <= ed + ry) {
                    undecided("clip at a vertex");
                }
                if (i > 0 && y[i] != y[i - 1]) {
                    steepest = Math.max(steepest, (x[i] - x[i - 1]) / Math.abs(y[i] - y[i - 1]));
                }
            }
        }
        for (int k = 0; k < cs.length; k++) {
            double pk = peak(o, k);
            for (int j = k + 1; j < cs.length && pk > 0; j++) {
                double pj = peak(o, j);
                double e = contributionError[cs[k]] + contributionError[cs[j]] + 4 * Norms.R;
                if (pj > 0 && Math.abs(pk - pj) <= e && !(pk == pj && rounded == 0 && representation == 0
                        && contributionError[cs[k]] == 0 && contributionError[cs[j]] == 0)) {
                    undecided("equal maxima of two contributions");
                }
            }
        }
        steepestRun = steepest;
        vertexRepresentation = representation;
        roundedLevels = rounded != 0;
    }

    /** The height of contribution k's activated set: w · min(d, h) (MIN) or w · d · h (PROD), h its term's height. */
    private double peak(OutputPlan o, int k) {
        int c = o.contributions()[k];
        int s = o.termShapes()[o.contributionTerm()[k]];
        double h = 0;
        for (int i = 0; i < plan.shapes[s].n; i++) {
            h = Math.max(h, curY[s][i]);
        }
        double d = contributionDegree[c];
        double w = contributionWeight[c];
        return o.contributionActivation()[k] == org.fclcert.model.ActivationMethod.MIN ? w * Math.min(d, h) : w * d * h;
    }

    /**
     * The contributions to o's set that fired (degree · weight &gt; 0), in place of those collected before; decides
     * for each whether it fired, and returns the bound of the accumulated degree (see {@link #decideSet}).
     */
    private double collect(OutputPlan o, Activations into, boolean merge) {
        into.clear();
        merge &= o.accumulation() == AccumulationMethod.MAX;
        collectedLargest = 0;
        collectedTotal = 0;
        int[] cs = o.contributions();
        if (liveCount >= 0 && cs.length > 0) {
            // the kernel's live contributions, ascending as o.contributions() is: the others are exact 0s
            int index = contributionOutput[cs[0]];
            for (int k = 0; k < liveCount; k++) {
                int c = live[k];
                if (contributionOutput[c] == index) {
                    collectOne(o, contributionPosition[c], into, merge);
                }
            }
        } else {
            for (int i = 0; i < cs.length; i++) {
                collectOne(o, i, into, merge);
            }
        }
        return switch (o.accumulation()) {
            case MAX -> collectedLargest;
            case NSUM -> 2 * collectedTotal;
            default -> collectedTotal;
        };
    }

    /** Set by {@link #collectOne}: the largest and the sum of the bounds of the contributions collected. */
    private double collectedLargest;
    private double collectedTotal;

    /** {@link #collect} for the contribution at position i of o's list. */
    private void collectOne(OutputPlan o, int i, Activations into, boolean merge) {
        int c = o.contributions()[i];
        double d = contributionDegree[c];
        double w = contributionWeight[c];
        double e = contributionError[c];
        double dw = d * w;
        if (!(dw > e) && !(dw == 0 && e == 0)) {
            undecided("whether a rule fired");
        }
        if (dw > 0 && merge) {
            into.addUnderMax(o.termShapes()[o.contributionTerm()[i]], d, w, o.contributionActivation()[i]);
        } else if (dw > 0) {
            into.add(o.termShapes()[o.contributionTerm()[i]], d, w, o.contributionActivation()[i]);
        }
        collectedLargest = Math.max(collectedLargest, e);
        collectedTotal += e;
    }

    /** Outputs whose set is not piece-wise linear: accumulation and defuzzification by SmoothSet. */
    private double smoothSet(OutputPlan o, SmoothSet smooth, Trace trace) {
        collect(o, smooth.act, false);
        double result = smooth.defuzzify(o.method(), o.accumulation(), o.rangeMin(), o.rangeMax(), plan.shapes,
                curX, curY);
        // the exact path integrates the same way on its own degrees: a .5 within a billionth is left to it
        methodBound = Double.isFinite(result) ? 1e-9 * Math.max(1, Math.abs(result)) : 0;
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
            default -> Defuzzifier.centreOfGravity(set.px, set.py, set.np, setArea);
        };
    }

    /** The area of the set CoG was last computed on ({@link #decideSet} reads it instead of summing again). */
    private final double[] setArea = new double[1];
}
