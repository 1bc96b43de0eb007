package org.fclcert.syntax.dialect;

import java.util.Arrays;
import java.util.Optional;

/**
 * The FCL dialects fclcert reads: the standard itself and the dialects of three libraries in the wild
 * (docs/peers.md). Every reader produces the same semantic model; a dialect reader records
 * each construct outside the standard as an Open Level feature of the program.
 */
public enum Dialect {
    STRICT("strict", "IEC 61131-7 as written"),
    FFLL("ffll", "Free Fuzzy Logic Library (FFLL)"),
    JFUZZYLOGIC("jfuzzylogic", "jFuzzyLogic"),
    FUZZYLITE("fuzzylite", "fuzzylite");

    private final String cliName;
    private final String displayName;

    Dialect(String cliName, String displayName) {
        this.cliName = cliName;
        this.displayName = displayName;
    }

    /** The name used on the command line ({@code --dialect ffll}). */
    public String cliName() {
        return cliName;
    }

    public String displayName() {
        return displayName;
    }

    public static Optional<Dialect> byCliName(String name) {
        return Arrays.stream(values()).filter(d -> d.cliName.equalsIgnoreCase(name)).findFirst();
    }
}
