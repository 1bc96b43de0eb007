package org.fclcert.eval;

import static org.objectweb.asm.Opcodes.*;

import java.lang.invoke.MethodHandles;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.eval.BlockPlan.RuleBlockPlan;
import org.fclcert.eval.BlockPlan.SubconclusionPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.OrAlgorithm;
import org.objectweb.asm.ClassTooLargeException;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodTooLargeException;
import org.objectweb.asm.MethodVisitor;

/**
 * Generates a block's {@link CompiledKernel} with ASM: the interpreter's fuzzification, rule blocks and
 * singleton CoGS written out for one plan, its points, weights and operators as constants, its loops unrolled
 * (docs/semantics.md, "The compiled kernel"). Every double the generated code computes is computed by the same
 * operations in the same order as in {@link FunctionBlockInstance} ({@code degree}, {@code aggregateTerms},
 * {@code aggregate}, {@code runRuleBlock}, {@code degreesPerTerm}, {@code centreOfGravityForSingletons}), and every bound by the same
 * {@link Norms} method; constants the interpreter derives from the plan (a segment's width, a singleton set's
 * largest |value|) are derived here by the same Java expressions. {@code KernelAgreementTest} holds the two to
 * each other bit for bit.
 *
 * <p>It covers the plans of the usual Mamdani block: input terms given by constant points (piece-wise linear or
 * singleton), conditions of terms, IS NOT, NOT, parentheses and variables with any Table 3 pair, IS
 * subconclusions with constant or variable weights; singleton outputs with MAX accumulation and CoG/CoGS are
 * compiled whole, other outputs are accumulated and defuzzified by the interpreter from the kernel's degrees. A plan with anything
 * else (variable points, named shapes, hedges, 'any', bare conclusions, the dialects' chained terms) gets no
 * kernel and is interpreted.
 *
 * <p>Its size (about 1 000 lines, above the project's 700) is earned: each emitter sits beside the interpreter
 * expression it writes out, operation by operation, so that the two can be read side by side; splitting it would
 * separate an emitter from the constants it derives.
 */
final class KernelCompiler {
    private KernelCompiler() {
    }

    /** A compiled kernel and, per output, whether {@link CompiledKernel#output} covers it. */
    record Compiled(CompiledKernel kernel, boolean[] outputs) {
    }

    private static final String NORMS = "org/fclcert/eval/Norms";
    private static final String FBI = "org/fclcert/eval/FunctionBlockInstance";
    private static final String SELF = "org/fclcert/eval/Kernel";
    private static final String FRONT_DESC = "([D[D[D[D[D[D[D[D[I)I";
    private static final String OUTPUT_DESC = "(I[D[D[D[D[D[D)D";
    private static final String ONE_OUTPUT_DESC = "([D[D[D[D[D[D)D";
    /** A budget of bytecode per generated method, well below HotSpot's 8 000-byte limit for compiling one. */
    private static final int CHUNK = 2500;

    /** The block's kernel, or null when the plan uses something the kernel does not cover. */
    static Compiled compile(BlockPlan plan) {
        if (!covered(plan)) {
            return null;
        }
        boolean[] outputs = new boolean[plan.outputs.length];
        for (int i = 0; i < outputs.length; i++) {
            outputs[i] = compiledOutput(plan, plan.outputs[i]);
        }
        ClassWriter cw = newClass(SELF, "org/fclcert/eval/CompiledKernel");
        List<String> fuzzify = fuzzifyMethods(cw, plan);
        List<String> rules = ruleMethods(cw, plan);
        MethodVisitor front = cw.visitMethod(ACC_PUBLIC, "front", FRONT_DESC, null, null);
        front.visitCode();
        for (String m : fuzzify) {
            for (int a = 1; a <= 4; a++) {
                front.visitVarInsn(ALOAD, a);
            }
            front.visitMethodInsn(INVOKESTATIC, SELF, m, "([D[D[D[D)V", false);
        }
        // the count of live contributions so far, threaded through the rule methods
        front.visitInsn(ICONST_0);
        for (String m : rules) {
            front.visitVarInsn(ISTORE, 10);
            for (int a = 3; a <= 8; a++) {
                front.visitVarInsn(ALOAD, a);
            }
            front.visitVarInsn(ALOAD, 1);
            front.visitVarInsn(ALOAD, 2);
            front.visitVarInsn(ALOAD, 9);
            front.visitVarInsn(ILOAD, 10);
            front.visitMethodInsn(INVOKESTATIC, SELF, m, RULES_DESC, false);
        }
        front.visitInsn(IRETURN);
        front.visitMaxs(0, 0);
        front.visitEnd();
        outputMethods(cw, plan, outputs);
        Object kernel = instance(cw, "the compiled kernel of block '" + plan.name + "'");
        return kernel == null ? null : new Compiled((CompiledKernel) kernel, outputs);
    }

    /** A generated final class implementing {@code iface} (internal name), with its no-argument constructor. */
    static ClassWriter newClass(String name, String iface) {
        ClassWriter cw = new ClassWriter(ClassWriter.COMPUTE_FRAMES | ClassWriter.COMPUTE_MAXS);
        cw.visit(V17, ACC_FINAL | ACC_SUPER, name, null, "java/lang/Object", new String[] {iface});
        MethodVisitor init = cw.visitMethod(0, "<init>", "()V", null, null);
        init.visitCode();
        init.visitVarInsn(ALOAD, 0);
        init.visitMethodInsn(INVOKESPECIAL, "java/lang/Object", "<init>", "()V", false);
        init.visitInsn(RETURN);
        init.visitMaxs(0, 0);
        init.visitEnd();
        return cw;
    }

    /**
     * Ends {@code cw}, defines it as a hidden class of this package and makes its one instance; null when a method or
     * the class would exceed the class file's limits (64 KiB of code in one method: an input term of a thousand points
     * is one method), so that the caller declines and the block stays with the interpreter, which computes the same
     * doubles. It used to throw there, and an evaluation of such a block failed at its 65th step.
     */
    static Object instance(ClassWriter cw, String what) {
        cw.visitEnd();
        byte[] bytes;
        try {
            bytes = cw.toByteArray();
        } catch (MethodTooLargeException | ClassTooLargeException e) {
            return null;
        }
        try {
            MethodHandles.Lookup hidden = MethodHandles.lookup().defineHiddenClass(bytes, true);
            return hidden.findConstructor(hidden.lookupClass(), java.lang.invoke.MethodType.methodType(void.class))
                    .invoke();
        } catch (Throwable e) {
            throw new IllegalStateException(what + " failed to load", e);
        }
    }

