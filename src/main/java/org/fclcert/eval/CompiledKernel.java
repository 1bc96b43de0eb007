package org.fclcert.eval;

/**
 * The compiled kernel of one block: bytecode {@link KernelCompiler} generates for the block's plan, doing what the
 * interpreter ({@link FunctionBlockInstance}) does for the stages it covers, with the same double operations in
 * the same order and the same error bounds, so that its results are the interpreter's bit for bit
 * (docs/semantics.md, "The compiled kernel"). It decides nothing itself: every decision point stays in the
 * instance, which reads the degrees and bounds the kernel wrote (and which redoes the step exactly where a bound
 * cannot settle a decision).
 */
interface CompiledKernel {
    /**
     * Fuzzification and every rule block: each input term's degree and bound into {@code td}/{@code te}, each
     * contribution's degree, weight, bound of w·degree and bound of the degree into {@code cd}, {@code cw},
     * {@code ce}, {@code cde}; the contributions not written as an exact 0 (degree 0, bound 0), in ascending order,
     * into {@code live}. Returns how many those are.
     */
    int front(double[] values, double[] valueRep, double[] td, double[] te, double[] cd, double[] cw, double[] ce,
            double[] cde, int[] live);

    /**
     * Accumulation and defuzzification of an output the kernel compiled ({@link KernelCompiler.Compiled#outputs}):
     * each term's accumulated degree and bound into {@code sd}/{@code se}, the method's bound into
     * {@code scratch[0]} and into {@code scratch[1]} the first decision the bounds could not settle (0 none, 1
     * whether any rule fired, 2 the CoGS bound); returns the value, NaN when nothing fired.
     */
    double output(int index, double[] cd, double[] cw, double[] ce, double[] sd, double[] se, double[] scratch);
}
