package org.fclcert.corpus;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Point;
import org.fclcert.model.Range;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * The width of each output's scale, which the {@link Tolerance#CONTINUOUS} class takes a fraction of:
 * <ol>
 *   <li>the width max - min of the output's RANGE, when it has one;</li>
 *   <li>otherwise the span from the smallest to the largest constant abscissa among its point terms (the
 *       part of the axis where the accumulated set can be non-zero: a bounded output without RANGE must
 *       be zero at its outer ends, FCL-C025);</li>
 *   <li>no width at all for an output with singleton terms only, with no DEFUZZIFY block (a bare variable
 *       conclusion), or whose span is zero: such outputs are compared exactly.</li>
 * </ol>
 */
public final class OutputScales {
    private final Map<String, Double> widths;

    private OutputScales(Map<String, Double> widths) {
        this.widths = Map.copyOf(widths);
    }

    /** No widths: every output compared exactly. */
    public static OutputScales none() {
        return new OutputScales(Map.of());
    }

    /** The widths of the VAR_OUTPUT variables of one function block. */
    public static OutputScales of(FunctionBlock block) {
        Map<String, Double> widths = new HashMap<>();
        for (Variable v : block.variables(VariableKind.OUTPUT)) {
            block.defuzzification(v.name())
                    .flatMap(OutputScales::widthOf)
                    .ifPresent(w -> widths.put(Names.key(v.name()), w));
        }
        return new OutputScales(widths);
    }

    /** The width for an output (case-insensitive name); empty when it must be compared exactly. */
    public OptionalDouble width(String output) {
        Double w = widths.get(Names.key(output));
        return w == null ? OptionalDouble.empty() : OptionalDouble.of(w);
    }

    private static Optional<Double> widthOf(Defuzzification d) {
        if (d.range().isPresent()) {
            Range r = d.range().get();
            double w = r.max().value() - r.min().value();
            return w > 0 ? Optional.of(w) : Optional.empty();
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Term t : d.terms()) {
            if (t.function() instanceof MembershipFunction.Points p) {
                for (Point pt : p.points()) {
                    if (pt.x() instanceof Literal l) {
                        lo = Math.min(lo, l.value());
                        hi = Math.max(hi, l.value());
                    }
                }
            }
        }
        return hi > lo ? Optional.of(hi - lo) : Optional.empty();
    }
}
