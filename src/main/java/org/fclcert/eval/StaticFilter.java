package org.fclcert.eval;

import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.eval.BlockPlan.RuleBlockPlan;
import org.fclcert.eval.BlockPlan.SubconclusionPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.OrAlgorithm;
import static org.objectweb.asm.Opcodes.*;

import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;

/**
 * The static filter of a block (the second half of Shewchuk's and CGAL's filtered predicates; docs/semantics.md,
 * "The static filter"): error bounds computed once per plan, valid for every finite input, so that a step computes
 * only the doubles and compares them with constants. Where every static test passes, the running bounds of
 * {@link FunctionBlockInstance} would settle every decision too (each running bound is at most its static one), so
 * the step's discrete outcome is the exact one and its doubles are the interpreter's; where a test fails the step is
 * evaluated again with the running bounds (and, if still undecided, exactly).
 *
 * <p>It covers the blocks whose every output the compiled kernel computes whole (singleton terms, MAX accumulation,
 * CoGS) or is CoG over a chain of point terms ({@link #chainOutput}), and whose rules are one term or one AND (MIN,
 * PROD) or OR (MAX) of terms, negated or not, with constant
 * weights, over input terms of constant points with degrees in [0, 1]. The doubles are computed by the interpreter's
 * operations in its order ({@link Pwl#degree}, the fold of {@code aggregateTerms}, w·d, {@code degreesPerTerm}'s MAX,
 * {@code centreOfGravityForSingletons}; for a chain output its own {@link SetBuilder#buildChain} and CoG), so they
 * are the interpreter's bit for bit.
 *
 * <p>Its size (about 1 000 lines, above the project's 700) is earned: the static bounds, the step interpreted and the
 * step generated sit side by side, so that every operation the generator leaves out or replaces can be read beside
 * the argument that it cannot change a bit, and the bounds beside the running formulas they dominate.
 *
 * <p>The static bounds, each no smaller than the running bound {@link FunctionBlockInstance} computes for the same
 * quantity at any finite input (every running bound is a sum and product of non-negative doubles, each operation
 * monotonic, so the same expression on the largest operands bounds it):
 * <ul>
 * <li>a term of points: the largest bound of its pieces, where a sloped piece between x₀ and x₁ takes the running
 * formula with the input's representation distance at its largest in [x₀, x₁], ulp(max(|x₀|, |x₁|))/2; a singleton
 * term 0;</li>
 * <li>MIN, MAX: the larger operand bound ({@code minError} and {@code maxError} never exceed it); PROD and w·d:
 * {@code productError} on the operands' largest magnitudes, plus the smallest normal double (its underflow case);
 * NOT: the operand's bound plus its rounding term;</li>
 * <li>a singleton term's accumulated degree under MAX: the largest bound of its contributions; CoGS: undecided by the
 * running bounds only when Σμ does not exceed Σe, so Σμ &gt; Σ (static bounds), summed in the same order, settles it
 * (and implies that some term fired).</li>
 * </ul>
 */
final class StaticFilter {
    private static final int SINGLE = 0;
    private static final int MIN = 1;
    private static final int PROD = 2;
    private static final int MAX = 3;
    /** Slack on a largest magnitude: an interpolated degree may round a few ulps above its points' degrees. */
    private static final double SLACK = 1 + 0x1.0p-40;

    /** Per input term: its variable's slot, points (null for a singleton) and static bound. */
    private final int[] termSlot;
    private final double[][] termX;
    private final double[][] termY;
    private final double[] singletonAt;
    final double[] termBound;
    /** Per rule (all rule blocks): its operator and its terms ({@code ruleFrom}), negated or not. */
    private final int[] ruleOp;
    private final int[] ruleFrom;
    private final int[] ruleTerm;
    private final boolean[] ruleNot;
    final double[] ruleBound;
    /** Per output: its slot, its contributions ({@code outFrom}): rule, constant weight, term; its terms' values. */
    final int[] outputSlot;
    private final int[] outFrom;
    private final int[] contributionRule;
    private final double[] contributionWeight;
    private final int[] contributionTerm;
    private final double[][] singletonValue;
    /** Per output, per term: the static bound of its accumulated degree; per output: Σ of them (the CoGS test). */
    final double[][] singletonBound;
    /** Per contribution (the plan's index): the static bound of w·d and of d (for the tests). */
    final double[] contributionBound;
    final double[] contributionDegreeBound;
    /** Per contribution: its output and singleton term (for the tests). */
    final int[] contributionOutput;
    final int[] contributionSingleton;
    final double[] threshold;
    /** The step as generated code ({@link #compile}), or null when the block is too large for one method or has chains. */
    final Step compiled;
    /**
     * Per output: its chain of terms when it is a point-set output the kernel leaves to the interpreter (CoG under MAX
     * over a {@link TermChain}, see {@link #chainOutput}), else null; its interval, and the two parts of CoG's area
     * test (docs/semantics.md, point 10): the largest static bound of its contributions, and M (decideSet's).
     */
    private final TermChain[] chainOf;
    private final double[] chainLo;
    private final double[] chainHi;
    private final double[] chainSpread;
    private final double[] chainM;
    /** Per contribution (in output order): its term's shape and activation, for the chain outputs. */
    private final int[] contributionShape;
    private final org.fclcert.model.ActivationMethod[] contributionActivation;
    /**
     * Per chain output: its contributions are stored in the chain's order, one per term
     * ({@link #contributionPlaces}), so that {@link #chainOutput} adds them without merging and
     * {@link SetBuilder#buildChain} takes them in that order.
     */
    private final boolean[] chainInOrder;
    /** Per contribution (in output order): its index in the plan (of contributionBound). */
    private final int[] contributionIndex;
    /** Per shape of the plan: its points (constant for every shape of a chain output). */
    private final double[][] shapeX;
    private final double[][] shapeY;
    /** Per input term: a degree 0 is exact (bound 0) at an input outside (slopedFrom, slopedTo), its sloped pieces. */
    private final double[] slopedFrom;
    private final double[] slopedTo;
    /** For a block with chain outputs: the term and rule degrees as generated code ({@link #compileFront}), or null. */
    final Front front;

    /** The term and rule degrees of {@link #step} written out for one plan, into arrays (for blocks with chains). */
    interface Front extends SetBuilder.Staging {
        void front(double[] values, double[] td, double[] rd);

        /**
         * Chain output i's contributions that fired, into {@code act} (cleared), with {@link #chainOutput}'s tests
         * on them written out; false as soon as one test fails.
         */
        boolean collect(int i, double[] values, double[] td, double[] rd, Activations act);
    }

    /** {@link #step} written out for one plan: the same operations on the same operands, its numbers as constants. */
    interface Step {
        /** As {@link StaticFilter#step}, without the scratch arrays. */
        boolean step(double[] values, double[] saved);
    }

    /** The VAR_INPUT slots in declaration order; per output its type's range. */
    private final int[] inputSlot;
    private final double[] outputMin;
    private final double[] outputMax;
    /** Scratch sizes. */
    final int terms;
    final int rules;
    final int maxOutputTerms;

