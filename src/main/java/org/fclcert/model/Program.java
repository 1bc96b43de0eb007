package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/** A whole FCL source text: one or more function blocks (5.4 {@code function_block_declaration}). */
public record Program(String sourceName, List<FunctionBlock> functionBlocks) {
    public Program {
        functionBlocks = List.copyOf(functionBlocks);
    }

    /** The function block of that name (case-insensitive). */
    public Optional<FunctionBlock> functionBlock(String name) {
        return functionBlocks.stream().filter(fb -> Names.same(fb.name(), name)).findFirst();
    }
}