    // ------------------------------------------------------------------------------------------ what is covered

    private static boolean covered(BlockPlan plan) {
        // output-value conditions (jFuzzyLogic) are chained terms too: valueTermShape has one entry per chained
        // term (BlockCompiler.chainedDegrees), so a block without chained terms has nothing for valueConditions to do
        if (plan.chainedTerms != 0) {
            return false;
        }
        for (org.fclcert.model.Hedge[] h : plan.contributionHedges) {
            if (h != null) {
                return false;
            }
        }
        for (int t = 0; t < plan.termShape.length; t++) {
            if (!coveredShape(plan.shapes[plan.termShape[t]])) {
                return false;
            }
        }
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            if (rb.bareTargetSlots().length != 0) {
                return false;
            }
            for (int r = 0; r < rb.conditions().length; r++) {
                for (int op : rb.conditions()[r].ops) {
                    // the dialects' hedges and 'any' (aggregate refuses them: no agreement test reaches them yet)
                    if (op < ConditionCode.TERM || op > ConditionCode.OR) {
                        return false;
                    }
                }
                // a subconclusion without a contribution is a bare conclusion: declined above with its target
            }
        }
        return true;
    }

    /** Constant points, piece-wise linear or a singleton, every segment of finite width. */
    private static boolean coveredShape(Shape s) {
        if (!s.constant || s.kind != null || s.computed != null || s.n == 0) {
            return false;
        }
        for (int i = 0; i < s.n; i++) {
            if (!Double.isFinite(s.sortedX[i]) || i > 0 && !Double.isFinite(s.sortedX[i] - s.sortedX[i - 1])) {
                return false;
            }
        }
        return true;
    }

    /** Singleton terms of constant value, MAX accumulation, a method the interpreter computes as CoGS, not INT. */
    private static boolean compiledOutput(BlockPlan plan, OutputPlan o) {
        if (!o.singletons() || o.accumulation() != AccumulationMethod.MAX || plan.types[o.slot()].isInteger()
                || o.noChange()) {
            return false;
        }
        DefuzzificationMethod m = o.method();
        if (m == DefuzzificationMethod.LM || m == DefuzzificationMethod.RM || m == DefuzzificationMethod.MOM
                || m == DefuzzificationMethod.COGSS || m == DefuzzificationMethod.TSUKAMOTO) {
            return false;
        }
        for (int s : o.termShapes()) {
            Shape shape = plan.shapes[s];
            if (!shape.constant || shape.computed != null || shape.kind != null || !Double.isFinite(shape.sortedX[0])) {
                return false;
            }
        }
        return true;
    }

    // ------------------------------------------------------------------------------------------ fuzzification

    /** Locals of a fuzzification method: its four arrays, then u, uRep, d, e, shift. */
    private static final int U = 4;
    private static final int UREP = 6;
    private static final int D = 8;
    private static final int E = 10;
    private static final int SHIFT = 12;

    private static List<String> fuzzifyMethods(ClassWriter cw, BlockPlan plan) {
        List<String> names = new ArrayList<>();
        MethodVisitor mv = null;
        int used = 0;
        for (int t = 0; t < plan.termShape.length; t++) {
            Shape s = plan.shapes[plan.termShape[t]];
            int cost = 40 + 90 * s.n;
            if (mv == null || used + cost > CHUNK) {
                end(mv);
                String name = "fuzzify" + names.size();
                names.add(name);
                mv = cw.visitMethod(ACC_PRIVATE | ACC_STATIC, name, "([D[D[D[D)V", null, null);
                mv.visitCode();
                used = 0;
            }
            used += cost;
            term(mv, t, plan.termVariableSlot[t], s);
        }
        end(mv);
        return names;
    }

    private static void end(MethodVisitor mv) {
        if (mv != null) {
            mv.visitInsn(RETURN);
            mv.visitMaxs(0, 0);
            mv.visitEnd();
        }
    }

    /** FunctionBlockInstance.degree for one term of a constant shape, into td[t] and te[t]. */
    private static void term(MethodVisitor mv, int t, int slot, Shape s) {
        double[] x = s.sortedX;
        double[] y = s.sortedY;
        int n = s.n;
        double[] rx = new double[n];
        double[] ry = new double[n];
        for (int i = 0; i < n; i++) {
            rx[i] = FunctionBlockInstance.representation(x[i]);
            ry[i] = FunctionBlockInstance.representation(y[i]);
        }
        loadElement(mv, 0, slot);
        mv.visitVarInsn(DSTORE, U);
        Label store = new Label();
        if (s.singleton) {
            // u == x[0] ? 1.0 : 0.0, bound 0
            Label miss = new Label();
            mv.visitVarInsn(DLOAD, U);
            mv.visitLdcInsn(x[0]);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFNE, miss);
            constants(mv, 1.0, 0.0, store);
            mv.visitLabel(miss);
            constants(mv, 0.0, 0.0, store);
        } else {
            loadElement(mv, 1, slot);
            mv.visitVarInsn(DSTORE, UREP);
            searchPoints(mv, U, x, new PointPlaces() {
                @Override
                public void outside(int i) {
                    constants(mv, y[i], ry[i], store);
                }

                @Override
                public void atPoint(int i, int end) {
                    // degreeAtPoint: the largest degree of the points at x[i], the largest of their bounds
                    double max = y[i];
                    double e = ry[i];
                    for (int j = i + 1; j < end; j++) {
                        max = Math.max(max, y[j]);
                        e = Math.max(e, ry[j]);
                    }
                    constants(mv, max, e, store);
                }

                @Override
                public void between(int i) {
                    segment(mv, x[i - 1], y[i - 1], x[i], y[i], rx[i - 1], rx[i], ry[i - 1], ry[i], store);
                }
            });
        }
        mv.visitLabel(store);
        storeElement(mv, 2, t, D);
        storeElement(mv, 3, t, E);
    }

    /**
     * What a term's degree is at each place {@link #searchPoints} finds u: each method writes its values and jumps
     * to the caller's store label. The kernel writes a degree and its bound, the static filter the degree alone.
     */
    interface PointPlaces {
        /** u below the first point (i = 0) or above the last (i = n - 1): y[i]. */
        void outside(int i);

        /** u at x[i]; the points i to end - 1 share that abscissa (a jump): the largest of their degrees. */
        void atPoint(int i, int end);

        /** u strictly between x[i - 1] and x[i]. */
        void between(int i);
    }

    /**
     * The search for local {@code u} among a term's sorted points in Pwl.degree's order, written once for the
     * kernel and the static filter: below the first point, above the last, then for each distinct abscissa at it
     * or strictly before it. NaN is neither below nor above nor at a point, so it takes the last segment's branch.
     */
    static void searchPoints(MethodVisitor mv, int u, double[] x, PointPlaces at) {
        int n = x.length;
        Label notBelow = new Label();
        mv.visitVarInsn(DLOAD, u);
        mv.visitLdcInsn(x[0]);
        mv.visitInsn(DCMPG);
        mv.visitJumpInsn(IFGE, notBelow);
        at.outside(0);
        mv.visitLabel(notBelow);
        Label notAbove = new Label();
        mv.visitVarInsn(DLOAD, u);
        mv.visitLdcInsn(x[n - 1]);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFLE, notAbove);
        at.outside(n - 1);
        mv.visitLabel(notAbove);
        // i = the first index with x[i] >= u (Pwl.linearLowerBound / lowerBound); u == x[i]: the point's degree
        for (int i = 0; i < n; i++) {
            if (i > 0 && x[i] == x[i - 1]) {
                continue;   // the first of equal abscissas is found first
            }
            boolean last = x[i] == x[n - 1];
            Label next = new Label();
            if (!last) {
                mv.visitVarInsn(DLOAD, u);
                mv.visitLdcInsn(x[i]);
                mv.visitInsn(DCMPG);
                mv.visitJumpInsn(IFGT, next);
            }
            Label between = new Label();
            if (i > 0) {
                mv.visitVarInsn(DLOAD, u);
                mv.visitLdcInsn(x[i]);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFNE, between);
            }
            int end = i + 1;
            while (end < n && x[end] == x[i]) {
                end++;
            }
            at.atPoint(i, end);
            if (i > 0) {
                mv.visitLabel(between);
                at.between(i);
            }
            if (last) {
                break;
            }
            mv.visitLabel(next);
        }
    }

    /** d := a, e := b, then to the store. */
    private static void constants(MethodVisitor mv, double d, double e, Label store) {
        mv.visitLdcInsn(d);
        mv.visitVarInsn(DSTORE, D);
        mv.visitLdcInsn(e);
        mv.visitVarInsn(DSTORE, E);
        mv.visitJumpInsn(GOTO, store);
    }

    /** Between x0 and x1 (u strictly inside): Pwl.interpolate and the bound of FunctionBlockInstance.degree. */
    private static void segment(MethodVisitor mv, double x0, double y0, double x1, double y1, double rx0, double rx1,
            double ry0, double ry1, Label store) {
        double e = Math.max(ry0, ry1);
        if (y0 == y1) {
            constants(mv, y0, e, store);
            return;
        }
        double width = x1 - x0;
        // ((x1 - u) * y0 + (u - x0) * y1) / width
        mv.visitLdcInsn(x1);
        mv.visitVarInsn(DLOAD, U);
        mv.visitInsn(DSUB);
        mv.visitLdcInsn(y0);
        mv.visitInsn(DMUL);
        mv.visitVarInsn(DLOAD, U);
        mv.visitLdcInsn(x0);
        mv.visitInsn(DSUB);
        mv.visitLdcInsn(y1);
        mv.visitInsn(DMUL);
        mv.visitInsn(DADD);
        mv.visitLdcInsn(width);
        mv.visitInsn(DDIV);
        mv.visitVarInsn(DSTORE, D);
        Label shifted = new Label();
        if (rx0 == 0 && rx1 == 0) {
            // uRep != 0 || repX[i-1] != 0 || repX[i] != 0: only uRep is not known here
            mv.visitVarInsn(DLOAD, UREP);
            mv.visitInsn(DCONST_0);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFNE, shifted);
            mv.visitLdcInsn(e + 2 * Norms.R);
            mv.visitVarInsn(DSTORE, E);
            mv.visitJumpInsn(GOTO, store);
        }
        mv.visitLabel(shifted);
        // shift = uRep + repX[i-1] + repX[i]
        mv.visitVarInsn(DLOAD, UREP);
        mv.visitLdcInsn(rx0);
        mv.visitInsn(DADD);
        mv.visitLdcInsn(rx1);
        mv.visitInsn(DADD);
        mv.visitVarInsn(DSTORE, SHIFT);
        // 4 * shift < width ? e + Math.abs(y1 - y0) * 2 * shift / width + 2 * Norms.R : infinity
        Label wide = new Label();
        mv.visitLdcInsn(4.0);
        mv.visitVarInsn(DLOAD, SHIFT);
        mv.visitInsn(DMUL);
        mv.visitLdcInsn(width);
        mv.visitInsn(DCMPG);
        mv.visitJumpInsn(IFLT, wide);
        mv.visitLdcInsn(Double.POSITIVE_INFINITY);
        mv.visitVarInsn(DSTORE, E);
        mv.visitJumpInsn(GOTO, store);
        mv.visitLabel(wide);
        mv.visitLdcInsn(e);
        mv.visitLdcInsn(Math.abs(y1 - y0) * 2);
        mv.visitVarInsn(DLOAD, SHIFT);
        mv.visitInsn(DMUL);
        mv.visitLdcInsn(width);
        mv.visitInsn(DDIV);
        mv.visitInsn(DADD);
        mv.visitLdcInsn(2 * Norms.R);
        mv.visitInsn(DADD);
        mv.visitVarInsn(DSTORE, E);
        mv.visitJumpInsn(GOTO, store);
    }

    private static void loadElement(MethodVisitor mv, int array, int index) {
        mv.visitVarInsn(ALOAD, array);
        push(mv, index);
        mv.visitInsn(DALOAD);
    }

    private static void storeElement(MethodVisitor mv, int array, int index, int local) {
        mv.visitVarInsn(ALOAD, array);
        push(mv, index);
        mv.visitVarInsn(DLOAD, local);
        mv.visitInsn(DASTORE);
    }

    private static void storeConstant(MethodVisitor mv, int array, int index, double value) {
        mv.visitVarInsn(ALOAD, array);
        push(mv, index);
        mv.visitLdcInsn(value);
        mv.visitInsn(DASTORE);
    }

    /** Pushes the int constant i with the shortest instruction. */
    static void push(MethodVisitor mv, int i) {
        if (i <= 5) {
            mv.visitInsn(ICONST_0 + i);
        } else if (i <= Byte.MAX_VALUE) {
            mv.visitIntInsn(BIPUSH, i);
        } else if (i <= Short.MAX_VALUE) {
            mv.visitIntInsn(SIPUSH, i);
        } else {
            mv.visitLdcInsn(i);
        }
    }

    // ------------------------------------------------------------------------------------------ rule blocks

    /**
     * Locals of a rule method: td, te, cd, cw, ce, cde, values, valueRep (0–7), live and its count (8, 9), then acc,
     * e, y, ey, r, wd, w, ew, and from STACK the degree and bound of each entry of a condition's stack. A rule method
     * returns the count of live contributions.
     */
    private static final int LIVE = 8;
    private static final int COUNT = 9;
    private static final int ACC = 10;
    private static final int ERR = 12;
    private static final int Y = 14;
    private static final int EY = 16;
    private static final int R = 18;
    private static final int WD = 20;
    private static final int W = 22;
    private static final int EW = 24;
    private static final int STACK = 26;
    private static final String RULES_DESC = "([D[D[D[D[D[D[D[D[II)I";

    private static List<String> ruleMethods(ClassWriter cw, BlockPlan plan) {
        List<String> names = new ArrayList<>();
        MethodVisitor mv = null;
        int used = 0;
        for (RuleBlockPlan rb : plan.ruleBlocks) {
            int rules = rb.conditions().length;
            for (int r = 0; r < rules; ) {
                // a run of consecutive rules that an exact 0 of the same first term settles: one test for all
                // (a run within one method's budget: a longer one is split, each part behind its own test)
                int first = zeroSkipTerm(rb, r);
                int end = r + 1;
                int cost = ruleCost(rb, r);
                while (first >= 0 && end < rules && zeroSkipTerm(rb, end) == first && cost + ruleCost(rb, end) <= CHUNK) {
                    cost += ruleCost(rb, end);
                    end++;
                }
                if (mv == null || used + cost > CHUNK) {
                    endRules(mv);
                    String name = "rules" + names.size();
                    names.add(name);
                    mv = cw.visitMethod(ACC_PRIVATE | ACC_STATIC, name, RULES_DESC, null, null);
                    mv.visitCode();
                    used = 0;
                }
                used += cost;
                runs(mv, rb, r, end, 0);
                r = end;
            }
        }
        endRules(mv);
        return names;
    }

    /** The bytecode budget of rule r, with room for the tests of its runs. */
    private static int ruleCost(RuleBlockPlan rb, int r) {
        return 60 + 70 * rb.conditions()[r].ops.length + 120 * rb.conclusions()[r].length;
    }

    /**
     * Rules from..to-1, which share their first {@code level} terms (all rules ZeroSkip may settle, when level &gt; 0),
     * in runs of consecutive rules with the same term at position {@code level}, each run behind one test that
     * settles all of its rules with nothing to write:
     * <ul>
     * <li>level 0, runRuleBlock's ZeroSkip: the first term's degree is 0 with bound 0; the rules give degree 0, their
     * constant weights and bounds 0;</li>
     * <li>level k &gt; 0: the first k terms' degrees are above 0 and the next term's is +0 with bound 0. The fold of
     * MIN or PROD reaches that term with a degree not below +0 (or stopped before at +0 with bound 0) and gives +0
     * with bound 0 there ({@code minError}'s and {@code productError}'s first case), then stops: the rule writes
     * degree +0, its constant weight, bounds 0, as ZeroSkip does.</li>
     * </ul>
     * FunctionBlockInstance.clearLive has set every contribution the kernel did not write in the step before to just
     * those values, so a settled run writes nothing. A run of more than one rule is split again by the next term.
     */
    private static void runs(MethodVisitor mv, RuleBlockPlan rb, int from, int to, int level) {
        for (int q = from; q < to; ) {
            int t = termAt(rb, q, level);
            int end = q + 1;
            while (t >= 0 && end < to && termAt(rb, end, level) == t) {
                end++;
            }
            Label past = new Label();
            if (t >= 0) {
                Label run = new Label();
                int[] args = rb.conditions()[q].args;
                if (level == 0) {
                    loadElement(mv, 0, t);
                    mv.visitInsn(DCONST_0);
                    mv.visitInsn(DCMPL);
                    mv.visitJumpInsn(IFNE, run);
                } else {
                    for (int i = 0; i < level; i++) {
                        loadElement(mv, 0, args[i]);
                        mv.visitInsn(DCONST_0);
                        mv.visitInsn(DCMPL);
                        mv.visitJumpInsn(IFLE, run);
                    }
                    loadElement(mv, 0, t);
                    mv.visitMethodInsn(INVOKESTATIC, "java/lang/Double", "doubleToRawLongBits", "(D)J", false);
                    mv.visitInsn(LCONST_0);
                    mv.visitInsn(LCMP);
                    mv.visitJumpInsn(IFNE, run);
                }
                loadElement(mv, 1, t);
                mv.visitInsn(DCONST_0);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFEQ, past);
                mv.visitLabel(run);
            }
            if (t >= 0 && end - q > 1) {
                runs(mv, rb, q, end, level + 1);
            } else {
                for (int k = q; k < end; k++) {
                    rule(mv, rb, rb.conditions()[k], rb.conclusions()[k]);
                }
            }
            mv.visitLabel(past);
            q = end;
        }
    }

    /** The term at position {@code level} of rule r's flat AND (not negated) when ZeroSkip may settle r, else -1. */
    private static int termAt(RuleBlockPlan rb, int r, int level) {
        ConditionCode code = rb.conditions()[r];
        return zeroSkipTerm(rb, r) >= 0 && code.flatTerms > level && code.ops[level] == ConditionCode.TERM
                ? code.args[level] : -1;
    }

    /**
     * The first term whose exact 0 settles rule r (runRuleBlock's ZeroSkip: a lone term or an AND by MIN or PROD
     * of terms, its subconclusions of constant weight), else -1.
     */
    private static int zeroSkipTerm(RuleBlockPlan rb, int r) {
        ConditionCode code = rb.conditions()[r];
        int n = code.flatTerms;
        boolean absorbs = n > 1 && code.ops[n] == ConditionCode.AND
                && (rb.and() == AndAlgorithm.MIN || rb.and() == AndAlgorithm.PROD);
        for (SubconclusionPlan sc : rb.conclusions()[r]) {
            if (sc.weightSlot() >= 0) {
                return -1;
            }
        }
        return n > 0 && code.ops[0] == ConditionCode.TERM && (n == 1 || absorbs) ? code.args[0] : -1;
    }

    private static void endRules(MethodVisitor mv) {
        if (mv != null) {
            mv.visitVarInsn(ILOAD, COUNT);
            mv.visitInsn(IRETURN);
            mv.visitMaxs(0, 0);
            mv.visitEnd();
        }
    }

    /**
     * FunctionBlockInstance.runRuleBlock for one rule (its ZeroSkip tested before, in {@link #ruleMethods}):
     * aggregateTerms or aggregate, and its subconclusions.
     */
    private static void rule(MethodVisitor mv, RuleBlockPlan rb, ConditionCode code, SubconclusionPlan[] scs) {
        int[] ops = code.ops;
        int[] args = code.args;
        int n = code.flatTerms;
        AndAlgorithm and = rb.and();
        OrAlgorithm or = rb.or();
        boolean isAnd = n > 1 && ops[n] == ConditionCode.AND;
        boolean absorbs = isAnd && (and == AndAlgorithm.MIN || and == AndAlgorithm.PROD);
        Label next = new Label();
        if (n == 0) {
            aggregate(mv, code, and, or);
        }
        Label folded = new Label();
        if (n > 0) {
            operand(mv, ops[0], args[0], ACC, ERR);
        }
        for (int j = 1; j < n; j++) {
            if (absorbs) {
                Label go = new Label();
                mv.visitVarInsn(DLOAD, ACC);
                mv.visitInsn(DCONST_0);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFNE, go);
                mv.visitVarInsn(DLOAD, ERR);
                mv.visitInsn(DCONST_0);
                mv.visitInsn(DCMPL);
                mv.visitJumpInsn(IFEQ, folded);
                mv.visitLabel(go);
            }
            operand(mv, ops[j], args[j], Y, EY);
            if (isAnd) {
                and(mv, and);
            } else {
                or(mv, or);
            }
            mv.visitVarInsn(DLOAD, R);
            mv.visitVarInsn(DSTORE, ACC);
        }
        mv.visitLabel(folded);
        // an exact 0 (d = 0, bound 0): productError's first case, 0, without the call
        Label inexact = new Label();
        mv.visitVarInsn(DLOAD, ACC);
        mv.visitInsn(DCONST_0);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFNE, inexact);
        mv.visitVarInsn(DLOAD, ERR);
        mv.visitInsn(DCONST_0);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFNE, inexact);
        for (SubconclusionPlan sc : scs) {
            weight(mv, sc);
            storeElement(mv, 2, sc.contribution(), ACC);
            storeElement(mv, 3, sc.contribution(), W);
            storeConstant(mv, 4, sc.contribution(), 0.0);
            storeElement(mv, 5, sc.contribution(), ERR);
            live(mv, sc.contribution());
        }
        mv.visitJumpInsn(GOTO, next);
        mv.visitLabel(inexact);
        for (SubconclusionPlan sc : scs) {
            int c = sc.contribution();
            weight(mv, sc);
            // wd = w * d; ewd = Norms.productError(w, ew, d, e, wd)
            mv.visitVarInsn(DLOAD, W);
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitInsn(DMUL);
            mv.visitVarInsn(DSTORE, WD);
            storeElement(mv, 2, c, ACC);
            storeElement(mv, 3, c, W);
            mv.visitVarInsn(ALOAD, 4);
            push(mv, c);
            mv.visitVarInsn(DLOAD, W);
            mv.visitVarInsn(DLOAD, EW);
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitVarInsn(DLOAD, ERR);
            mv.visitVarInsn(DLOAD, WD);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "productError", "(DDDDD)D", false);
            mv.visitInsn(DASTORE);
            storeElement(mv, 5, c, ERR);
            live(mv, c);
        }
        mv.visitLabel(next);
    }

    /** live[count++] = c: a contribution written in this step (FunctionBlockInstance clears it before the next). */
    private static void live(MethodVisitor mv, int c) {
        mv.visitVarInsn(ALOAD, LIVE);
        mv.visitVarInsn(ILOAD, COUNT);
        push(mv, c);
        mv.visitInsn(IASTORE);
        mv.visitIincInsn(COUNT, 1);
    }

    /**
     * w and ew of runRuleBlock: a constant and its decimal reading's distance, or clamp01 of a variable with
     * (w == value ? valueRep : 0) + slotErrors, the last always 0 in the kernel's plans (no bare conclusions write
     * a bound before the rule blocks end).
     */
    private static void weight(MethodVisitor mv, SubconclusionPlan sc) {
        if (sc.weightSlot() < 0) {
            mv.visitLdcInsn(sc.weightConst());
            mv.visitVarInsn(DSTORE, W);
            mv.visitLdcInsn(FunctionBlockInstance.representation(sc.weightConst()));
            mv.visitVarInsn(DSTORE, EW);
            return;
        }
        variable(mv, sc.weightSlot(), W, EW);
    }

    /** clamp01(values[slot]) into d, (d == values[slot] ? valueRep[slot] : 0) + 0 (slotErrors) into e. */
    private static void variable(MethodVisitor mv, int slot, int d, int e) {
        mv.visitInsn(DCONST_0);
        mv.visitInsn(DCONST_1);
        loadElement(mv, 6, slot);
        mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", "min", "(DD)D", false);
        mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", "max", "(DD)D", false);
        mv.visitVarInsn(DSTORE, d);
        Label differs = new Label();
        Label done = new Label();
        mv.visitVarInsn(DLOAD, d);
        loadElement(mv, 6, slot);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFNE, differs);
        loadElement(mv, 7, slot);
        mv.visitJumpInsn(GOTO, done);
        mv.visitLabel(differs);
        mv.visitInsn(DCONST_0);
        mv.visitLabel(done);
        mv.visitInsn(DCONST_0);
        mv.visitInsn(DADD);
        mv.visitVarInsn(DSTORE, e);
    }

    /** FunctionBlockInstance.aggregate: the postfix code on a stack of locals, the result into acc and err. */
    private static void aggregate(MethodVisitor mv, ConditionCode code, AndAlgorithm and, OrAlgorithm or) {
        int sp = 0;
        for (int i = 0; i < code.ops.length; i++) {
            int arg = code.args[i];
            switch (code.ops[i]) {
                case ConditionCode.TERM, ConditionCode.TERM_NOT -> operand(mv, code.ops[i], arg, STACK + 4 * sp,
                        STACK + 4 * sp + 2);
                case ConditionCode.VARIABLE -> variable(mv, arg, STACK + 4 * sp, STACK + 4 * sp + 2);
                case ConditionCode.NOT -> {
                    int d = STACK + 4 * (sp - 1);
                    mv.visitVarInsn(DLOAD, d);
                    mv.visitVarInsn(DLOAD, d + 2);
                    mv.visitMethodInsn(INVOKESTATIC, NORMS, "notError", "(DD)D", false);
                    mv.visitVarInsn(DSTORE, d + 2);
                    mv.visitInsn(DCONST_1);
                    mv.visitVarInsn(DLOAD, d);
                    mv.visitInsn(DSUB);
                    mv.visitVarInsn(DSTORE, d);
                }
                // the dialects' hedges and 'any': covered() declines them, so no kernel meets them (emitters for
                // them would be code no program runs; write them with an agreement test when the kernel takes them)
                case ConditionCode.HEDGE, ConditionCode.ONE -> throw new IllegalStateException(
                        "the kernel does not cover hedges and 'any'");
                default -> {
                    // AND / OR of the top arg entries (fold: no early stop)
                    int base = sp - arg;
                    int b = STACK + 4 * base;
                    mv.visitVarInsn(DLOAD, b);
                    mv.visitVarInsn(DSTORE, ACC);
                    mv.visitVarInsn(DLOAD, b + 2);
                    mv.visitVarInsn(DSTORE, ERR);
                    for (int j = base + 1; j < sp; j++) {
                        mv.visitVarInsn(DLOAD, STACK + 4 * j);
                        mv.visitVarInsn(DSTORE, Y);
                        mv.visitVarInsn(DLOAD, STACK + 4 * j + 2);
                        mv.visitVarInsn(DSTORE, EY);
                        if (code.ops[i] == ConditionCode.AND) {
                            and(mv, and);
                        } else {
                            or(mv, or);
                        }
                        mv.visitVarInsn(DLOAD, R);
                        mv.visitVarInsn(DSTORE, ACC);
                    }
                    mv.visitVarInsn(DLOAD, ACC);
                    mv.visitVarInsn(DSTORE, b);
                    mv.visitVarInsn(DLOAD, ERR);
                    mv.visitVarInsn(DSTORE, b + 2);
                    sp = base;
                }
            }
            sp += switch (code.ops[i]) {
                case ConditionCode.TERM, ConditionCode.TERM_NOT, ConditionCode.VARIABLE, ConditionCode.ONE,
                        ConditionCode.AND, ConditionCode.OR -> 1;
                default -> 0;
            };
        }
        mv.visitVarInsn(DLOAD, STACK);
        mv.visitVarInsn(DSTORE, ACC);
        mv.visitVarInsn(DLOAD, STACK + 2);
        mv.visitVarInsn(DSTORE, ERR);
    }

    /** A term's degree and bound into two locals; TERM_NOT: Norms.notError, then 1 − d. */
    private static void operand(MethodVisitor mv, int op, int t, int d, int e) {
        loadElement(mv, 0, t);
        mv.visitVarInsn(DSTORE, d);
        loadElement(mv, 1, t);
        mv.visitVarInsn(DSTORE, e);
        if (op == ConditionCode.TERM_NOT) {
            mv.visitVarInsn(DLOAD, d);
            mv.visitVarInsn(DLOAD, e);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "notError", "(DD)D", false);
            mv.visitVarInsn(DSTORE, e);
            mv.visitInsn(DCONST_1);
            mv.visitVarInsn(DLOAD, d);
            mv.visitInsn(DSUB);
            mv.visitVarInsn(DSTORE, d);
        }
    }

    /** r := and(acc, y), err := andError(acc, err, y, ey, r). */
    private static void and(MethodVisitor mv, AndAlgorithm and) {
        if (and == AndAlgorithm.MIN) {
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitVarInsn(DLOAD, Y);
            mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", "min", "(DD)D", false);
        } else if (and == AndAlgorithm.PROD) {
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitVarInsn(DLOAD, Y);
            mv.visitInsn(DMUL);
        } else {
            mv.visitFieldInsn(GETSTATIC, "org/fclcert/model/AndAlgorithm", and.name(),
                    "Lorg/fclcert/model/AndAlgorithm;");
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitVarInsn(DLOAD, Y);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "and", "(Lorg/fclcert/model/AndAlgorithm;DD)D", false);
        }
        mv.visitVarInsn(DSTORE, R);
        if (and == AndAlgorithm.MIN) {
            fourOperands(mv);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "minError", "(DDDD)D", false);
        } else if (and == AndAlgorithm.PROD) {
            fourOperands(mv);
            mv.visitVarInsn(DLOAD, R);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "productError", "(DDDDD)D", false);
        } else {
            mv.visitFieldInsn(GETSTATIC, "org/fclcert/model/AndAlgorithm", and.name(),
                    "Lorg/fclcert/model/AndAlgorithm;");
            fourOperands(mv);
            mv.visitVarInsn(DLOAD, R);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "andError", "(Lorg/fclcert/model/AndAlgorithm;DDDDD)D", false);
        }
        mv.visitVarInsn(DSTORE, ERR);
    }

    /** r := or(acc, y), err := orError(acc, err, y, ey, r). */
    private static void or(MethodVisitor mv, OrAlgorithm or) {
        if (or == OrAlgorithm.MAX) {
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitVarInsn(DLOAD, Y);
            mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", "max", "(DD)D", false);
            mv.visitVarInsn(DSTORE, R);
            fourOperands(mv);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "maxError", "(DDDD)D", false);
        } else {
            mv.visitFieldInsn(GETSTATIC, "org/fclcert/model/OrAlgorithm", or.name(), "Lorg/fclcert/model/OrAlgorithm;");
            mv.visitVarInsn(DLOAD, ACC);
            mv.visitVarInsn(DLOAD, Y);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "or", "(Lorg/fclcert/model/OrAlgorithm;DD)D", false);
            mv.visitVarInsn(DSTORE, R);
            mv.visitFieldInsn(GETSTATIC, "org/fclcert/model/OrAlgorithm", or.name(), "Lorg/fclcert/model/OrAlgorithm;");
            fourOperands(mv);
            mv.visitVarInsn(DLOAD, R);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "orError", "(Lorg/fclcert/model/OrAlgorithm;DDDDD)D", false);
        }
        mv.visitVarInsn(DSTORE, ERR);
    }

    private static void fourOperands(MethodVisitor mv) {
        mv.visitVarInsn(DLOAD, ACC);
        mv.visitVarInsn(DLOAD, ERR);
        mv.visitVarInsn(DLOAD, Y);
        mv.visitVarInsn(DLOAD, EY);
    }

    // ------------------------------------------------------------------------------------------ singleton outputs

    private static void outputMethods(ClassWriter cw, BlockPlan plan, boolean[] outputs) {
        MethodVisitor mv = cw.visitMethod(ACC_PUBLIC, "output", OUTPUT_DESC, null, null);
        mv.visitCode();
        Label[] cases = new Label[outputs.length];
        Label none = new Label();
        for (int i = 0; i < outputs.length; i++) {
            cases[i] = outputs[i] ? new Label() : none;
        }
        if (outputs.length > 0) {
            mv.visitVarInsn(ILOAD, 1);
            mv.visitTableSwitchInsn(0, outputs.length - 1, none, cases);
        }
        for (int i = 0; i < outputs.length; i++) {
            if (!outputs[i]) {
                continue;
            }
            mv.visitLabel(cases[i]);
            for (int a = 2; a <= 7; a++) {
                mv.visitVarInsn(ALOAD, a);
            }
            mv.visitMethodInsn(INVOKESTATIC, SELF, "output" + i, ONE_OUTPUT_DESC, false);
            mv.visitInsn(DRETURN);
        }
        mv.visitLabel(none);
        mv.visitTypeInsn(NEW, "java/lang/IllegalArgumentException");
        mv.visitInsn(DUP);
        mv.visitMethodInsn(INVOKESPECIAL, "java/lang/IllegalArgumentException", "<init>", "()V", false);
        mv.visitInsn(ATHROW);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
        for (int i = 0; i < outputs.length; i++) {
            if (outputs[i]) {
                singletonOutput(cw, plan, plan.outputs[i], i);
            }
        }
    }

    /**
     * FunctionBlockInstance.degreesPerTerm (MAX) and centreOfGravityForSingletons for one output. Locals: cd, cw, ce,
     * sd, se, scratch (0–5), status (6), then a, acc, num, den, errors, c, spread, bound, and per term its degree and
     * bound.
     */
    private static void singletonOutput(ClassWriter cw, BlockPlan plan, OutputPlan o, int index) {
        final int status = 6;
        final int a = 7;
        final int acc = 9;
        final int num = 11;
        final int den = 13;
        final int errors = 15;
        final int c = 17;
        final int spread = 19;
        final int bound = 21;
        final int sd0 = 23;
        int terms = o.termShapes().length;
        MethodVisitor mv = cw.visitMethod(ACC_PRIVATE | ACC_STATIC, "output" + index, ONE_OUTPUT_DESC, null, null);
        mv.visitCode();
        for (int t = 0; t < terms; t++) {
            mv.visitInsn(DCONST_0);
            mv.visitVarInsn(DSTORE, sd0 + 4 * t);
            mv.visitInsn(DCONST_0);
            mv.visitVarInsn(DSTORE, sd0 + 4 * t + 2);
        }
        int[] cs = o.contributions();
        for (int k = 0; k < cs.length; k++) {
            int sd = sd0 + 4 * o.contributionTerm()[k];
            int se = sd + 2;
            // a = w * d; acc = max(sd, a); se = maxError(sd, se, a, e); sd = acc
            loadElement(mv, 1, cs[k]);
            loadElement(mv, 0, cs[k]);
            mv.visitInsn(DMUL);
            mv.visitVarInsn(DSTORE, a);
            mv.visitVarInsn(DLOAD, sd);
            mv.visitVarInsn(DLOAD, a);
            mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", "max", "(DD)D", false);
            mv.visitVarInsn(DSTORE, acc);
            mv.visitVarInsn(DLOAD, sd);
            mv.visitVarInsn(DLOAD, se);
            mv.visitVarInsn(DLOAD, a);
            loadElement(mv, 2, cs[k]);
            mv.visitMethodInsn(INVOKESTATIC, NORMS, "maxError", "(DDDD)D", false);
            mv.visitVarInsn(DSTORE, se);
            mv.visitVarInsn(DLOAD, acc);
            mv.visitVarInsn(DSTORE, sd);
        }
        // whether any rule fired: some degree above its bound, or every degree an exact 0
        Label decided = new Label();
        Label notEmpty = new Label();
        mv.visitInsn(ICONST_0);
        mv.visitVarInsn(ISTORE, status);
        for (int t = 0; t < terms; t++) {
            mv.visitVarInsn(DLOAD, sd0 + 4 * t);
            mv.visitVarInsn(DLOAD, sd0 + 4 * t + 2);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFGT, decided);
        }
        for (int t = 0; t < terms; t++) {
            mv.visitVarInsn(DLOAD, sd0 + 4 * t);
            mv.visitInsn(DCONST_0);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFNE, notEmpty);
            mv.visitVarInsn(DLOAD, sd0 + 4 * t + 2);
            mv.visitInsn(DCONST_0);
            mv.visitInsn(DCMPL);
            mv.visitJumpInsn(IFNE, notEmpty);
        }
        mv.visitJumpInsn(GOTO, decided);
        mv.visitLabel(notEmpty);
        mv.visitInsn(ICONST_1);
        mv.visitVarInsn(ISTORE, status);
        mv.visitLabel(decided);
        for (int t = 0; t < terms; t++) {
            storeElement(mv, 3, t, sd0 + 4 * t);
            storeElement(mv, 4, t, sd0 + 4 * t + 2);
        }
        // CoGS: the singleton values, their decimal readings' largest distance and largest |value| are constants
        double[] v = new double[terms];
        double maxAbs = 0;
        double maxRep = 0;
        for (int t = 0; t < terms; t++) {
            v[t] = plan.shapes[o.termShapes()[t]].sortedX[0];
            maxAbs = Math.max(maxAbs, Math.abs(v[t]));
            maxRep = Math.max(maxRep, FunctionBlockInstance.representation(v[t]));
        }
        mv.visitInsn(DCONST_0);
        mv.visitVarInsn(DSTORE, num);
        mv.visitInsn(DCONST_0);
        mv.visitVarInsn(DSTORE, den);
        mv.visitInsn(DCONST_0);
        mv.visitVarInsn(DSTORE, errors);
        for (int t = 0; t < terms; t++) {
            mv.visitVarInsn(DLOAD, num);
            mv.visitLdcInsn(v[t]);
            mv.visitVarInsn(DLOAD, sd0 + 4 * t);
            mv.visitInsn(DMUL);
            mv.visitInsn(DADD);
            mv.visitVarInsn(DSTORE, num);
            mv.visitVarInsn(DLOAD, den);
            mv.visitVarInsn(DLOAD, sd0 + 4 * t);
            mv.visitInsn(DADD);
            mv.visitVarInsn(DSTORE, den);
            mv.visitVarInsn(DLOAD, errors);
            mv.visitVarInsn(DLOAD, sd0 + 4 * t + 2);
            mv.visitInsn(DADD);
            mv.visitVarInsn(DSTORE, errors);
        }
        // !(den > 0): nothing fired, NaN (the bound stays 0)
        Label positive = new Label();
        mv.visitVarInsn(DLOAD, den);
        mv.visitInsn(DCONST_0);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFGT, positive);
        finish(mv, status, null, 0.0);
        mv.visitLdcInsn(Double.NaN);
        mv.visitInsn(DRETURN);
        mv.visitLabel(positive);
        mv.visitVarInsn(DLOAD, num);
        mv.visitVarInsn(DLOAD, den);
        mv.visitInsn(DDIV);
        mv.visitVarInsn(DSTORE, c);
        double rounding = 2 * (terms + 1) * (0x1.0p-53) * maxAbs;
        Label inexact = new Label();
        mv.visitVarInsn(DLOAD, errors);
        mv.visitInsn(DCONST_0);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFNE, inexact);
        finish(mv, status, null, maxRep + 2 * (terms + 1) * (0x1.0p-53) * maxAbs);
        mv.visitVarInsn(DLOAD, c);
        mv.visitInsn(DRETURN);
        mv.visitLabel(inexact);
        Label open = new Label();
        mv.visitVarInsn(DLOAD, den);
        mv.visitVarInsn(DLOAD, errors);
        mv.visitInsn(DCMPL);
        mv.visitJumpInsn(IFLE, open);
        mv.visitInsn(DCONST_0);
        mv.visitVarInsn(DSTORE, spread);
        for (int t = 0; t < terms; t++) {
            // spread += Math.abs(v - c) * e
            mv.visitVarInsn(DLOAD, spread);
            mv.visitLdcInsn(v[t]);
            mv.visitVarInsn(DLOAD, c);
            mv.visitInsn(DSUB);
            mv.visitMethodInsn(INVOKESTATIC, "java/lang/Math", "abs", "(D)D", false);
            mv.visitVarInsn(DLOAD, sd0 + 4 * t + 2);
            mv.visitInsn(DMUL);
            mv.visitInsn(DADD);
            mv.visitVarInsn(DSTORE, spread);
        }
        // spread / (den - errors) + maxRep + 2 * (terms + 1) * U * maxAbs
        mv.visitVarInsn(DLOAD, spread);
        mv.visitVarInsn(DLOAD, den);
        mv.visitVarInsn(DLOAD, errors);
        mv.visitInsn(DSUB);
        mv.visitInsn(DDIV);
        mv.visitLdcInsn(maxRep);
        mv.visitInsn(DADD);
        mv.visitLdcInsn(rounding);
        mv.visitInsn(DADD);
        mv.visitVarInsn(DSTORE, bound);
        finish(mv, status, bound, 0.0);
        mv.visitVarInsn(DLOAD, c);
        mv.visitInsn(DRETURN);
        mv.visitLabel(open);
        // the CoGS bound is open: the first undecided decision, unless one came before
        Label keep = new Label();
        mv.visitVarInsn(ILOAD, status);
        mv.visitJumpInsn(IFNE, keep);
        mv.visitInsn(ICONST_2);
        mv.visitVarInsn(ISTORE, status);
        mv.visitLabel(keep);
        finish(mv, status, null, Double.POSITIVE_INFINITY);
        mv.visitVarInsn(DLOAD, c);
        mv.visitInsn(DRETURN);
        mv.visitMaxs(0, 0);
        mv.visitEnd();
    }

    /** scratch[0] := the bound (a local, or a constant when {@code local} is null), scratch[1] := status. */
    private static void finish(MethodVisitor mv, int status, Integer local, double constant) {
        mv.visitVarInsn(ALOAD, 5);
        mv.visitInsn(ICONST_0);
        if (local != null) {
            mv.visitVarInsn(DLOAD, local);
        } else {
            mv.visitLdcInsn(constant);
        }
        mv.visitInsn(DASTORE);
        mv.visitVarInsn(ALOAD, 5);
        mv.visitInsn(ICONST_1);
        mv.visitVarInsn(ILOAD, status);
        mv.visitInsn(I2D);
        mv.visitInsn(DASTORE);
    }
}
