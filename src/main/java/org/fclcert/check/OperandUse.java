package org.fclcert.check;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
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
 * worded only when asked, as most operands never appear in a message.
 */
record OperandUse(Operand operand, Role role, Supplier<String> place) {
    String where() {
        return place.get();
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
                    s.weight().ifPresent(w -> out.add(new OperandUse(w, Role.WEIGHT,
                            () -> "the weighting factor of '" + Describe.subconclusion(s) + "' in rule " + rule.name()
                                    + " of rule block '" + rb.name() + "'")));
                }
            }
        }
        return out;
    }

    private static void addTerm(List<OperandUse> out, Term term, String variable) {
        if (term.function() instanceof MembershipFunction.Singleton s) {
            out.add(new OperandUse(s.value(), Role.SINGLETON, () -> "the value of singleton " + of(term, variable)));
            return;
        }
        if (!(term.function() instanceof MembershipFunction.Points pts)) {
            return;   // a named shape has literal parameters only
        }
        List<Point> points = pts.points();
        for (int i = 0; i < points.size(); i++) {
            Point p = points.get(i);
            int number = i + 1;
            out.add(new OperandUse(p.x(), Role.POINT_X, () -> "the x of point " + number + " of " + of(term, variable)));
            out.add(new OperandUse(p.degree(), Role.DEGREE,
                    () -> "the degree of point " + number + " of " + of(term, variable)));
        }
    }

    /** Built only when a diagnostic needs it: most operands are fine. */
    private static String of(Term term, String variable) {
        return "term '" + term.name() + "' of '" + variable + "'";
    }
}
