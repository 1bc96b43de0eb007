package org.fclcert.eval;

import java.lang.invoke.MethodHandles;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A MIN/MAX rule block (conditions that are one term or an AND MIN over terms, every subconclusion
 * accumulated by MAX: the usual Mamdani block) as code of its own: the degrees of its unimodal input
 * terms ({@link TermDegrees}), 1 − μ for its negated terms, each rule's minimum and each accumulator's
 * maximum in locals, the accumulators written out once at the end, and each singleton CoGS output
 * computed and stored. It computes exactly what {@link CompiledEvaluator}'s array loops compute, bit for
 * bit (the one reordering, clamping once per rule instead of once per term, is exact: see the comment at
 * the rule loop); it is faster because an interpreted plan loads every constant and index from an array
 * and keeps every intermediate in memory, while here the JIT sees constants and keeps the block in
 * registers (docs/performance.md has the figures). Minimum and maximum are short branches, which the
 * processor predicts, or, where that code would be too large, calls of Math.min/max.
 *
 * <p>The code is defined as a hidden class of this package (unloaded with its last instance). A block
 * whose code would exceed what the JIT compiles ({@value #MAX_CODE} bytes of bytecode) gets none.
 */
interface MinMaxKernel {
    /** The JIT leaves larger methods to the interpreter (HotSpot's HugeMethodLimit is 8000). */
    int MAX_CODE = 7900;

    /**
     * Reads the input values and the degrees of the terms that are not unimodal, writes every accumulator and
     * stores each CoGS output that it computes and that fits its type; returns the number of outputs left
     * to {@link CompiledEvaluator} (the other outputs, and a CoGS of nothing fired or out of range).
     */
    int run(double[] values, double[] deg, double[] acc);

    /**
     * A MIN/MAX block as {@link CompiledEvaluator} compiled it. Rule r's operands are
     * {@code operand[ruleStart[r]..ruleEnd[r])} (term indices, then {@code terms.count + k} for 1 − μ of term
     * {@code negated[k]}); its subconclusions {@code conclusionStart[r]..conclusionStart[r + 1])} raise
     * accumulator {@code target[c]} to {@code weight[c]} times its degree. For each output o whose CoGS the
     * kernel computes, {@code cogsSlot[o]} is its variable's slot (else -1), {@code cogsFrom[o]} to
     * {@code cogsTo[o]} its accumulators, whose singleton values are {@code singleton[k]}, and {@code min[o]},
     * {@code max[o]} the range of its (real) type.
     */
    record Block(TermDegrees terms, int[] negated, int[] ruleStart, int[] ruleEnd, int[] operand,
            int[] conclusionStart, int[] target, double[] weight, int accumulators, int[] cogsSlot, int[] cogsFrom,
            int[] cogsTo, double[] singleton, double[] min, double[] max) {
    }

    /**
     * Generates the kernel, or returns null when its code would be too large or the JVM refuses it: the array
     * loops then go on computing the same values (a refusal is a bug of this class, which MinMaxKernelTest, by
     * asserting that every random program gets its code, is there to catch; a user's evaluation must not fail
     * on it).
     */
    static MinMaxKernel generate(Block b) {
        for (boolean compact : new boolean[] {false, true}) {
            byte[] bytes = code(compact, b);
            if (bytes != null) {
                try {
                    Class<?> k = MethodHandles.lookup().defineHiddenClass(bytes, true).lookupClass();
                    return (MinMaxKernel) k.getDeclaredConstructor().newInstance();
                } catch (ReflectiveOperationException | LinkageError e) {
                    return null;
                }
            }
        }
        return null;
    }

    /** The class file of the kernel, or null when its method would exceed {@link #MAX_CODE} bytes. */
    private static byte[] code(boolean compact, Block b) {
        TermDegrees terms = b.terms();
        int[] negated = b.negated();
        int[] operand = b.operand();
        int[] ruleStart = b.ruleStart();
        int[] ruleEnd = b.ruleEnd();
        int accumulators = b.accumulators();
        int[] cogsSlot = b.cogsSlot();
        ClassFile cf = new ClassFile();
        ClassFile.Code c = cf.code;
        c.compact = compact;
        int termCount = terms.count;
        int[] local = new int[termCount + negated.length];
        int flag = 4;                                   // after this, values, deg, acc: the int result
        int next = 5;
        for (int i = 0; i < local.length; i++) {
            local[i] = next;
            next += 2;
        }
        int accLocal = next;
        next += 2 * accumulators;
        int zero = next;
        int one = next + 2;
        int minLocal = next + 4;
        int tmp = next + 6;                             // and tmp + 2
        int numLocal = next + 10;
        int left = 0;
        for (int slot : cogsSlot) {
            left += slot < 0 ? 1 : 0;
        }
        c.intConst(left);
        c.op(ClassFile.ISTORE);
        c.op(flag);
        c.op(ClassFile.DCONST_0);
        c.local(ClassFile.DSTORE, zero);
        c.op(ClassFile.DCONST_1);
        c.local(ClassFile.DSTORE, one);

        // degrees: unclamped quotients for the unimodal terms (min and max commute with the clamp, see below)
        terms.emitUnimodal(c, local, tmp);
        boolean[] unimodal = terms.unimodal();
        for (int t = 0; t < termCount; t++) {
            if (!unimodal[t]) {
                c.op(0x2c);                             // aload_2: deg (clamped already)
                c.intConst(t);
                c.op(ClassFile.DALOAD);
                c.local(ClassFile.DSTORE, local[t]);
            }
        }
        for (int k = 0; k < negated.length; k++) {
            // 1 − μ needs μ itself: max(0, min(1, q))
            c.pick(local[negated[k]], one, true);
            c.local(ClassFile.DSTORE, tmp);
            c.pick(zero, tmp, false);
            c.local(ClassFile.DSTORE, tmp);
            c.op(ClassFile.DCONST_1);
            c.local(ClassFile.DLOAD, tmp);
            c.op(ClassFile.DSUB);
            c.local(ClassFile.DSTORE, local[termCount + k]);
        }
        for (int i = 0; i < accumulators; i++) {
            c.op(ClassFile.DCONST_0);
            c.local(ClassFile.DSTORE, accLocal + 2 * i);
        }
        // each rule: m = min(1, q1, …, qn), then acc = max(acc, w·m). Clamping each q to [0, 1] first gives
        // the same m where m >= 0 (min commutes with the clamp); where m < 0 the clamped m is 0, and
        // max(acc, w·0) = acc = max(acc, w·m) because acc >= 0 and w >= 0. So the results are the array
        // loops' to the bit, with two comparisons per rule fewer on the critical path.
        boolean[] atMostOne = java.util.Arrays.copyOf(terms.atMostOne(), local.length);
        java.util.Arrays.fill(atMostOne, termCount, local.length, true);   // 1 − μ
        for (int r = 0; r < ruleStart.length; r++) {
            c.local(ClassFile.DLOAD, local[operand[ruleStart[r]]]);
            c.local(ClassFile.DSTORE, minLocal);
            boolean bounded = atMostOne[operand[ruleStart[r]]];
            for (int k = ruleStart[r] + 1; k < ruleEnd[r]; k++) {
                c.pick(minLocal, local[operand[k]], true);
                c.local(ClassFile.DSTORE, minLocal);
                bounded |= atMostOne[operand[k]];
            }
            if (!bounded) {                             // the min of the q is at most 1 when one of them is
                c.pick(minLocal, one, true);
                c.local(ClassFile.DSTORE, minLocal);
            }
            for (int s = b.conclusionStart()[r]; s < b.conclusionStart()[r + 1]; s++) {
                int a = accLocal + 2 * b.target()[s];
                int value = minLocal;
                if (b.weight()[s] != 1.0) {             // 1.0 · m is m exactly
                    c.doubleConst(b.weight()[s]);
                    c.local(ClassFile.DLOAD, minLocal);
                    c.op(ClassFile.DMUL);
                    c.local(ClassFile.DSTORE, tmp);
                    value = tmp;
                }
                c.raise(a, value);
            }
            if (c.size() > MAX_CODE) {
                return null;
            }
        }
        for (int i = 0; i < accumulators; i++) {
            c.op(0x2d);                                 // aload_3: acc
            c.intConst(i);
            c.local(ClassFile.DLOAD, accLocal + 2 * i);
            c.op(ClassFile.DASTORE);
        }
        for (int o = 0; o < cogsSlot.length; o++) {
            if (cogsSlot[o] < 0) {
                continue;
            }
            // num = Σ v·μ, den = Σ μ, summed in accumulator order from 0 as CompiledEvaluator.defuzzify does, with
            // two exact shortcuts: μ >= +0, so 0 + μ is μ and the sum of the μ needs no 0 to start from; and
            // v·μ is +0 or positive for v > 0, so with such a v among the terms the sum of the v·μ cannot end
            // as −0, which is all that starting from 0 changes, and a term with v = 0 adds an exact +0
            boolean positive = false;
            for (int k = b.cogsFrom()[o]; k < b.cogsTo()[o]; k++) {
                positive |= b.singleton()[k] > 0;
            }
            boolean numStarted = !positive;
            if (!positive) {
                c.op(ClassFile.DCONST_0);
                c.local(ClassFile.DSTORE, numLocal);
            }
            for (int k = b.cogsFrom()[o]; k < b.cogsTo()[o]; k++) {
                if (b.singleton()[k] != 0 || !positive) {
                    if (numStarted) {
                        c.local(ClassFile.DLOAD, numLocal);
                    }
                    c.doubleConst(b.singleton()[k]);
                    c.local(ClassFile.DLOAD, accLocal + 2 * k);
                    c.op(ClassFile.DMUL);
                    if (numStarted) {
                        c.op(ClassFile.DADD);
                    }
                    c.local(ClassFile.DSTORE, numLocal);
                    numStarted = true;
                }
                c.local(ClassFile.DLOAD, accLocal + 2 * k);
                if (k > b.cogsFrom()[o]) {
                    c.local(ClassFile.DLOAD, minLocal);
                    c.op(ClassFile.DADD);
                }
                c.local(ClassFile.DSTORE, minLocal);    // the denominator
            }
            c.local(ClassFile.DLOAD, numLocal);
            c.local(ClassFile.DLOAD, minLocal);
            c.op(ClassFile.DDIV);
            c.local(ClassFile.DSTORE, tmp);
            // 0/0 (nothing fired) is NaN and fails the range test like a value out of range: left to Java
            c.storeWithin(tmp, b.min()[o], b.max()[o], cogsSlot[o], flag);
        }
        c.op(ClassFile.ILOAD);
        c.op(flag);
        c.op(ClassFile.IRETURN);
        if (c.size() > MAX_CODE) {
            return null;
        }
        String pkg = MinMaxKernel.class.getPackageName().replace('.', '/');
        return cf.toBytes(pkg + "/MinMaxKernel$Generated" + Counter.NEXT.incrementAndGet(), pkg + "/MinMaxKernel",
                "run", "([D[D[D)I", 5);
    }

    /** Distinct names for the generated classes. */
    final class Counter {
        static final AtomicLong NEXT = new AtomicLong();

        private Counter() {
        }
    }
}
