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

    /** A fresh fast-path instance of the first function block ({@link CompiledEvaluator}). */
    public CompiledEvaluator newCompiledInstance() {
        return new CompiledEvaluator(blocks.get(0));
    }

    /** A fresh fast-path instance of the named function block (case-insensitive). */
    public CompiledEvaluator newCompiledInstance(String blockName) throws EvaluationException {
        return new CompiledEvaluator(block(blockName));
    }

    private BlockPlan block(String blockName) throws EvaluationException {
        for (BlockPlan b : blocks) {
            if (Names.same(b.name, blockName)) {
                return b;
            }
        }
        throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                "no function block named '" + blockName + "' (the program has " + functionBlockNames() + ")");
    }

    /** The plan of the named block (null: the first), for FairVectors; null when there is none. */
    BlockPlan plan(String blockName) {
        if (blockName == null) {
            return blocks.get(0);
        }
        return blocks.stream().filter(b -> Names.same(b.name, blockName)).findFirst().orElse(null);
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
        for (BlockPlan b : blocks) {
            if (Names.same(b.name, blockName)) {
                return new ExactInstance(b, reading);
            }
        }
        throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                "no function block named '" + blockName + "' (the program has " + functionBlockNames() + ")");
    }
}
