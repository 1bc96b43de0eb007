package org.fclcert.check;

import java.util.HashMap;
import java.util.Map;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Program;

/**
 * FCL-C032: each function block of a program has a unique name; case does not count (IEC 61131-3
 * B.1.1), so {@code Fuzzy_FB} and {@code FUZZY_FB} are one name and a caller asking for it could not
 * say which block it means.
 */
public final class UniqueFunctionBlockNames implements CheckRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C032", "5.1 (IEC 61131-3 B.1.1)",
            "each function block name is used once per program, ignoring case");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(Program program, DiagnosticSink sink) {
        Map<String, FunctionBlock> seen = new HashMap<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            FunctionBlock first = seen.putIfAbsent(Names.key(fb.name()), fb);
            if (first != null) {
                sink.report(finding(fb.location(), "function block '" + fb.name()
                        + "' has the same name as the function block '" + first.name() + "' at line "
                        + first.location().line() + " (names are not case-sensitive);"
                        + " each function block needs a unique name"));
            }
        }
    }
}
