package org.fclcert.check;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;

/**
 * A place where a function block takes a constant or a variable: a point's x or degree, a
 * singleton's value, a weighting factor. {@link #where()} names the place for messages; it is
 * worded only when asked, as most operands never appear in a message, from what the use keeps: the term
 * and its variable with the point's number (from 1; 0 for a singleton), or the subconclusion with its rule
 * and rule block.
 */
record OperandUse(Operand operand, Role role, Term term, String variable, int point, Subconclusion subconclusion,
        Rule rule, RuleBlock ruleBlock) {
    String where() {
        return switch (role) {
            case WEIGHT -> "the weighting factor of '" + Describe.subconclusion(subconclusion) + "' in rule "
                    + rule.name() + " of rule block '" + ruleBlock.name() + "'";
            case SINGLETON -> "the value of singleton " + of();
            case POINT_X -> "the x of point " + point + " of " + of();
            case DEGREE -> "the degree of point " + point + " of " + of();
        };
    }

    private String of() {
        return "term '" + term.name() + "' of '" + variable + "'";
    }

    enum Role {
        POINT_X("the x of a point"),
        DEGREE("a membership degree"),
        SINGLETON("a singleton value"),
        WEIGHT("a weighting factor");

        private final String words;

        Role(String words) {
            this.words = words;
        }

        String words() {
            return words;
        }
    }

    /** Every operand of the function block, terms first (in block order), then weighting factors. */
    static List<OperandUse> all(FunctionBlock block) {
        List<OperandUse> out = new ArrayList<>();
        block.fuzzifications().forEach(f -> f.terms().forEach(t -> addTerm(out, t, f.variable())));
        block.defuzzifications().forEach(d -> d.terms().forEach(t -> addTerm(out, t, d.variable())));
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Subconclusion s : rule.conclusion()) {
                    if (s.weight().isPresent()) {
                        out.add(new OperandUse(s.weight().get(), Role.WEIGHT, null, null, 0, s, rule, rb));
                    }
                }
            }
        }
        return out;
    }

    private static void addTerm(List<OperandUse> out, Term term, String variable) {
        if (term.function() instanceof MembershipFunction.Singleton s) {
            out.add(new OperandUse(s.value(), Role.SINGLETON, term, variable, 0, null, null, null));
            return;
        }
        if (!(term.function() instanceof MembershipFunction.Points pts)) {
            return;   // a named shape has literal parameters only
        }
        List<Point> points = pts.points();
        for (int i = 0; i < points.size(); i++) {
            Point p = points.get(i);
            out.add(new OperandUse(p.x(), Role.POINT_X, term, variable, i + 1, null, null, null));
            out.add(new OperandUse(p.degree(), Role.DEGREE, term, variable, i + 1, null, null, null));
        }
    }
}
