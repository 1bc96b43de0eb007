package org.fclcert.model;

import java.util.Arrays;
import java.util.Optional;

/**
 * {@code METHOD:} algorithms: those of Tables 1 and 2, with the spelling Table 1 uses, and the
 * non-standard ones dialect readers accept (Open Level, Table 10), which the strict reader rejects.
 */
public enum DefuzzificationMethod {
    COG("CoG", true),
    COGS("CoGS", true),
    COA("CoA", true),
    LM("LM", true),
    RM("RM", true),
    /** Mean of maximum (FFLL's MoM, jFuzzyLogic's and fuzzylite's MM): Open Level, O-MOM. */
    MOM("MoM", false),
    /** Weighted sum of singletons, Σ u·μ without the division (fuzzylite's COGSS): Open Level, O-COGSS. */
    COGSS("COGSS", false),
    /**
     * Tsukamoto's method (fuzzylite's COGS on monotonic terms): Σ μ·z / Σ μ over the terms, z the point where the
     * monotonic term reaches its accumulated degree μ: Open Level, O-TSUKAMOTO.
     */
    TSUKAMOTO("Tsukamoto", false);

    private final String keyword;
    private final boolean standard;

    DefuzzificationMethod(String keyword, boolean standard) {
        this.keyword = keyword;
        this.standard = standard;
    }

    /** True for the methods of Table 1. */
    public boolean standard() {
        return standard;
    }

    /** The keyword as Table 1 spells it; FCL keywords are not case-sensitive. */
    public String keyword() {
        return keyword;
    }

    /** A method of Table 1 by its keyword (any case); the non-standard ones are not found. */
    public static Optional<DefuzzificationMethod> byKeyword(String word) {
        return Arrays.stream(values()).filter(m -> m.standard && m.keyword.equalsIgnoreCase(word)).findFirst();
    }
}
