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
        for (BlockPlan b : blocks) {
            if (Names.same(b.name, blockName)) {
                return new FunctionBlockInstance(b);
            }
        }
        throw new EvaluationException(EvaluationCode.UNKNOWN_NAME,
                "no function block named '" + blockName + "' (the program has " + functionBlockNames() + ")");
    }
}
