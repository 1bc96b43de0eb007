package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.harness.fakes.EvaluatorIut;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;

/**
 * Implementations wrong in one way each, besides those of {@code harness.fakes.Fakes}: the correct evaluator
 * with the program rewritten as the defective implementation would read it.
 */
final class SingleDefects {
    private SingleDefects() {
    }

    /** ACT PROD evaluated as MIN. */
    public static final class ProdActivationAsMin extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return map(p, fb -> new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(),
                    fb.ruleBlocks().stream().map(rb -> rb.activation().filter(a -> a.value() == ActivationMethod.PROD).isEmpty() ? rb
                            : new RuleBlock(rb.name(), rb.and(), rb.or(), Optional.of(new Located<>(ActivationMethod.MIN, rb.location())),
                                    rb.accumulation(), rb.rules(), rb.location())).toList(), fb.options(), fb.location()));
        }
    }

    /** LM computed as RM and RM as LM. */
    public static final class LeftRightSwapped extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return map(p, fb -> new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications().stream()
                    .map(d -> d.method().filter(m -> m.value() == DefuzzificationMethod.LM || m.value() == DefuzzificationMethod.RM)
                            .map(m -> new Defuzzification(d.variable(), d.range(), d.terms(), Optional.of(new Located<>(
                                    m.value() == DefuzzificationMethod.LM ? DefuzzificationMethod.RM : DefuzzificationMethod.LM,
                                    m.location())), d.defaultValue(), d.location())).orElse(d)).toList(),
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }
    }

    /** A term's degree is 0 beyond its outer points, instead of the outer point's degree (5.2.2). */
    public static final class ZeroOutsideThePoints extends EvaluatorIut {
        @Override
        protected Program transform(Program p) {
            return map(p, fb -> new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications().stream()
                    .map(f -> new Fuzzification(f.variable(), f.terms().stream().map(ZeroOutsideThePoints::closed).toList(),
                            f.location())).toList(),
                    fb.defuzzifications().stream().map(d -> new Defuzzification(d.variable(), d.range(),
                            d.terms().stream().map(ZeroOutsideThePoints::closed).toList(), d.method(), d.defaultValue(),
                            d.location())).toList(),
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }

        /** The term with a drop to 0 at its outer points (a vertical edge keeps the degree at the point itself). */
        private static Term closed(Term t) {
            if (!(t.function() instanceof MembershipFunction.Points pts) || pts.points().isEmpty()) {
                return t;
            }
            List<Point> points = new ArrayList<>(pts.points());
            Point first = points.get(0);
            Point last = points.get(points.size() - 1);
            if (!(first.degree() instanceof Literal d0 && d0.value() == 0)) {
                points.add(0, new Point(first.x(), Literal.of(0), first.location()));
            }
            if (!(last.degree() instanceof Literal dn && dn.value() == 0)) {
                points.add(new Point(last.x(), Literal.of(0), last.location()));
            }
            return new Term(t.name(), new MembershipFunction.Points(points), t.location());
        }
    }

    private static Program map(Program p, java.util.function.UnaryOperator<FunctionBlock> f) {
        return new Program(p.sourceName(), p.functionBlocks().stream().map(f).toList());
    }
}