    private StaticFilter(BlockPlan plan, int[][] rulesTerms, int[] ops, boolean[][] nots, int[] contributionRules,
            double[] weights, TermChain[] chains) {
        int nt = plan.termShape.length;
        slopedFrom = new double[nt];
        slopedTo = new double[nt];
        this.terms = nt;
        termSlot = plan.termVariableSlot.clone();
        termX = new double[nt][];
        termY = new double[nt][];
        singletonAt = new double[nt];
        termBound = new double[nt];
        double[] termMax = new double[nt];
        for (int t = 0; t < nt; t++) {
            Shape s = plan.shapes[plan.termShape[t]];
            slopedFrom[t] = Double.POSITIVE_INFINITY;
            slopedTo[t] = Double.NEGATIVE_INFINITY;
            if (s.singleton) {
                singletonAt[t] = s.sortedX[0];
                termMax[t] = 1;
                continue;
            }
            termX[t] = s.sortedX;
            termY[t] = s.sortedY;
            termBound[t] = termBound(s.sortedX, s.sortedY);
            for (int i = 1; i < s.n; i++) {
                if (s.sortedX[i] > s.sortedX[i - 1] && s.sortedY[i] != s.sortedY[i - 1]) {
                    slopedFrom[t] = Math.min(slopedFrom[t], s.sortedX[i - 1]);
                    slopedTo[t] = s.sortedX[i];
                }
            }
            double m = 0;
            for (double y : s.sortedY) {
                m = Math.max(m, y);
            }
            termMax[t] = m * SLACK;
        }
        int nr = ops.length;
        this.rules = nr;
        ruleOp = ops;
        ruleFrom = new int[nr + 1];
        int total = 0;
        for (int r = 0; r < nr; r++) {
            ruleFrom[r] = total;
            total += rulesTerms[r].length;
        }
        ruleFrom[nr] = total;
        ruleTerm = new int[total];
        ruleNot = new boolean[total];
        ruleBound = new double[nr];
        double[] ruleMax = new double[nr];
        for (int r = 0; r < nr; r++) {
            double m = 0;
            double e = 0;
            for (int j = 0; j < rulesTerms[r].length; j++) {
                int t = rulesTerms[r][j];
                ruleTerm[ruleFrom[r] + j] = t;
                ruleNot[ruleFrom[r] + j] = nots[r][j];
                double mj = nots[r][j] ? SLACK : termMax[t];      // 1 - d of a degree in [0, 1 + tiny]
                double ej = nots[r][j] ? termBound[t] + Norms.R : termBound[t];
                if (j == 0) {
                    m = mj;
                    e = ej;
                } else if (ops[r] == PROD) {
                    e = Norms.productError(m, e, mj, ej, m * mj) + Double.MIN_NORMAL;
                    m = m * mj * SLACK;
                } else {
                    e = Math.max(e, ej);
                    m = Math.max(m, mj);
                }
            }
            ruleBound[r] = e;
            ruleMax[r] = m;
        }
        int no = plan.outputs.length;
        outputSlot = new int[no];
        inputSlot = plan.inputNames.stream().mapToInt(plan.slotByName::get).toArray();
        outputMin = new double[no];
        outputMax = new double[no];
        outFrom = new int[no + 1];
        int nc = 0;
        int maxTerms = 0;
        for (int i = 0; i < no; i++) {
            outFrom[i] = nc;
            nc += plan.outputs[i].contributions().length;
            maxTerms = Math.max(maxTerms, plan.outputs[i].termShapes().length);
        }
        outFrom[no] = nc;
        maxOutputTerms = maxTerms;
        contributionRule = new int[nc];
        contributionWeight = new double[nc];
        contributionTerm = new int[nc];
        singletonValue = new double[no][];
        singletonBound = new double[no][];
        threshold = new double[no];
        contributionBound = new double[plan.contributionCount];
        contributionDegreeBound = new double[plan.contributionCount];
        contributionOutput = new int[plan.contributionCount];
        contributionSingleton = new int[plan.contributionCount];
        contributionShape = new int[nc];
        contributionIndex = new int[nc];
        shapeX = new double[plan.shapes.length][];
        shapeY = new double[plan.shapes.length][];
        for (int s = 0; s < plan.shapes.length; s++) {
            shapeX[s] = plan.shapes[s].sortedX;
            shapeY[s] = plan.shapes[s].sortedY;
        }
        contributionActivation = new org.fclcert.model.ActivationMethod[nc];
        chainOf = chains;
        chainInOrder = new boolean[no];
        chainLo = new double[no];
        chainHi = new double[no];
        chainSpread = new double[no];
        chainM = new double[no];
        boolean anyChain = false;
        for (int i = 0; i < no; i++) {
            OutputPlan o = plan.outputs[i];
            outputSlot[i] = o.slot();
            outputMin[i] = plan.types[o.slot()].min();
            outputMax[i] = plan.types[o.slot()].max();
            int n = o.termShapes().length;
            singletonValue[i] = new double[n];
            singletonBound[i] = new double[n];
            for (int t = 0; t < n; t++) {
                singletonValue[i][t] = plan.shapes[o.termShapes()[t]].sortedX[0];
            }
            int[] cs = o.contributions();
            int[] place = contributionPlaces(o, chains[i]);
            chainInOrder[i] = place != null;      // null for an output without a chain too
            for (int k = 0; k < cs.length; k++) {
                int c = cs[k];
                int at = outFrom[i] + (place != null ? place[k] : k);
                int r = contributionRules[c];
                double w = weights[c];
                contributionRule[at] = r;
                contributionWeight[at] = w;
                contributionTerm[at] = o.contributionTerm()[k];
                double aw = Math.abs(w);
                double e = Norms.productError(aw, FunctionBlockInstance.representation(w), ruleMax[r], ruleBound[r],
                        aw * ruleMax[r]) + Double.MIN_NORMAL;
                int t = o.contributionTerm()[k];
                singletonBound[i][t] = Math.max(singletonBound[i][t], e);
                contributionBound[c] = e;
                contributionDegreeBound[c] = ruleBound[r];
                contributionOutput[c] = i;
                contributionSingleton[c] = t;
                contributionShape[at] = o.termShapes()[t];
                contributionIndex[at] = c;
                contributionActivation[at] = o.contributionActivation()[k];
                chainSpread[i] = Math.max(chainSpread[i], e);
            }
            if (chains[i] != null) {
                anyChain = true;
                double lo = o.rangeMin();
                double hi = o.rangeMax();
                if (!o.hasRange()) {        // as FunctionBlockInstance.pointSet: the hull of the terms' points
                    lo = Double.POSITIVE_INFINITY;
                    hi = Double.NEGATIVE_INFINITY;
                    for (int s : o.termShapes()) {
                        lo = Math.min(lo, plan.shapes[s].sortedX[0]);
                        hi = Math.max(hi, plan.shapes[s].sortedX[plan.shapes[s].n - 1]);
                    }
                }
                chainLo[i] = lo;
                chainHi[i] = hi;
                chainM[i] = FunctionBlockInstance.setScale(lo, hi);
            }
            double sum = 0;
            for (int t = 0; t < n; t++) {
                sum += singletonBound[i][t];
            }
            threshold[i] = sum;
        }
        compiled = anyChain ? null : compile();
        front = anyChain ? compileFront() : null;
    }

