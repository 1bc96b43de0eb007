package org.fclcert.check;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;

/**
 * FCL-W005 (warning): for every input the rule block's conditions can see, some rule fires. A region where
 * every rule's degree is 0 leaves the block's outputs at their DEFAULT (or unchanged, NC; 5.2.3), which is
 * rarely what a controller's author meant. The regions are found exactly by {@link CoverageGaps}; each is
 * reported as a box, at most {@link #MAX_REPORTED} per block.
 */
public final class RulesCoverTheInputSpace implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.warning("FCL-W005", "5.2.3",
            "some rule of each rule block fires for every input");

    /** Boxes reported one by one per rule block; the last finding counts the rest. */
    static final int MAX_REPORTED = 8;

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (RuleBlock rb : block.ruleBlocks()) {
            CoverageGaps.Result result = CoverageGaps.of(block, rb);
            if (!result.analysed() || result.gaps().isEmpty()) {
                continue;
            }
            String fallback = fallback(block, rb);
            List<CoverageGaps.Box> gaps = result.gaps();
            for (int i = 0; i < gaps.size() && i < MAX_REPORTED; i++) {
                String more = i == MAX_REPORTED - 1 && gaps.size() > MAX_REPORTED
                        ? " (and " + (gaps.size() - MAX_REPORTED) + " more such regions)" : "";
                sink.report(finding(rb.location(), region(result.inputs(), gaps.get(i)) + ": no rule of block '"
                        + rb.name() + "' fires; " + fallback + more));
            }
        }
    }

    /** {@code error in [-5, -1] and trend in [-2, 0]}; an input free over the whole line is left out. */
    static String region(List<String> inputs, CoverageGaps.Box box) {
        List<String> parts = new ArrayList<>();
        for (int a = 0; a < inputs.size(); a++) {
            CoverageGaps.Interval in = box.intervals().get(a);
            if (!in.whole()) {
                parts.add(inputs.get(a) + (in.point() ? " " : " in ") + in);
            }
        }
        return parts.isEmpty() ? "for every input" : String.join(" and ", parts);
    }

    /** What the block's outputs do when none of its rules fires. */
    private static String fallback(FunctionBlock block, RuleBlock rb) {
        Map<String, String> outputs = new LinkedHashMap<>();
        for (Rule r : rb.rules()) {
            for (Subconclusion s : r.conclusion()) {
                outputs.putIfAbsent(Names.key(s.variable()), s.variable());
            }
        }
        List<String> parts = new ArrayList<>();
        for (String output : outputs.values()) {
            var d = block.defuzzification(output).flatMap(Defuzzification::defaultValue);
            if (d.isEmpty()) {
                parts.add(output + " takes no defined value (it has no DEFAULT)");
            } else if (d.get() instanceof DefaultValue.Constant c) {
                parts.add(output + " takes DEFAULT " + Describe.number(c.value().value()));
            } else {
                parts.add(output + " keeps its previous value (DEFAULT NC)");
            }
        }
        boolean shared = block.ruleBlocks().size() > 1;
        return String.join(", ", parts) + (shared ? " unless another rule block concludes it" : "");
    }
}
