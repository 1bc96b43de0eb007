package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;

/**
 * The rules of a block as the rule-per-weight libraries (fuzzylite, jFuzzyLogic) write them: the condition
 * cleaned of what they cannot say, bare-variable subconclusions left out (lost), and one line per weight group.
 * When some rule of the block is split, the block's rules are numbered 1, 2, … (rule names carry no meaning).
 */
final class RuleLines {
    private RuleLines() {
    }

    record Line(String name, Rule rule, Condition condition, BlockContext.WeightGroup group) {
    }

    static List<Line> of(BlockContext cx, RuleBlock rb, boolean hedges) {
        List<Line> lines = new ArrayList<>();
        boolean split = false;
        for (Rule r : rb.rules()) {
            Optional<Condition> condition = LibraryConditions.clean(r.condition(), hedges, cx, r.name());
            List<Subconclusion> parts = new ArrayList<>();
            for (Subconclusion s : r.conclusion()) {
                if (s.bareVariable()) {
                    cx.findings.lost(s.location(), WriterCode.BARE_VARIABLE, "rule " + r.name() + " concludes the"
                            + " variable '" + s.variable() + "' itself (Table 9); " + cx.findings.library()
                            + " concludes only 'variable IS term': the subconclusion is left out");
                } else {
                    parts.add(s);
                }
            }
            if (condition.isEmpty() || parts.isEmpty()) {
                cx.findings.lost(r.location(), WriterCode.RULE_FORM, "rule " + r.name() + " is left out: nothing of its "
                        + (condition.isEmpty() ? "condition" : "conclusion") + " is left that " + cx.findings.library()
                        + " can say");
                continue;
            }
            Rule kept = new Rule(r.name(), r.condition(), parts, r.location());
            List<BlockContext.WeightGroup> groups = cx.weightGroups(kept);
            split |= groups.size() > 1;
            for (BlockContext.WeightGroup g : groups) {
                lines.add(new Line(r.name(), r, condition.get(), g));
            }
        }
        if (split) {
            List<Line> numbered = new ArrayList<>();
            for (int i = 0; i < lines.size(); i++) {
                Line l = lines.get(i);
                numbered.add(new Line(Integer.toString(i + 1), l.rule(), l.condition(), l.group()));
            }
            return numbered;
        }
        return lines;
    }

    /**
     * Both libraries multiply a rule's degree by its weight before activation (T(w·d, μ)) where the standard
     * weighs the activated set (w·T(d, μ)); the two agree for ACT PROD only. The text is the same, the result
     * differs, so the writer names it.
     */
    static void noteWeightBeforeActivation(BlockContext cx, ActivationMethod act, Line line, Subconclusion s,
            String library) {
        if (act != ActivationMethod.PROD && line.group().value() != 1 && cx.pointTerms(s.variable())
                && !cx.tsukamoto(s.variable())) {
            String t = act.name();
            cx.findings.differs(s.location(), WriterCode.WEIGHT_BEFORE_ACTIVATION, library + " multiplies the"
                    + " degree of rule " + line.rule().name() + " by its weight before ACT " + t + " (" + t
                    + "(w·d, μ)); fclcert weighs the activated set (w·" + t + "(d, μ), semantics.md point 3)");
        }
    }
}
