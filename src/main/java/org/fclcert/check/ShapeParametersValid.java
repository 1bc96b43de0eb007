package org.fclcert.check;

import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Term;

/**
 * FCL-C041: the parameters of a named shape describe a proper shape: the corners of a triangle,
 * trapezoid, rectangle, S, Z or pi shape in ascending order and not all at one place; a ramp's ends
 * apart; a Gaussian's standard deviations, a bell's width and slope and a cosine's width positive; a
 * sigmoid's slope not zero. Reported at the term, naming the parameters. Shapes with the wrong
 * parameter count are left to FCL-C040.
 */
public final class ShapeParametersValid implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C041", "Open Level (docs/dialects.md)",
            "a named shape's parameters are ordered and positive where its formula needs it");

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
        if (!(t.function() instanceof MembershipFunction.NamedShape s) || s.parameters().size() != s.kind().arity()) {
            return;
        }
        double[] p = s.values();
        String problem = switch (s.kind()) {
            case TRIANGLE -> ascending(p) && p[0] < p[2] ? null : "needs a <= b <= c with a < c";
            case TRAPEZOID -> ascending(p) && p[0] < p[3] ? null : "needs a <= b <= c <= d with a < d";
            case RECTANGLE, S_SHAPE, Z_SHAPE -> p[0] < p[1] ? null : "needs start < end";
            case RAMP -> p[0] != p[1] ? null : "needs start and end apart";
            case GAUSSIAN -> p[1] > 0 ? null : "needs sd > 0";
            case GAUSSIAN_PRODUCT -> p[1] > 0 && p[3] > 0 ? null : "needs sdA > 0 and sdB > 0";
            case BELL -> p[1] > 0 && p[2] > 0 ? null : "needs width > 0 and slope > 0";
            case SIGMOID -> p[1] != 0 ? null : "needs a slope other than 0";
            case SIGMOID_DIFFERENCE, SIGMOID_PRODUCT -> null;
            case COSINE -> p[1] > 0 ? null : "needs width > 0";
            case CONCAVE -> p[0] != p[1] ? null : "needs inflection and end apart";
            case SPIKE -> p[1] > 0 ? null : "needs width > 0";
            case PI_SHAPE -> ascending(p) && p[0] < p[1] && p[2] < p[3] ? null
                    : "needs bottomLeft < topLeft <= topRight < bottomRight";
        };
        if (problem != null) {
            StringBuilder values = new StringBuilder();
            for (int i = 0; i < p.length; i++) {
                values.append(i == 0 ? "" : ", ").append(s.kind().parameterNames().get(i)).append(" = ")
                        .append((p[i] == Math.rint(p[i]) && Math.abs(p[i]) < 1e15 ? String.valueOf((long) p[i]) : String.valueOf(p[i])));
            }
            sink.report(finding(t.location(), "term '" + t.name() + "' of '" + variable + "': a " + s.kind()
                    + " shape " + problem + " (" + values + ")"));
        }
    }

    private static boolean ascending(double[] p) {
        for (int i = 0; i + 1 < p.length; i++) {
            if (p[i] > p[i + 1]) {
                return false;
            }
        }
        return true;
    }
}
