package org.fclcert.model;

import java.util.Arrays;
import java.util.Optional;

/** {@code METHOD:} algorithms (Tables 1 and 2), with the spelling Table 1 uses. */
public enum DefuzzificationMethod {
    COG("CoG"),
    COGS("CoGS"),
    COA("CoA"),
    LM("LM"),
    RM("RM");

    private final String keyword;

    DefuzzificationMethod(String keyword) {
        this.keyword = keyword;
    }

    /** The keyword as Table 1 spells it; FCL keywords are not case-sensitive. */
    public String keyword() {
        return keyword;
    }

    public static Optional<DefuzzificationMethod> byKeyword(String word) {
        return Arrays.stream(values()).filter(m -> m.keyword.equalsIgnoreCase(word)).findFirst();
    }
}
