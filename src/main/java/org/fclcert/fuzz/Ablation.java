package org.fclcert.fuzz;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;

/**
 * A program with one feature switched to its Basic Level counterpart (NSUM to MAX, PROD activation to none,
 * no weights, ...), to tell whether a new disagreement is one already found: if it disappears when the
 * feature of a known finding is switched off, it is that finding again and need not be shrunk.
 */
final class Ablation {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;

    private Ablation() {
    }

    static Optional<Program> without(Program p, Feature f) {
        FunctionBlock fb = p.functionBlocks().get(0);
        FunctionBlock out = switch (f) {
            case E_ACCU_NSUM, E_ACCU_BSUM -> blocks(fb, rb -> new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(),
                    Optional.of(new Located<>(AccumulationMethod.MAX, AT)), rb.rules(), rb.location()));
            case E_ACT_PROD, E_ACT_MIN -> blocks(fb, rb -> new RuleBlock(rb.name(), rb.and(), rb.or(), Optional.empty(),
                    rb.accumulation(), rb.rules(), rb.location()));
            case E_AND_PROD, E_AND_BDIF, E_OR_ASUM, E_OR_BSUM -> blocks(fb, rb -> new RuleBlock(rb.name(),
                    Optional.of(new Located<>(AndAlgorithm.MIN, AT)), rb.or().map(o -> new Located<>(OrAlgorithm.MAX, AT)),
                    rb.activation(), rb.accumulation(), rb.rules(), rb.location()));
            case E_WITH_CONST, E_WITH_VAR -> blocks(fb, rb -> new RuleBlock(rb.name(), rb.and(), rb.or(), rb.activation(),
                    rb.accumulation(), rb.rules().stream().map(r -> new Rule(r.name(), r.condition(), r.conclusion().stream()
                            .map(s -> new Subconclusion(s.variable(), s.term(), Optional.empty(), s.location())).toList(),
                            r.location())).toList(), rb.location()));
            case B_DEFAULT_NC -> new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications().stream()
                    .map(d -> d.defaultValue().orElse(null) instanceof DefaultValue.NoChange
                            ? new Defuzzification(d.variable(), d.range(), d.terms(), d.method(),
                                    Optional.of(new DefaultValue.Constant(Literal.of(0), AT)), d.location()) : d).toList(),
                    fb.ruleBlocks(), fb.options(), fb.location());
            default -> null;
        };
        return out == null ? Optional.empty() : Optional.of(new Program(p.sourceName(), List.of(out)));
    }

    private static FunctionBlock blocks(FunctionBlock fb, java.util.function.UnaryOperator<RuleBlock> f) {
        return new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), fb.defuzzifications(),
                fb.ruleBlocks().stream().map(f).toList(), fb.options(), fb.location());
    }
}
