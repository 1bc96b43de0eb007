package org.fclcert.syntax.dialect;

import org.fclcert.model.Severity;

/**
 * The stable diagnostic codes of the dialect readers, {@code FCL-Dnnn}: FFLL owns D101-D199 (the jFuzzyLogic and
 * fuzzylite readers take D2nn and D3nn). Errors are FFLL programs fclcert cannot give a meaning to; warnings
 * mark places where FFLL itself gives the program another meaning than fclcert's (standard) reading, or where
 * FFLL would not load the program. docs/diagnostics.md lists the same table; a test keeps the two in step.
 */
public enum DialectCode {
    FFLL_NO_INPUT_IN_POSITION("FCL-D101", Severity.ERROR,
            "a subcondition in a position with no input: FFLL matches subconditions to inputs by declaration order"),
    FFLL_NO_OUTPUT_IN_POSITION("FCL-D102", Severity.ERROR,
            "a term-only subconclusion in a position with no output"),
    FFLL_MALFORMED_RANGE_COMMENT("FCL-D103", Severity.ERROR,
            "a comment starting with RANGE that is not '(* RANGE(lo .. hi) *)'"),
    FFLL_WRITTEN_VARIABLE_IGNORED("FCL-D111", Severity.WARNING,
            "a subcondition whose written variable is not the input in its position, which FFLL uses instead"),
    FFLL_NOT_AN_AND("FCL-D112", Severity.WARNING,
            "OR, NOT or parentheses in a condition, which FFLL evaluates as an AND of its subconditions"),
    FFLL_WITH_IGNORED("FCL-D113", Severity.WARNING,
            "WITH, which FFLL ignores"),
    FFLL_NO_DEFAULT("FCL-D114", Severity.WARNING,
            "no DEFAULT: FFLL returns the smallest positive float when no rule fires; fclcert reads DEFAULT := 0"),
    FFLL_MOM("FCL-D115", Severity.WARNING,
            "METHOD MoM: FFLL takes the peak of the single most activated term, fclcert the mean of maximum"),
    FFLL_COG("FCL-D116", Severity.WARNING,
            "METHOD CoG on point terms: FFLL adds each activated term's area separately on a grid"),
    FFLL_METHOD_NOT_HONOURED("FCL-D117", Severity.WARNING,
            "a METHOD other than 'CoG' or 'MoM' spelled so, which FFLL replaces by CoG"),
    FFLL_NO_RANGE_COMMENT("FCL-D118", Severity.WARNING,
            "a declaration without the RANGE comment FFLL needs to load the program"),
    FFLL_POINT_COUNT("FCL-D119", Severity.WARNING,
            "a term of a number of points FFLL does not load (it takes 1, 3, 4 or 7)"),
    FFLL_RANGES_DISAGREE("FCL-D120", Severity.WARNING,
            "an output whose RANGE and RANGE comment disagree; fclcert uses the RANGE");

    private final String code;
    private final Severity severity;
    private final String meaning;

    DialectCode(String code, Severity severity, String meaning) {
        this.code = code;
        this.severity = severity;
        this.meaning = meaning;
    }

    public String code() {
        return code;
    }

    public Severity severity() {
        return severity;
    }

    public String meaning() {
        return meaning;
    }
}
