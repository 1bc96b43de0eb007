package org.fclcert.iut;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.model.Names;

/**
 * Finds the VAR_OUTPUT names of one function block in FCL text. The vendor SPI returns one output at
 * a time by name, so the Java adapter must know which names to ask for; this small scanner reads only
 * the declarations and does not depend on the program being valid anywhere else.
 */
final class DeclaredOutputs {
    private static final Pattern COMMENT = Pattern.compile("\\(\\*.*?(\\*\\)|\\z)", Pattern.DOTALL);
    private static final Pattern TOKEN = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*|:=|\\S");
    private static final List<String> QUALIFIERS = List.of("RETAIN", "NON_RETAIN", "CONSTANT");

    private DeclaredOutputs() {}

    /** The outputs of {@code block} (null = the first function block) in declaration order, as written. */
    static List<String> of(String fcl, String block) {
        List<String> tokens = tokens(fcl);
        List<String> outputs = new ArrayList<>();
        int k = blockStart(tokens, block);
        while (k >= 0 && k < tokens.size() && !is(tokens.get(k), "END_FUNCTION_BLOCK")) {
            k = is(tokens.get(k), "VAR_OUTPUT") ? declarations(tokens, k + 1, outputs) : k + 1;
        }
        return List.copyOf(outputs);
    }

    private static List<String> tokens(String fcl) {
        List<String> tokens = new ArrayList<>();
        Matcher m = TOKEN.matcher(COMMENT.matcher(fcl).replaceAll(" "));
        while (m.find()) {
            tokens.add(m.group());
        }
        return tokens;
    }

    /** The index after the named block's header, or -1 when there is no such block. */
    private static int blockStart(List<String> tokens, String block) {
        for (int k = 0; k + 1 < tokens.size(); k++) {
            if (is(tokens.get(k), "FUNCTION_BLOCK") && (block == null || Names.same(tokens.get(k + 1), block))) {
                return k + 2;
            }
        }
        return -1;
    }

    /** Reads {@code name {, name} : type [:= value] ;} lines up to END_VAR; returns the index after it. */
    private static int declarations(List<String> tokens, int k, List<String> outputs) {
        boolean naming = true;
        for (; k < tokens.size() && !is(tokens.get(k), "END_VAR"); k++) {
            String t = tokens.get(k);
            if (t.equals(";")) {
                naming = true;
            } else if (t.equals(":")) {
                naming = false;
            } else if (naming && Character.isLetter(t.charAt(0)) || naming && t.charAt(0) == '_') {
                if (!QUALIFIERS.contains(Names.key(t))) {
                    outputs.add(t);
                }
            }
        }
        return k + 1;
    }

    private static boolean is(String token, String keyword) {
        return Names.same(token, keyword);
    }
}
