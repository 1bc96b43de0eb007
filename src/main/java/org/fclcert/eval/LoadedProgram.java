package org.fclcert.eval;

import java.util.List;
import org.fclcert.model.Names;

/** A compiled program: immutable and thread-safe; each instance it creates has its own state. */
public final class LoadedProgram {
    private final List<BlockPlan> blocks;

    LoadedProgram(List<BlockPlan> blocks) {
        this.blocks = List.copyOf(blocks);
    }

    /** The function block names, in textual order. */
    public List<String> functionBlockNames() {
        return blocks.stream().map(b -> b.name).toList();
    }

    /** A fresh instance of the first function block. */
    public FunctionBlockInstance newInstance() {
        return new FunctionBlockInstance(blocks.get(0));
    }

    /** A fresh instance of the named function block (case-insensitive). */
    public FunctionBlockInstance newInstance(String blockName) throws EvaluationException {
        return new FunctionBlockInstance(block(blockName));
    }

    /**
     * A fresh instance of the named block (null: the first) that runs the compiled kernel from its first evaluation
     * instead of its {@link FunctionBlockInstance#KERNEL_AFTER}th: for a caller that knows the instance will run long
     * (a controller loop) and for the corpus's second judgement (CorpusMutationTest), which so reaches the kernel with
     * a handful of vectors. The results are those of {@link #newInstance(String)} bit for bit (docs/semantics.md, "The
     * compiled kernel"); a block the kernel does not cover stays interpreted.
     */
    public FunctionBlockInstance newCompiledInstance(String blockName) throws EvaluationException {
        FunctionBlockInstance instance = new FunctionBlockInstance(blockName == null ? blocks.get(0) : block(blockName));
        instance.useKernel();
        return instance;
    }

    /**
     * A fresh instance of the named block (null: the first) in plain double arithmetic, without the exact fallback
     * of the filtered evaluator: one arithmetic an implementation may use, for judging whether a vector is fair
     * ({@link FairVectors}, the fuzzer's screen). Never the reference: its decisions may differ from the exact ones.
     */
    public FunctionBlockInstance newDoubleInstance(String blockName) throws EvaluationException {
        return new FunctionBlockInstance(blockName == null ? blocks.get(0) : block(blockName), false);
    }

    /**
     * The one block of that name (case-insensitive). Two blocks whose names differ only in case
     * (FCL-C032) make the name ambiguous: refused rather than silently taking the first.
     */
    private BlockPlan block(String blockName) throws EvaluationException {
        BlockPlan found = null;
        for (BlockPlan b : blocks) {
            if (Names.same(b.name, blockName)) {
                if (found != null) {
                    throw new EvaluationException(EvaluationCode.UNKNOWN_NAME, "the function block name '" + blockName
                            + "' is ambiguous: the program has both '" + found.name + "' and '" + b.name
                            + "' (names are not case-sensitive)");
                }
                found = b;
            }
        }
        if (found == null) {
            throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                    "no function block named '" + blockName + "' (the program has " + functionBlockNames() + ")");
        }
        return found;
    }

    /** The plan of the named block (null: the first), for FairVectors; null when there is none. */
    BlockPlan plan(String blockName) {
        if (blockName == null) {
            return blocks.get(0);
        }
        try {
            return block(blockName);
        } catch (EvaluationException e) {
            return null;
        }
    }

    /** A fresh exact-path instance of the first function block, numbers read as {@link NumberReading#DECIMAL}. */
    public ExactInstance newExactInstance() {
        return new ExactInstance(blocks.get(0), NumberReading.DECIMAL);
    }

    /**
     * A fresh exact-path instance of the named function block (case-insensitive; null: the first) under the
     * given reading of numbers.
     */
    public ExactInstance newExactInstance(String blockName, NumberReading reading) throws EvaluationException {
        if (blockName == null) {
            return new ExactInstance(blocks.get(0), reading);
        }
        return new ExactInstance(block(blockName), reading);
    }
}
