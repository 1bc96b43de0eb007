package org.fclcert.check;

import java.util.HashMap;
import java.util.Map;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.SourceLocation;

/**
 * FCL-C028: a variable has at most one FUZZIFY block and at most one DEFUZZIFY block: two blocks
 * for one linguistic variable would leave its terms ambiguous (5.2.2, 5.2.3).
 */
public final class OneFuzzificationPerVariable implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C028", "5.2.2, 5.2.3",
            "no variable has a second FUZZIFY block or a second DEFUZZIFY block");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Map<String, SourceLocation> fuzzified = new HashMap<>();
        block.fuzzifications().forEach(f -> once("FUZZIFY", f.variable(), f.location(), fuzzified, sink));
        Map<String, SourceLocation> defuzzified = new HashMap<>();
        block.defuzzifications().forEach(d -> once("DEFUZZIFY", d.variable(), d.location(), defuzzified, sink));
    }

    private void once(String keyword, String variable, SourceLocation at, Map<String, SourceLocation> seen,
            DiagnosticSink sink) {
        SourceLocation first = seen.putIfAbsent(Names.key(variable), at);
        if (first != null) {
            sink.report(finding(at, keyword + " " + variable + ": '" + variable + "' already has a " + keyword
                    + " block at line " + first.line() + "; put all its terms in one block"));
        }
    }
}
