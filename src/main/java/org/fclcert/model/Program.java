package org.fclcert.model;

import java.util.List;
import java.util.Optional;

/**
 * A whole FCL source text: one or more function blocks (5.4 {@code function_block_declaration}).
 *
 * @param dialectFeatures the non-standard constructs a dialect reader accepted (Open Level features,
 *                        each where it was written); always empty for a program the strict reader read.
 *                        Like locations they describe how the text was written, so they take no part
 *                        in {@link #equals}: a dialect program and its standard conversion compare by meaning.
 * @param comments        the text's comments in source order, each with the line it belongs to ({@link Comment});
 *                        like locations they take no part in {@link #equals}
 */
public record Program(String sourceName, List<FunctionBlock> functionBlocks, List<FeatureUse> dialectFeatures,
        List<Comment> comments) {
    public Program {
        functionBlocks = List.copyOf(functionBlocks);
        dialectFeatures = List.copyOf(dialectFeatures);
        comments = List.copyOf(comments);
    }

    /** A program without comments. */
    public Program(String sourceName, List<FunctionBlock> functionBlocks, List<FeatureUse> dialectFeatures) {
        this(sourceName, functionBlocks, dialectFeatures, List.of());
    }

    /** This program with these comments instead of its own. */
    public Program withComments(List<Comment> comments) {
        return new Program(sourceName, functionBlocks, dialectFeatures, comments);
    }

    /** A program read as standard FCL: no dialect features. */
    public Program(String sourceName, List<FunctionBlock> functionBlocks) {
        this(sourceName, functionBlocks, List.of());
    }

    /** The function block of that name (case-insensitive). */
    public Optional<FunctionBlock> functionBlock(String name) {
        return functionBlocks.stream().filter(fb -> Names.same(fb.name(), name)).findFirst();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Program p && sourceName.equals(p.sourceName) && functionBlocks.equals(p.functionBlocks);
    }

    @Override
    public int hashCode() {
        return sourceName.hashCode() * 31 + functionBlocks.hashCode();
    }
}
