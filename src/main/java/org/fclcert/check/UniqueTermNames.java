package org.fclcert.check;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Term;

/** FCL-C005: the terms of one linguistic variable have distinct names; case does not count (5.2.2). */
public final class UniqueTermNames implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C005", "5.2.2",
            "each term name is defined once in a FUZZIFY or DEFUZZIFY block, ignoring case");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        block.fuzzifications().forEach(f -> check("FUZZIFY " + f.variable(), f.terms(), sink));
        block.defuzzifications().forEach(d -> check("DEFUZZIFY " + d.variable(), d.terms(), sink));
    }

    private void check(String owner, List<Term> terms, DiagnosticSink sink) {
        Map<String, Term> seen = new HashMap<>();
        for (Term t : terms) {
            Term first = seen.putIfAbsent(Names.key(t.name()), t);
            if (first != null) {
                sink.report(finding(t.location(), "term '" + t.name() + "' is defined twice in " + owner
                        + " (first as '" + first.name() + "' at line " + first.location().line()
                        + "; names are not case-sensitive); rename or remove one"));
            }
        }
    }
}
