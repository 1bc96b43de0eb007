package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;

/** A check whose scope is one function block: names, terms and rules never cross block boundaries. */
public interface FunctionBlockRule extends CheckRule {
    void check(FunctionBlock block, DiagnosticSink sink);

    @Override
    default void check(Program program, DiagnosticSink sink) {
        for (FunctionBlock block : program.functionBlocks()) {
            check(block, sink);
        }
    }
}
