package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Term;

/**
 * FCL-C040: a named shape (jFuzzyLogic, fuzzylite; Open Level) has exactly the parameters its formula
 * takes ({@link org.fclcert.model.ShapeKind#parameterNames()}), e.g. three for a triangle.
 */
public final class ShapeParameterCount implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C040", "Open Level (docs/dialects.md)",
            "a named shape has exactly the number of parameters its formula takes");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        block.fuzzifications().forEach(f -> f.terms().forEach(t -> check(t, f.variable(), sink)));
        block.defuzzifications().forEach(d -> d.terms().forEach(t -> check(t, d.variable(), sink)));
    }

    private void check(Term t, String variable, DiagnosticSink sink) {
        if (t.function() instanceof MembershipFunction.NamedShape s && s.parameters().size() != s.kind().arity()) {
            sink.report(finding(t.location(), "term '" + t.name() + "' of '" + variable + "': a " + s.kind()
                    + " shape takes " + s.kind().arity() + " parameters (" + String.join(", ", s.kind().parameterNames())
                    + "), not " + s.parameters().size()));
        }
    }
}
