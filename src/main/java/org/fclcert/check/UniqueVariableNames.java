package org.fclcert.check;

import java.util.HashMap;
import java.util.Map;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Variable;

/** FCL-C004: no two variables of a function block share a name; case does not count (5.2.1). */
public final class UniqueVariableNames implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C004", "5.2.1",
            "each variable name is declared once per function block, ignoring case");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Map<String, Variable> seen = new HashMap<>();
        for (Variable v : block.variables()) {
            Variable first = seen.putIfAbsent(Names.key(v.name()), v);
            if (first != null) {
                sink.report(finding(v.location(), "variable '" + v.name() + "' is declared again in function block '"
                        + block.name() + "': " + Describe.variable(first) + " was declared at line "
                        + first.location().line() + " (names are not case-sensitive); rename or remove one"));
            }
        }
    }
}
