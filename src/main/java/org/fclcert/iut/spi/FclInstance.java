package org.fclcert.iut.spi;

/**
 * One instance of a function block, with its own state (NC outputs keep their last value). Names are
 * the variable names of the program, in any letter case.
 */
public interface FclInstance {

    /** Sets an input variable. Throw (any runtime exception, with a clear message) to refuse the value. */
    void set(String name, double value);

    /** Runs the fuzzy inference once on the inputs set so far. */
    void evaluate();

    /** The value of an output variable after the last {@link #evaluate()}. */
    double get(String name);

    /** Back to the initial state, as if newly created (see {@link FclProgram#newInstance}). */
    void reset();
}
