package org.fclcert.syntax;

import java.util.Locale;

/**
 * The words standard FCL reserves (Table 7 and the IEC 61131-3 data types: every keyword of the lexer), for writers
 * that must never emit one as a name. A name read by a dialect reader may be one (an unnamed block is named
 * {@code function_block}; jFuzzyLogic takes {@code BSUM} as a rule's name); {@link #unreserved} gives the one
 * spelling every writer of standard FCL uses instead, the same at every use of the name.
 */
public final class ReservedWords {
    /** What a reserved name gets appended. */
    public static final String SUFFIX = "_1";

    private ReservedWords() {
    }

    /** True when {@code name}, in any letter case, is a keyword of standard FCL. */
    public static boolean isReserved(String name) {
        if (name == null || name.isEmpty()) {
            return false;
        }
        String upper = name.toUpperCase(Locale.ROOT);
        for (int type = FclLexer.FUNCTION_BLOCK; type <= FclLexer.ULINT; type++) {
            if (Keywords.spelling(type).toUpperCase(Locale.ROOT).equals(upper)) {
                return true;
            }
        }
        return false;
    }

    /** {@code name}, or for a reserved word {@code name_1}. */
    public static String unreserved(String name) {
        return isReserved(name) ? name + SUFFIX : name;
    }
}
