package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.Hedge;
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
                } else if (!hedges && !s.hedges().isEmpty()) {
                    cx.findings.lost(s.location(), WriterCode.HEDGE, "rule " + r.name() + ": " + cx.findings.library()
                            + " has no hedges in a conclusion (" + s.hedges().stream().map(Hedge::word).toList()
                            + " on '" + s.variable() + "'): the hedges are left out");
                    parts.add(new Subconclusion(s.variable(), s.term(), s.weight(), s.location()));
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
                List<BlockContext.WeightGroup> chains = hedgeChains(g);
                split |= chains.size() > 1;
                for (BlockContext.WeightGroup c : chains) {
                    lines.add(new Line(r.name(), r, condition.get(), c));
                }
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
     * fuzzylite applies a conclusion's hedges to the rule's degree itself, so they hold for every later subconclusion
     * of the line too, and the model gives each subconclusion the whole list it is hedged by (its own hedges first).
     * A line can say the list of a subconclusion only if the previous one's list ends it: the group is split where
     * it does not (the same condition concluding each part: the same activations).
     */
    static List<BlockContext.WeightGroup> hedgeChains(BlockContext.WeightGroup g) {
        List<BlockContext.WeightGroup> out = new ArrayList<>();
        List<Subconclusion> chain = new ArrayList<>();
        for (Subconclusion s : g.parts()) {
            if (!chain.isEmpty() && !endsWith(s.hedges(), chain.get(chain.size() - 1).hedges())) {
                out.add(new BlockContext.WeightGroup(List.copyOf(chain), g.weight(), g.value()));
                chain.clear();
            }
            chain.add(s);
        }
        out.add(new BlockContext.WeightGroup(List.copyOf(chain), g.weight(), g.value()));
        return out;
    }

    /**
     * The hedges to write before the term of the line's subconclusion {@code i}: its list less the part the
     * previous subconclusion of the line already applied to the degree (hedgeChains makes that part its end).
     */
    static List<Hedge> writtenHedges(BlockContext.WeightGroup line, int i) {
        List<Hedge> all = line.parts().get(i).hedges();
        int before = i == 0 ? 0 : line.parts().get(i - 1).hedges().size();
        return all.subList(0, all.size() - before);
    }

    private static boolean endsWith(List<Hedge> list, List<Hedge> end) {
        return list.size() >= end.size() && list.subList(list.size() - end.size(), list.size()).equals(end);
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
