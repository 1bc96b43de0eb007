package org.fclcert.probe;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Builds the text of one generated probe program: one function block, its declarations, FUZZIFY and
 * DEFUZZIFY blocks and rule blocks, always in the order of 5.4. Plain text rather than the model and
 * the canonical writer: the probes need programs of 100 000 elements built fast, and a few of them
 * (comments, letter case, long names) are about the text itself.
 */
final class FclText {
    private final String blockName;
    private final Map<String, String> inputs = new LinkedHashMap<>();
    private final Map<String, String> outputs = new LinkedHashMap<>();
    private final List<String> fuzzify = new ArrayList<>();
    private final List<String> defuzzify = new ArrayList<>();
    private final List<String> ruleBlocks = new ArrayList<>();
    private final List<List<String>> ruleTexts = new ArrayList<>();
    private List<String> currentRules;

    FclText(String blockName) {
        this.blockName = blockName;
    }

    FclText() {
        this("probe");
    }

    FclText input(String name, String type) {
        inputs.put(name, type);
        return this;
    }

    FclText input(String name) {
        return input(name, "REAL");
    }

    FclText output(String name, String type) {
        outputs.put(name, type);
        return this;
    }

    FclText output(String name) {
        return output(name, "REAL");
    }

    /** A FUZZIFY block; each term is {@code name := points} without the {@code TERM} and the {@code ;}. */
    FclText fuzzify(String variable, List<String> terms) {
        StringBuilder b = new StringBuilder("FUZZIFY ").append(variable).append('\n');
        for (String t : terms) {
            b.append("    TERM ").append(t).append(";\n");
        }
        fuzzify.add(b.append("END_FUZZIFY\n").toString());
        return this;
    }

    /** A DEFUZZIFY block with its terms, METHOD, optional RANGE and DEFAULT := 0. */
    FclText defuzzify(String variable, List<String> terms, String method, String range) {
        StringBuilder b = new StringBuilder("DEFUZZIFY ").append(variable).append('\n');
        for (String t : terms) {
            b.append("    TERM ").append(t).append(";\n");
        }
        b.append("    METHOD: ").append(method).append(";\n");
        b.append("    DEFAULT := 0;\n");
        if (range != null) {
            b.append("    RANGE := ").append(range).append(";\n");
        }
        defuzzify.add(b.append("END_DEFUZZIFY\n").toString());
        return this;
    }

    FclText singletons(String variable, List<String> terms) {
        return defuzzify(variable, terms, "CoGS", null);
    }

    /** Starts a rule block with AND: MIN and ACCU: MAX; {@link #rule} adds to it. */
    FclText ruleBlock(String name) {
        currentRules = new ArrayList<>();
        ruleBlocks.add(name);
        ruleTexts.add(currentRules);
        return this;
    }

    /** Adds {@code RULE n: IF condition THEN conclusion;} to the current rule block, numbered from 1. */
    FclText rule(String condition, String conclusion) {
        currentRules.add("IF " + condition + " THEN " + conclusion);
        return this;
    }

    String text() {
        StringBuilder b = new StringBuilder(1024);
        b.append("FUNCTION_BLOCK ").append(blockName).append('\n');
        declarations(b, "VAR_INPUT", inputs);
        declarations(b, "VAR_OUTPUT", outputs);
        fuzzify.forEach(b::append);
        defuzzify.forEach(b::append);
        for (int i = 0; i < ruleTexts.size(); i++) {
            b.append("RULEBLOCK ").append(ruleBlocks.get(i)).append('\n');
            b.append("    AND: MIN;\n    ACCU: MAX;\n");
            List<String> rules = ruleTexts.get(i);
            for (int r = 0; r < rules.size(); r++) {
                b.append("    RULE ").append(r + 1).append(": ").append(rules.get(r)).append(";\n");
            }
            b.append("END_RULEBLOCK\n");
        }
        return b.append("END_FUNCTION_BLOCK\n").toString();
    }

    private static void declarations(StringBuilder b, String section, Map<String, String> vars) {
        b.append(section).append('\n');
        vars.forEach((name, type) -> b.append("    ").append(name).append(": ").append(type).append(";\n"));
        b.append("END_VAR\n");
    }

    /** {@code (0, 0) (1, 1)}: degree = x on [0, 1]. */
    static final String RAMP = "(0, 0) (1, 1)";

    /** {@code (c-1, 0) (c, 1) (c+1, 0)}: 1 at c, 0 one unit away and beyond. */
    static String triangle(long c) {
        return "(" + (c - 1) + ", 0) (" + c + ", 1) (" + (c + 1) + ", 0)";
    }
}
