package org.fclcert.check;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * Hand-built models, for what no text can reasonably carry (conditions nested 100 000 deep) and so
 * that the rules can be tested without a reader. Locations are given as line numbers in a pretend
 * file {@code m.fcl}.
 */
final class ModelFixtures {
    private ModelFixtures() {
    }

    static SourceLocation at(int line, int column) {
        return SourceLocation.of("m.fcl", line, column);
    }

    static Literal num(double v, int line, int column) {
        return new Literal(v, v == Math.rint(v), at(line, column));
    }

    static Term points(String name, int line, double... xy) {
        List<Point> pts = new java.util.ArrayList<>();
        for (int i = 0; i < xy.length; i += 2) {
            pts.add(new Point(num(xy[i], line, 20 + i), num(xy[i + 1], line, 21 + i), at(line, 20 + i)));
        }
        return new Term(name, new MembershipFunction.Points(pts), at(line, 5));
    }

    static Term singleton(String name, double value, int line) {
        return new Term(name, new MembershipFunction.Singleton(num(value, line, 20)), at(line, 5));
    }

    static Condition.TermSubcondition is(String variable, String term, int line) {
        return new Condition.TermSubcondition(variable, term, false, at(line, 17));
    }

    /** The temp/valve program (5.3 reduced to one input), with the given rules in its one rule block. */
    static Program tempValve(List<Rule> rules) {
        List<Variable> variables = List.of(
                new Variable("temp", VariableKind.INPUT, DataType.REAL, Optional.empty(), at(3, 5)),
                new Variable("valve", VariableKind.OUTPUT, DataType.REAL, Optional.empty(), at(6, 5)));
        Fuzzification temp = new Fuzzification("temp",
                List.of(points("cold", 9, 3, 1, 27, 0), points("hot", 10, 3, 0, 27, 1)), at(8, 1));
        Defuzzification valve = new Defuzzification("valve", Optional.empty(),
                List.of(singleton("closed", 0, 13), singleton("open", 100, 14)),
                Optional.of(new Located<>(DefuzzificationMethod.COGS, at(15, 5))),
                Optional.of(new DefaultValue.Constant(num(0, 16, 16), at(16, 5))), at(12, 1));
        RuleBlock block = new RuleBlock("r", Optional.of(new Located<>(AndAlgorithm.MIN, at(19, 5))), Optional.empty(),
                Optional.empty(), Optional.of(new Located<>(AccumulationMethod.MAX, at(20, 5))), rules, at(18, 1));
        FunctionBlock fb = new FunctionBlock("t", variables, List.of(temp), List.of(valve), List.of(block), List.of(),
                at(1, 1));
        return new Program("m.fcl", List.of(fb));
    }

    static Rule rule(String name, Condition condition, String output, String term, int line) {
        return new Rule(name, condition, List.of(new Subconclusion(output, Optional.of(term), Optional.empty(),
                at(line, 40))), at(line, 5));
    }

    /** The two rules that use every term of {@link #tempValve}: a program with no findings. */
    static List<Rule> validRules() {
        return List.of(rule("1", is("temp", "cold", 21), "valve", "open", 21),
                rule("2", is("temp", "hot", 22), "valve", "closed", 22));
    }

    /** {@code temp IS hot} inside {@code depth} parentheses, each opening one column further right. */
    static Condition nested(int depth, int line) {
        Condition c = new Condition.TermSubcondition("temp", "hot", false, at(line, 17 + depth));
        for (int d = depth; d >= 1; d--) {
            c = new Condition.Parenthesized(c, at(line, 16 + d));
        }
        return c;
    }
}
