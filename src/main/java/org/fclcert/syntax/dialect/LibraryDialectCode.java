package org.fclcert.syntax.dialect;

/**
 * The stable diagnostic codes of the jFuzzyLogic and fuzzylite readers: {@code FCL-S3nn} errors and
 * {@code FCL-W3nn} warnings (where the library gives the program another meaning than fclcert reads).
 * docs/diagnostics.md lists the same table in its last section; a test keeps the two in step.
 */
public enum LibraryDialectCode {
    UNEXPECTED_CHARACTER("FCL-S301", "a character the dialect does not accept"),
    UNTERMINATED_COMMENT("FCL-S302", "a comment never closed"),
    COMMENT_STYLE("FCL-S303", "a comment style the dialect rejects (e.g. '(* *)' in fuzzylite)"),
    BAD_NUMBER("FCL-S304", "a malformed number, or inf / nan where the dialect takes none"),
    SYNTAX("FCL-S305", "text that does not fit the dialect's grammar (what was expected is named)"),
    NOT_IN_DIALECT("FCL-S306", "a construct the library itself rejects or silently drops (VAR, initial values, upper-case rule keywords in fuzzylite, ...)"),
    UNKNOWN_SHAPE("FCL-S307", "a membership-function name the dialect does not define"),
    UNSUPPORTED("FCL-S308", "a construct of the library fclcert does not evaluate (ENABLED : FALSE, other norms, hedges in conclusions, ...)"),
    ACCUMULATION_CONFLICT("FCL-S309", "outputs concluded by one rule block with different ACCU in their DEFUZZIFY blocks (fuzzylite)"),
    STATEMENT_SPANS_LINES("FCL-S310", "a rule or term continued on another line; fuzzylite reads one statement per line"),
    TOO_MANY_ERRORS("FCL-S399", "more errors than the reader reports, or an internal error of the reader"),
    COUPLED_AND_OR("FCL-W301", "jFuzzyLogic couples AND and OR: the later declaration replaces the other by its pair"),
    AND_OR_PRIORITY("FCL-W302", "jFuzzyLogic gives AND and OR one priority, left to right; fclcert binds AND tighter (Table 6)"),
    NAMES_DIFFER_IN_CASE("FCL-W303", "two spellings of one name that differ only in case: one name in FCL, two in jFuzzyLogic"),
    SUPPLIED_SETTING("FCL-W304", "a setting left out that the library supplies (jFuzzyLogic: ACCU SUM, METHOD CoG, DEFAULT NC)"),
    LOCK_PREVIOUS("FCL-W305", "LOCK : PREVIOUS read as DEFAULT NC: before the first result fclcert gives the initial value"),
    COGS_PER_RULE("FCL-W306", "fuzzylite's COGS counts every rule separately; fclcert accumulates per term first (Table 5)"),
    NSUM_AS_BSUM("FCL-W307", "the library computes NSUM as BSUM; fclcert normalises (Table 5)");

    private final String code;
    private final String meaning;

    LibraryDialectCode(String code, String meaning) {
        this.code = code;
        this.meaning = meaning;
    }

    public String code() {
        return code;
    }

    public String meaning() {
        return meaning;
    }
}