    /**
     * For a chain output whose terms are concluded by one contribution each: each contribution's place among the
     * output's, in the chain's order of their terms; else null (the contributions keep the rules' order). The order
     * changes no double: MAX merges nothing here, and the chain construction sorts by that order anyway.
     */
    private static int[] contributionPlaces(OutputPlan o, TermChain chain) {
        if (chain == null) {
            return null;
        }
        int[] cs = o.contributions();
        int[] rank = new int[cs.length];
        boolean[] taken = new boolean[o.termShapes().length];
        for (int k = 0; k < cs.length; k++) {
            int t = o.contributionTerm()[k];
            if (taken[t]) {
                return null;
            }
            taken[t] = true;
            rank[k] = chain.rank(o.termShapes()[t]);
        }
        int[] place = new int[cs.length];
        for (int k = 0; k < cs.length; k++) {
            for (int q = 0; q < cs.length; q++) {
                place[k] += rank[q] < rank[k] ? 1 : 0;
            }
        }
        return place;
    }

    // ------------------------------------------------------------------------------------------ generated step

    /** A budget of bytecode for the one generated method, below HotSpot's 8 000-byte limit for compiling one. */
    private static final int BUDGET = 6000;

    /**
     * {@link #step} as one generated method, its loops unrolled and every point, degree, weight, value and threshold
     * a constant: per term Pwl.degree's branches (below, above, the first point at or above u: at it the largest
     * degree of the points there, before it the interpolation ((x₁ − u)·y₀ + (u − x₀)·y₁)/(x₁ − x₀), a flat piece
     * its degree), per rule the fold by Math.min, Math.max or a product, per output the MAX per term and CoGS's sums
     * in {@link #step}'s order. Null when the estimate exceeds {@link #BUDGET} or the class file cannot hold the step.
     */
    private Step compile() {
        int cost = 0;
        for (int t = 0; t < terms; t++) {
            cost += 20 + (termX[t] == null ? 10 : 60 * termX[t].length);
        }
        cost += 20 * ruleTerm.length + 30 * contributionRule.length + 40 * maxOutputTerms * outputSlot.length;
        if (cost > BUDGET) {
            return null;
        }
        String self = "org/fclcert/eval/StaticStep";
        ClassWriter cw = KernelCompiler.newClass(self, "org/fclcert/eval/StaticFilter$Step");
        termMethods(cw, self);
        MethodVisitor mv = cw.visitMethod(ACC_PUBLIC, "step", "([D[D)Z", null, null);
        mv.visitCode();
        // locals: this, values, out; u; then the term degrees, rule degrees, singleton degrees, num, den
        int td = 5;
        int rd = td + 2 * terms;
        int sd = rd + 2 * rules;
        int num = sd + 2 * maxOutputTerms;
        int den = num + 2;
        int result = den + 2;
        degrees(mv, self, td, rd);
        Label undecided = new Label();
        // a rule degree is not below +0 when its fold has no NOT (1 - d of a degree rounded above 1 is below 0)
        boolean[] nonNegative = new boolean[rules];
        for (int r = 0; r < rules; r++) {
            nonNegative[r] = plainSoFar(r, ruleFrom[r + 1]);
        }
        for (int i = 0; i < outputSlot.length; i++) {
            int n = singletonValue[i].length;
            boolean[] written = new boolean[n];
            for (int k = outFrom[i]; k < outFrom[i + 1]; k++) {
                int t = contributionTerm[k];
                double w = contributionWeight[k];
                int r = contributionRule[k];
                // Math.max(+0 or the term's degree so far, w·d); w·d for w = 1 is d itself. The first contribution
                // of a term is Math.max(+0, w·d) = w·d when w·d is not below +0 (w >= +0, d >= +0)
                boolean first = !written[t] && nonNegative[r] && atLeastPlusZero(w);
                if (!first) {
                    if (written[t]) {
                        mv.visitVarInsn(DLOAD, sd + 2 * t);
                    } else {
                        mv.visitInsn(DCONST_0);
                    }
                }
                if (w == 1) {
                    mv.visitVarInsn(DLOAD, rd + 2 * r);
                } else {
                    mv.visitLdcInsn(w);
                    mv.visitVarInsn(DLOAD, rd + 2 * r);
                    mv.visitInsn(DMUL);
                }
                if (!first) {
                    // plain only where both are not below +0 (no -0.0: w·d of a non-negative w, d is +0 or above)
                    select(mv, false, !(nonNegative[r] && atLeastPlusZero(w)
                            && !anyNegativeBefore(i, k, t, nonNegative)));
                }
                mv.visitVarInsn(DSTORE, sd + 2 * t);
                written[t] = true;
            }
            for (int t = 0; t < n; t++) {
                if (!written[t]) {
                    mv.visitInsn(DCONST_0);
                    mv.visitVarInsn(DSTORE, sd + 2 * t);
                }
            }
            // num = 0.0 + v0·sd0 + ...; den = 0.0 + sd0 + ... (sd >= +0 here whenever every rule has no NOT: see
            // below). Only the additions that can change a bit are kept: the start 0.0 + x is x for x not -0.0, and
            // a term v·sd with v = +0 adds +0 to a sum that is never -0.0
            boolean allNonNegative = true;
            for (boolean b : nonNegative) {
                allNonNegative &= b;
            }
            for (int k = outFrom[i]; k < outFrom[i + 1]; k++) {
                allNonNegative &= contributionWeight[k] >= 0;
            }
            boolean numStarted = false;
            boolean denStarted = false;
            for (int t = 0; t < n; t++) {
                double v = singletonValue[i][t];
                boolean positiveV = atLeastPlusZero(v);
                if (!allNonNegative || !(v == 0 && positiveV && numStarted)) {
                    boolean lead = allNonNegative && positiveV && !numStarted;
                    if (!lead) {
                        if (numStarted) {
                            mv.visitVarInsn(DLOAD, num);
                        } else {
                            mv.visitInsn(DCONST_0);
                        }
                    }
                    mv.visitLdcInsn(v);
                    mv.visitVarInsn(DLOAD, sd + 2 * t);
                    mv.visitInsn(DMUL);
                    if (!lead) {
                        mv.visitInsn(DADD);
                    }
                    mv.visitVarInsn(DSTORE, num);
                    numStarted = true;
                }
                boolean leadDen = allNonNegative && !denStarted;
                if (!leadDen) {
                    if (denStarted) {
                        mv.visitVarInsn(DLOAD, den);
                    } else {
                        mv.visitInsn(DCONST_0);
                    }
                }
                mv.visitVarInsn(DLOAD, sd + 2 * t);
                if (!leadDen) {
                    mv.visitInsn(DADD);
                }
                mv.visitVarInsn(DSTORE, den);
                denStarted = true;
            }
            if (!numStarted) {
                mv.visitInsn(DCONST_0);
                mv.visitVarInsn(DSTORE, num);
            }
            // !(den > threshold): undecided (NaN compares as not greater)
            mv.visitVarInsn(DLOAD, den);
            mv.visitLdcInsn(threshold[i]);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFLE, undecided);
            mv.visitVarInsn(DLOAD, num);
            mv.visitVarInsn(DLOAD, den);
            mv.visitInsn(DDIV);
            mv.visitVarInsn(DSTORE, result + 2 * i);
            // !(c >= min && c <= max): the running path reports it. Left out where every μ is at least +0 and the
            // type's range holds twice the largest |v|: then |Σ v·μ / Σ μ| is at most max |v| times a few roundings
            double largest = 0;
            for (double v : singletonValue[i]) {
                largest = Math.max(largest, Math.abs(v));
            }
            if (allNonNegative && 2 * largest <= outputMax[i] && -2 * largest >= outputMin[i]) {
                continue;
            }
            mv.visitVarInsn(DLOAD, result + 2 * i);
            mv.visitLdcInsn(outputMin[i]);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFLT, undecided);
            mv.visitVarInsn(DLOAD, result + 2 * i);
            mv.visitLdcInsn(outputMax[i]);
            mv.visitInsn(DCMPG);
            mv.visitJumpInsn(IFGT, undecided);
        }
        for (int i = 0; i < outputSlot.length; i++) {
            mv.visitVarInsn(ALOAD, 1);
            KernelCompiler.push(mv, outputSlot[i]);
            mv.visitVarInsn(DLOAD, result + 2 * i);
            mv.visitInsn(DASTORE);
        }
        for (int k = 0; k < inputSlot.length; k++) {
            mv.visitVarInsn(ALOAD, 2);
            KernelCompiler.push(mv, k);
            mv.visitVarInsn(ALOAD, 1);
            KernelCompiler.push(mv, inputSlot[k]);
            mv.visitInsn(DALOAD);
            mv.visitInsn(DASTORE);
        }
        mv.visitInsn(ICONST_1);
        mv.visitInsn(IRETURN);
        mv.visitLabel(undecided);
        mv.visitInsn(ICONST_0);
        mv.visitInsn(IRETURN);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
        return (Step) KernelCompiler.instance(cw, "the static filter's step");
    }

    /**
     * Each term's degree in a small method of its own, so that the step stays under HotSpot's size for inlining a hot
     * method (FreqInlineSize, 325 bytes) and the JIT inlines it, and the terms into it.
     */
    private void termMethods(ClassWriter cw, String self) {
        for (int t = 0; t < terms; t++) {
            MethodVisitor tm = cw.visitMethod(ACC_PRIVATE | ACC_STATIC, "term" + t, "(D)D", null, null);
            tm.visitCode();
            term(tm, t, 0, 2);
            tm.visitVarInsn(DLOAD, 2);
            tm.visitInsn(DRETURN);
            tm.visitMaxs(0, 0);
            tm.visitEnd();
        }
    }

    /** The term degrees (of the values array in local 1) into locals td + 2t, the rule degrees into rd + 2r. */
    private void degrees(MethodVisitor mv, String self, int td, int rd) {
        for (int t = 0; t < terms; t++) {
            mv.visitVarInsn(ALOAD, 1);
            KernelCompiler.push(mv, termSlot[t]);
            mv.visitInsn(DALOAD);
            mv.visitMethodInsn(INVOKESTATIC, self, "term" + t, "(D)D", false);
            mv.visitVarInsn(DSTORE, td + 2 * t);
        }
        for (int r = 0; r < rules; r++) {
            for (int j = ruleFrom[r]; j < ruleFrom[r + 1]; j++) {
                if (ruleNot[j]) {
                    mv.visitInsn(DCONST_1);
                    mv.visitVarInsn(DLOAD, td + 2 * ruleTerm[j]);
                    mv.visitInsn(DSUB);
                } else {
                    mv.visitVarInsn(DLOAD, td + 2 * ruleTerm[j]);
                }
                if (j > ruleFrom[r]) {
                    if (ruleOp[r] == PROD) {
                        mv.visitInsn(DMUL);
                    } else {
                        // Math.min/max are the plain comparison's choice for operands neither NaN nor -0.0: the
                        // terms' degrees are not (points' degrees in [0, 1], not -0.0; an interpolation is a sum of
                        // products at least +0 over a positive width), nor MIN, MAX or PROD of them; 1 - d is not
                        // -0.0 either, but may be below 0, and a PROD of it with +0 is -0.0: Math's after a NOT
                        select(mv, ruleOp[r] == MIN, !plainSoFar(r, j + 1));
                    }
                }
            }
            mv.visitVarInsn(DSTORE, rd + 2 * r);
        }
    }

    /**
     * {@link #step}'s term and rule degrees as one generated method, for a block with chain outputs: the same code as
     * {@link #compile}'s, the degrees stored into arrays for {@link #step}'s outputs. Null when the class file cannot
     * hold it or the estimate exceeds {@link #BUDGET}.
     */
    private Front compileFront() {
        int cost = 0;
        for (int t = 0; t < terms; t++) {
            cost += 30 + (termX[t] == null ? 10 : 60 * termX[t].length);
        }
        cost += 30 * ruleTerm.length + 10 * rules;
        if (cost > BUDGET) {
            return null;
        }
        String self = "org/fclcert/eval/StaticFront";
        ClassWriter cw = KernelCompiler.newClass(self, "org/fclcert/eval/StaticFilter$Front");
        termMethods(cw, self);
        MethodVisitor mv = cw.visitMethod(ACC_PUBLIC, "front", "([D[D[D)V", null, null);
        mv.visitCode();
        // locals: this, values, td, rd; then the term degrees and rule degrees
        int td = 4;
        int rd = td + 2 * terms;
        degrees(mv, self, td, rd);
        for (int t = 0; t < terms; t++) {
            mv.visitVarInsn(ALOAD, 2);
            KernelCompiler.push(mv, t);
            mv.visitVarInsn(DLOAD, td + 2 * t);
            mv.visitInsn(DASTORE);
        }
        for (int r = 0; r < rules; r++) {
            mv.visitVarInsn(ALOAD, 3);
            KernelCompiler.push(mv, r);
            mv.visitVarInsn(DLOAD, rd + 2 * r);
            mv.visitInsn(DASTORE);
        }
        mv.visitInsn(RETURN);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
        collect(cw);
        staged = stage(cw);
        return (Front) KernelCompiler.instance(cw, "the static filter's front");
    }

    /**
     * Whether the front's {@link SetBuilder.Staging#stage} is written out for every term of the chain outputs (else it
     * returns −1 and {@link SetBuilder#buildChain} is given no staging: its own {@code contributionVertices}).
     */
    private boolean staged;

    /** Whether the chain outputs' contributions are staged by generated code ({@link #stage}; for the tests). */
    boolean staged() {
        return staged;
    }

    /**
     * {@link SetBuilder.Staging#stage}: per shape of a chain output (a switch on it), {@code contributionVertices}'
     * vertices in its order with the term's points, the support's ends ({@link SetBuilder#supportStart},
     * {@link SetBuilder#supportEnd}), their degrees ({@link SetBuilder#degreeAt}) and the range's ends as constants:
     * which points lie inside the part is decided here, once; the clip crossings ({@link SetBuilder#crossing}), the
     * plateau test and the activations ({@link Activations#activate}) at run time, by the same methods. A term over
     * {@link #BUDGET} in all is left to {@code contributionVertices} (false).
     */
    private boolean stage(ClassWriter cw) {
        int cost = 0;
        // shape -> its output (BlockCompiler gives every term a shape of its own: one output each)
        java.util.TreeMap<Integer, Integer> shapes = new java.util.TreeMap<>();
        for (int i = 0; i < outputSlot.length; i++) {
            for (int k = outFrom[i]; chainOf[i] != null && k < outFrom[i + 1]; k++) {
                if (shapes.put(contributionShape[k], i) == null) {
                    cost += 60 + 90 * shapeX[contributionShape[k]].length;
                }
            }
        }
        boolean all = cost <= BUDGET;
        MethodVisitor mv = cw.visitMethod(ACC_PUBLIC, "stage", "(IDDZ[D[DI)I", null, null);
        mv.visitCode();
        // locals: this, s, level (2), w (4), prod, vx, vy, q; then c (10)
        Label unknown = new Label();
        int[] keys = shapes.keySet().stream().mapToInt(Integer::intValue).toArray();
        Label[] cases = new Label[keys.length];
        for (int k = 0; k < keys.length; k++) {
            cases[k] = all ? new Label() : unknown;
        }
        mv.visitVarInsn(ILOAD, 1);
        mv.visitLookupSwitchInsn(unknown, keys, cases);
        for (int k = 0; all && k < keys.length; k++) {
            mv.visitLabel(cases[k]);
            int i = shapes.get(keys[k]);
            stageTerm(mv, keys[k], chainOf[i], chainLo[i], chainHi[i]);
            mv.visitVarInsn(ILOAD, 9);
            mv.visitInsn(IRETURN);
        }
        mv.visitLabel(unknown);
        mv.visitInsn(ICONST_M1);
        mv.visitInsn(IRETURN);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
        return all;
    }

    /** {@link #stage} for shape s of {@code chain} over [lo, hi]: contributionVertices' steps, q in local 9. */
    private void stageTerm(MethodVisitor mv, int s, TermChain chain, double lo, double hi) {
        double[] x = shapeX[s];
        double[] y = shapeY[s];
        int f = chain.first(s);
        int l = chain.last(s);
        double a = SetBuilder.supportStart(x, y, f, lo);
        double b = SetBuilder.supportEnd(x, y, l, hi);
        if (!(a < b)) {
            return;
        }
        stageVertex(mv, a, SetBuilder.degreeAt(x, y, f, a), false);
        if (x[f] > a && x[f] < b) {
            stagePoint(mv, x[f], y[f]);
        }
        for (int i = f + 1; i <= l; i++) {
            // if (!prod) { c = crossing(x0, y0, x1, y1, level); if (c > a && c < b) stage c at the level }
            Label skip = new Label();
            mv.visitVarInsn(ILOAD, 6);
            mv.visitJumpInsn(IFNE, skip);
            mv.visitLdcInsn(x[i - 1]);
            mv.visitLdcInsn(y[i - 1]);
            mv.visitLdcInsn(x[i]);
            mv.visitLdcInsn(y[i]);
            mv.visitVarInsn(DLOAD, 2);
            mv.visitMethodInsn(INVOKESTATIC, "org/fclcert/eval/SetBuilder", "crossing", "(DDDDD)D", false);
            mv.visitVarInsn(DSTORE, 10);
            mv.visitVarInsn(DLOAD, 10);
            mv.visitLdcInsn(a);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFLE, skip);
            mv.visitVarInsn(DLOAD, 10);
            mv.visitLdcInsn(b);
            mv.visitInsn(DCMPG);
            mv.visitJumpInsn(IFGE, skip);
            stageVertex(mv, Double.NaN, Double.NaN, true);
            mv.visitLabel(skip);
            if (x[i] > a && x[i] < b) {
                stagePoint(mv, x[i], y[i]);
            }
        }
        stageVertex(mv, b, SetBuilder.degreeAt(x, y, l, b), false);
    }

    /** A point (u, μ) of the term inside the part: staged when PROD or μ is not above the MIN level. */
    private static void stagePoint(MethodVisitor mv, double u, double mu) {
        Label skip = new Label();
        Label in = new Label();
        mv.visitVarInsn(ILOAD, 6);
        mv.visitJumpInsn(IFNE, in);
        mv.visitLdcInsn(mu);
        mv.visitVarInsn(DLOAD, 2);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFGT, skip);
        mv.visitLabel(in);
        stageVertex(mv, u, mu, false);
        mv.visitLabel(skip);
    }

    /**
     * vx[q] = u; vy[q] = Activations.activate(w, level, prod, μ); q++ — or, for a crossing, u from local 10 and
     * activate(w, level, false, level).
     */
    private static void stageVertex(MethodVisitor mv, double u, double mu, boolean crossing) {
        mv.visitVarInsn(ALOAD, 7);
        mv.visitVarInsn(ILOAD, 9);
        if (crossing) {
            mv.visitVarInsn(DLOAD, 10);
        } else {
            mv.visitLdcInsn(u);
        }
        mv.visitInsn(DASTORE);
        mv.visitVarInsn(ALOAD, 8);
        mv.visitVarInsn(ILOAD, 9);
        mv.visitVarInsn(DLOAD, 4);
        mv.visitVarInsn(DLOAD, 2);
        if (crossing) {
            mv.visitInsn(ICONST_0);
            mv.visitVarInsn(DLOAD, 2);
        } else {
            mv.visitVarInsn(ILOAD, 6);
            mv.visitLdcInsn(mu);
        }
        mv.visitMethodInsn(INVOKESTATIC, "org/fclcert/eval/Activations", "activate", "(DDZD)D", false);
        mv.visitInsn(DASTORE);
        mv.visitIincInsn(9, 1);
    }

    /**
     * {@link Front#collect}: per chain output its contributions in their stored order, each with its rule, weight,
     * shape, activation and static bound as constants. A contribution fired when w·d &gt; 0: it then needs w·d above its
     * static bound (else false: the running path decides it) and is added to the activations (merged under MAX unless
     * the output's terms have one contribution each, {@link #chainInOrder}). One that did not fire needs w·d = 0 with a
     * weight 0 or an exact 0 rule degree (else false): a degree 0 has running bound 0 when MIN or PROD has one operand
     * that is an exact 0 (Norms.minError, productError), a single term is its own, MAX needs all of its operands to be
     * exact 0s. A term's degree 0 is exact when it was read at or outside its points or on a flat piece (the bound of a
     * degree 0 point, 0; FunctionBlockInstance.degree), which an input outside the hull of its sloped pieces
     * (slopedFrom, slopedTo) guarantees, and a singleton's always is; a NOT is not counted (conservatively: the running
     * path decides those).
     */
    private void collect(ClassWriter cw) {
        MethodVisitor mv = cw.visitMethod(ACC_PUBLIC, "collect", "(I[D[D[DLorg/fclcert/eval/Activations;)Z", null,
                null);
        mv.visitCode();
        // locals: this, i, values, td, rd, act; then d, dw
        int d = 6;
        int dw = 8;
        Label undecided = new Label();
        Label[] outputs = new Label[outputSlot.length];
        for (int i = 0; i < outputs.length; i++) {
            outputs[i] = chainOf[i] != null ? new Label() : undecided;
        }
        mv.visitVarInsn(ILOAD, 1);
        mv.visitTableSwitchInsn(0, outputs.length - 1, undecided, outputs);
        for (int i = 0; i < outputs.length; i++) {
            if (chainOf[i] == null) {
                continue;
            }
            mv.visitLabel(outputs[i]);
            for (int k = outFrom[i]; k < outFrom[i + 1]; k++) {
                int r = contributionRule[k];
                double w = contributionWeight[k];
                Label notFired = new Label();
                Label next = new Label();
                mv.visitVarInsn(ALOAD, 4);
                KernelCompiler.push(mv, r);
                mv.visitInsn(DALOAD);
                mv.visitVarInsn(DSTORE, d);
                mv.visitVarInsn(DLOAD, d);
                mv.visitLdcInsn(w);
                mv.visitInsn(DMUL);
                mv.visitVarInsn(DSTORE, dw);
                // w·d > 0, else notFired (NaN too)
                mv.visitVarInsn(DLOAD, dw);
                mv.visitInsn(DCONST_0);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFLE, notFired);
                // !(w·d > bound): undecided
                mv.visitVarInsn(DLOAD, dw);
                mv.visitLdcInsn(contributionBound[contributionIndex[k]]);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFLE, undecided);
                mv.visitVarInsn(ALOAD, 5);
                KernelCompiler.push(mv, contributionShape[k]);
                mv.visitVarInsn(DLOAD, d);
                mv.visitLdcInsn(w);
                if (chainInOrder[i]) {
                    mv.visitInsn(contributionActivation[k] == org.fclcert.model.ActivationMethod.PROD ? ICONST_1
                            : ICONST_0);
                    mv.visitMethodInsn(INVOKEVIRTUAL, "org/fclcert/eval/Activations", "add", "(IDDZ)V", false);
                } else {
                    mv.visitFieldInsn(GETSTATIC, "org/fclcert/model/ActivationMethod",
                            contributionActivation[k].name(), "Lorg/fclcert/model/ActivationMethod;");
                    mv.visitMethodInsn(INVOKEVIRTUAL, "org/fclcert/eval/Activations", "addUnderMax",
                            "(IDDLorg/fclcert/model/ActivationMethod;)V", false);
                }
                mv.visitJumpInsn(GOTO, next);
                mv.visitLabel(notFired);
                // !(w·d == 0): undecided (NaN too)
                mv.visitVarInsn(DLOAD, dw);
                mv.visitInsn(DCONST_0);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFNE, undecided);
                if (w != 0) {
                    exactZero(mv, r, next, undecided);
                }
                mv.visitLabel(next);
            }
            mv.visitInsn(ICONST_1);
            mv.visitInsn(IRETURN);
        }
        mv.visitLabel(undecided);
        mv.visitInsn(ICONST_0);
        mv.visitInsn(IRETURN);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
    }

    /** Jumps to {@code exact} when rule r's degree (0 here) is an exact 0 ({@link #collect}), else to {@code not}. */
    private void exactZero(MethodVisitor mv, int r, Label exact, Label not) {
        boolean all = ruleOp[r] == MAX;
        for (int j = ruleFrom[r]; j < ruleFrom[r + 1]; j++) {
            if (ruleNot[j]) {
                if (all) {
                    mv.visitJumpInsn(GOTO, not);
                    return;
                }
                continue;
            }
            int t = ruleTerm[j];
            // the term's degree 0 is exact: td[t] == 0 and !(u > slopedFrom && u < slopedTo)
            Label inexact = all ? not : new Label();
            mv.visitVarInsn(ALOAD, 3);
            KernelCompiler.push(mv, t);
            mv.visitInsn(DALOAD);
            mv.visitInsn(DCONST_0);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFNE, inexact);
            Label outside = all ? new Label() : exact;
            mv.visitVarInsn(ALOAD, 2);
            KernelCompiler.push(mv, termSlot[t]);
            mv.visitInsn(DALOAD);
            mv.visitInsn(DUP2);
            mv.visitLdcInsn(slopedFrom[t]);
            mv.visitInsn(DCMPL);
            Label above = new Label();
            mv.visitJumpInsn(IFGT, above);
            mv.visitInsn(POP2);
            mv.visitJumpInsn(GOTO, outside);
            mv.visitLabel(above);
            mv.visitLdcInsn(slopedTo[t]);
            mv.visitInsn(DCMPG);
            mv.visitJumpInsn(IFGE, outside);
            mv.visitJumpInsn(GOTO, inexact);
            if (all) {
                mv.visitLabel(outside);
            } else {
                mv.visitLabel(inexact);
            }
        }
        mv.visitJumpInsn(GOTO, all ? exact : not);
    }

    /** Pwl.degree (or a singleton's 1/0) of term t at local {@code u}, into local {@code into}. */
    private void term(MethodVisitor mv, int t, int u, int into) {
        Label store = new Label();
        double[] x = termX[t];
        if (x == null) {
            Label miss = new Label();
            mv.visitVarInsn(DLOAD, u);
            mv.visitLdcInsn(singletonAt[t]);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFNE, miss);
            constant(mv, 1.0, into, store);
            mv.visitLabel(miss);
            constant(mv, 0.0, into, store);
            mv.visitLabel(store);
            return;
        }
        double[] y = termY[t];
        KernelCompiler.searchPoints(mv, u, x, new KernelCompiler.PointPlaces() {
            @Override
            public void outside(int i) {
                constant(mv, y[i], into, store);
            }

            @Override
            public void atPoint(int i, int end) {
                double max = y[i];
                for (int j = i + 1; j < end; j++) {
                    max = Math.max(max, y[j]);
                }
                constant(mv, max, into, store);
            }

            @Override
            public void between(int i) {
                if (y[i - 1] == y[i]) {
                    constant(mv, y[i - 1], into, store);
                    return;
                }
                // ((x1 - u) * y0 + (u - x0) * y1) / (x1 - x0). Inside the piece both differences are above 0
                // and the degrees not below +0, so each product is at least +0: a product by a degree 0 is +0
                // and adds nothing (a + +0 = a for a >= +0), and one by a degree 1 is the difference itself,
                // so those operations are left out (the same double)
                double y0 = y[i - 1];
                double y1 = y[i];
                if (y0 != 0) {
                    mv.visitLdcInsn(x[i]);
                    mv.visitVarInsn(DLOAD, u);
                    mv.visitInsn(DSUB);
                    if (y0 != 1) {
                        mv.visitLdcInsn(y0);
                        mv.visitInsn(DMUL);
                    }
                }
                if (y1 != 0) {
                    mv.visitVarInsn(DLOAD, u);
                    mv.visitLdcInsn(x[i - 1]);
                    mv.visitInsn(DSUB);
                    if (y1 != 1) {
                        mv.visitLdcInsn(y1);
                        mv.visitInsn(DMUL);
                    }
                }
                if (y0 != 0 && y1 != 0) {
                    mv.visitInsn(DADD);
                }
                mv.visitLdcInsn(x[i] - x[i - 1]);
                mv.visitInsn(DDIV);
                mv.visitVarInsn(DSTORE, into);
                mv.visitJumpInsn(GOTO, store);
            }
        });
        mv.visitLabel(store);
    }

    /**
     * Math.min (min) or Math.max of the two doubles on the stack; as {@code a <= b ? a : b} (or {@code >=}) unless
     * {@code general}: equal to Math's choice when neither is NaN nor -0.0.
     */
    private static void select(MethodVisitor mv, boolean min, boolean general) {
        if (general) {
            mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", min ? "min" : "max", "(DD)D", false);
            return;
        }
        mv.visitMethodInsn(INVOKESTATIC, "org/fclcert/eval/StaticFilter", min ? "plainMin" : "plainMax", "(DD)D",
                false);
    }

    /** Math.min for operands that are not NaN and not -0.0. */
    static double plainMin(double a, double b) {
        return a <= b ? a : b;
    }

    /** Math.max for operands that are not NaN and not -0.0. */
    static double plainMax(double a, double b) {
        return a >= b ? a : b;
    }

    /** Whether the fold of rule r before position j has no NOT (every degree there at least +0, not -0.0). */
    private boolean plainSoFar(int r, int j) {
        for (int q = ruleFrom[r]; q < j; q++) {
            if (ruleNot[q]) {
                return false;
            }
        }
        return true;
    }

    /** Whether v is +0 or above: not below 0, not -0.0, not NaN (Math.min/max and a plain comparison agree there). */
    private static boolean atLeastPlusZero(double v) {
        return v > 0 || Double.doubleToRawLongBits(v) == 0L;
    }

    /** Whether a contribution of output i before k on singleton term t may be below 0 or -0.0. */
    private boolean anyNegativeBefore(int i, int k, int t, boolean[] nonNegative) {
        for (int q = outFrom[i]; q < k; q++) {
            if (contributionTerm[q] == t
                    && !(nonNegative[contributionRule[q]] && atLeastPlusZero(contributionWeight[q]))) {
                return true;
            }
        }
        return false;
    }

    private static void constant(MethodVisitor mv, double d, int into, Label store) {
        mv.visitLdcInsn(d);
        mv.visitVarInsn(DSTORE, into);
        mv.visitJumpInsn(GOTO, store);
    }

    /**
     * The largest running bound of {@code FunctionBlockInstance.degree} on a constant shape of points over every
     * finite input: at or outside a point the point's representation distance; inside a sloped piece the running
     * formula with the input's distance at its largest there.
     */
    static double termBound(double[] x, double[] y) {
        int n = x.length;
        double b = 0;
        for (int i = 0; i < n; i++) {
            b = Math.max(b, FunctionBlockInstance.representation(y[i]));
        }
        for (int i = 1; i < n; i++) {
            if (x[i] == x[i - 1]) {
                continue;
            }
            double e = Math.max(FunctionBlockInstance.representation(y[i - 1]),
                    FunctionBlockInstance.representation(y[i]));
            if (y[i - 1] != y[i]) {
                double uRep = 0.5 * Math.ulp(Math.max(Math.abs(x[i - 1]), Math.abs(x[i])));
                double shift = uRep + FunctionBlockInstance.representation(x[i - 1])
                        + FunctionBlockInstance.representation(x[i]);
                double width = x[i] - x[i - 1];
                e = 4 * shift < width ? e + Math.abs(y[i] - y[i - 1]) * 2 * shift / width + 2 * Norms.R
                        : Double.POSITIVE_INFINITY;
            }
            b = Math.max(b, e);
        }
        return b;
    }

    /**
     * The static filter of a block the compiled kernel covers (so no chained terms, constant point or singleton
     * input terms, no bare conclusions, every subconclusion a contribution: {@code KernelCompiler.covered}), or
     * null when the filter does not cover it: every output computed whole by the kernel, conditions of one term or
     * one AND/OR of terms under MIN, PROD or MAX, constant weights, input term degrees in [0, 1] (not −0.0).
     */
    static StaticFilter build(BlockPlan plan, KernelCompiler.Compiled kernel) {
        TermChain[] chains = new TermChain[plan.outputs.length];
        for (int i = 0; i < chains.length; i++) {
            if (!kernel.outputs()[i] && (chains[i] = chainOutput(plan, i)) == null) {
                return null;
            }
        }
        for (int t = 0; t < plan.termShape.length; t++) {
            for (double y : plan.shapes[plan.termShape[t]].sortedY) {
                if (!(atLeastPlusZero(y) && y <= 1)) {
                    return null;
                }
            }
        }
        java.util.List<int[]> terms = new java.util.ArrayList<>();
        java.util.List<boolean[]> nots = new java.util.ArrayList<>();
        java.util.List<Integer> ops = new java.util.ArrayList<>();
        int[] contributionRules = new int[plan.contributionCount];
        double[] weights = new double[plan.contributionCount];
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            for (int r = 0; r < rb.conditions().length; r++) {
                ConditionCode code = rb.conditions()[r];
                int n = code.flatTerms;
                if (n == 0) {
                    return null;
                }
                int op = SINGLE;
                if (n > 1) {
                    boolean isAnd = code.ops[n] == ConditionCode.AND;
                    op = isAnd && rb.and() == AndAlgorithm.MIN ? MIN : isAnd && rb.and() == AndAlgorithm.PROD ? PROD
                            : !isAnd && rb.or() == OrAlgorithm.MAX ? MAX : -1;
                    if (op < 0) {
                        return null;
                    }
                }
                int[] ts = new int[n];
                boolean[] ns = new boolean[n];
                for (int j = 0; j < n; j++) {
                    ts[j] = code.args[j];
                    ns[j] = code.ops[j] == ConditionCode.TERM_NOT;
                }
                int rule = ops.size();
                terms.add(ts);
                nots.add(ns);
                ops.add(op);
                for (SubconclusionPlan sc : rb.conclusions()[r]) {
                    if (sc.weightSlot() >= 0) {         // a constant weight is a literal in [0, 1] (FCL-C012)
                        return null;
                    }
                    contributionRules[sc.contribution()] = rule;
                    weights[sc.contribution()] = sc.weightConst();
                }
            }
        }
        boolean anyChain = false;
        for (TermChain c : chains) {
            anyChain |= c != null;
        }
        if (anyChain && ops.size() > CHAIN_RULES) {
            return null;
        }
        // every contribution is a subconclusion of some rule (BlockCompiler), so each has its rule now
        return new StaticFilter(plan, terms.toArray(new int[0][]), ops.stream().mapToInt(Integer::intValue).toArray(),
                nots.toArray(new boolean[0][]), contributionRules, weights, chains);
    }

    /**
     * The chain of output i when the filter covers it although the kernel leaves it to the interpreter: a point-set
     * output with CoG under MAX over a chain of terms ({@link TermChain}), MIN or PROD activations, a REAL or LREAL
     * variable, no NC (nothing fired is left to the running path anyway) and, without RANGE, no term positive at its
     * outer points (else a fired one has no finite interval: the running path reports it). Null otherwise.
     */
    /**
     * The most rules of a block with chain outputs the filter takes: its step computes every rule and tests every
     * rule of degree 0 for an exact 0, where the kernel's running path skips the rules whose first term is an exact 0
     * (ZeroSkip) — faster from a few dozen rules on (125 rules: 1.4 µs a step against the kernel's 0.5 µs).
     */
    static final int CHAIN_RULES = 16;

    private static TermChain chainOutput(BlockPlan plan, int i) {
        OutputPlan o = plan.outputs[i];
        // BlockPlan.chains holds a chain only for CoG under MAX over point terms; an INT output's value is rounded on
        // store, which this step does not do. NC needs no test: a step where nothing fired goes to the running path
        TermChain chain = plan.chains()[i];
        if (chain == null || plan.types[o.slot()].isInteger()) {
            return null;
        }
        for (org.fclcert.model.ActivationMethod a : o.contributionActivation()) {
            if (a != org.fclcert.model.ActivationMethod.MIN && a != org.fclcert.model.ActivationMethod.PROD) {
                return null;
            }
        }
        for (int s : o.termShapes()) {
            Shape shape = plan.shapes[s];
            if (!o.hasRange() && (shape.sortedY[0] > 0 || shape.sortedY[shape.n - 1] > 0)) {
                return null;
            }
        }
        return chain;
    }

    /**
     * One step with the static tests: the term degrees into {@code td}, rule degrees into {@code rd}, each output's
     * value into {@code out}; when every test passes and every output fits its type, the outputs are written into
     * {@code values}, the inputs copied into {@code saved} (the step's inputs, for its running bounds later) and it
     * returns true. Else it returns false and writes nothing: the step must be evaluated with the running bounds
     * (which also report an output that does not fit).
     */
    boolean step(double[] values, double[] saved, double[] td, double[] rd, double[] sd, double[] out, Front code,
            SetBuilder set, double[] area) {
        if (code != null) {
            code.front(values, td, rd);
        } else {
            degrees(values, td, rd);
        }
        for (int i = 0; i < outputSlot.length; i++) {
            if (chainOf[i] != null) {
                if (code == null || !chainOutput(i, values, td, rd, out, code, set, area)) {
                    return false;
                }
                continue;
            }
            double[] v = singletonValue[i];
            int n = v.length;
            for (int t = 0; t < n; t++) {
                sd[t] = 0;
            }
            for (int k = outFrom[i]; k < outFrom[i + 1]; k++) {
                int t = contributionTerm[k];
                sd[t] = Norms.accumulate(AccumulationMethod.MAX, sd[t], contributionWeight[k] * rd[contributionRule[k]]);
            }
            double num = 0;
            double den = 0;
            for (int t = 0; t < n; t++) {
                num += v[t] * sd[t];
                den += sd[t];
            }
            if (!(den > threshold[i])) {
                return false;
            }
            double c = num / den;
            if (!(c >= outputMin[i] && c <= outputMax[i])) {
                return false;
            }
            out[i] = c;
        }
        for (int i = 0; i < outputSlot.length; i++) {
            values[outputSlot[i]] = out[i];
        }
        for (int k = 0; k < inputSlot.length; k++) {
            saved[k] = values[inputSlot[k]];
        }
        return true;
    }

    /** {@link #step}'s term and rule degrees, interpreted: the operations {@link #degrees(MethodVisitor, String, int, int)} generates. */
    private void degrees(double[] values, double[] td, double[] rd) {
        for (int t = 0; t < terms; t++) {
            double u = values[termSlot[t]];
            double[] x = termX[t];
            td[t] = x == null ? (u == singletonAt[t] ? 1.0 : 0.0) : Pwl.degree(x, termY[t], x.length, u);
        }
        for (int r = 0; r < rules; r++) {
            int from = ruleFrom[r];
            int to = ruleFrom[r + 1];
            double acc = ruleNot[from] ? 1.0 - td[ruleTerm[from]] : td[ruleTerm[from]];
            int op = ruleOp[r];
            for (int j = from + 1; j < to; j++) {
                double y = ruleNot[j] ? 1.0 - td[ruleTerm[j]] : td[ruleTerm[j]];
                acc = op == MIN ? Norms.and(AndAlgorithm.MIN, acc, y) : op == PROD ? Norms.and(AndAlgorithm.PROD, acc, y)
                        : Norms.or(OrAlgorithm.MAX, acc, y);
            }
            rd[r] = acc;
        }
    }

    /**
     * A chain output of {@link #step}: the running path's point set and CoG on the same doubles
     * ({@code FunctionBlockInstance.collect} and {@code pointSet}: the contributions that fired merged under MAX, the
     * chain's construction, {@link Defuzzifier#centreOfGravity}), and its decisions with the static bounds:
     * <ul>
     * <li>whether a contribution fired (collectOne): w·d above its static bound, or an exact 0 — a weight 0, or a rule
     * degree 0 that has running bound 0 — in the generated front ({@link #collect}; a block without one is left to
     * the running path);</li>
     * <li>nothing fired (DEFAULT) and a step the chain construction declines are left to the running path;</li>
     * <li>CoG's area test (decideSet): the area above 2Δ with Δ = S·W + 8(n + 2)·u·M, S the largest static bound of a
     * contribution, in decideSet's expression, which its running Δ (the largest running bound for S) does not
     * exceed;</li>
     * <li>a value that does not fit the variable's type, or NaN, is left to the running path (which reports it).</li>
     * </ul>
     */
    private boolean chainOutput(int i, double[] values, double[] td, double[] rd, double[] out, Front code,
            SetBuilder set, double[] area) {
        Activations act = set.act;
        act.clear();
        if (!code.collect(i, values, td, rd, act)) {
            return false;
        }
        if (act.n == 0) {
            return false;
        }
        double lo = chainLo[i];
        double hi = chainHi[i];
        if (!set.buildChain(chainOf[i], lo, hi, shapeX, shapeY, chainInOrder[i], staged ? code : null)) {
            return false;
        }
        double c = Defuzzifier.centreOfGravity(set.px, set.py, set.np, area);
        double delta = chainSpread[i] * (hi - lo) + FunctionBlockInstance.setRounding(set.np, chainM[i]);
        if (!(area[0] > 2 * delta) || !(c >= outputMin[i] && c <= outputMax[i])) {
            return false;
        }
        out[i] = c;
        return true;
    }

}
