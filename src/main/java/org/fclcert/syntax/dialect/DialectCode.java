package org.fclcert.syntax.dialect;

import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;

/**
 * The stable diagnostic codes of the dialect readers, in one place: FFLL's {@code FCL-D101..D199}, and the
 * jFuzzyLogic and fuzzylite readers' {@code FCL-S301..S399} (errors) and {@code FCL-W301..W399} (warnings).
 * Errors are texts fclcert cannot give a meaning to in the dialect; warnings mark places where the library
 * itself gives the program another meaning than fclcert's (standard) reading, or would not load it. docs/diagnostics.md lists the same table; a test keeps the two in step.
 * An internal error of a dialect reader is the strict reader's {@code SyntaxCode.INTERNAL_ERROR} (FCL-S999).
 */
public enum DialectCode implements DiagnosticCode {
    FFLL_NO_INPUT_IN_POSITION("FCL-D101", Severity.ERROR, "5.2.4",
            "a subcondition in a position with no input: FFLL matches subconditions to inputs by declaration order"),
    FFLL_NO_OUTPUT_IN_POSITION("FCL-D102", Severity.ERROR, "5.2.4",
            "a term-only subconclusion in a position with no output"),
    FFLL_MALFORMED_RANGE_COMMENT("FCL-D103", Severity.ERROR, "5.2.3",
            "a comment starting with RANGE that is not '(* RANGE(lo .. hi) *)'"),
    FFLL_WRITTEN_VARIABLE_IGNORED("FCL-D111", Severity.WARNING, "5.2.4",
            "a subcondition whose written variable is not the input in its position, which FFLL uses instead"),
    FFLL_NOT_AN_AND("FCL-D112", Severity.WARNING, "Table 6",
            "OR, NOT or parentheses in a condition, which FFLL evaluates as an AND of its subconditions"),
    FFLL_WITH_IGNORED("FCL-D113", Severity.WARNING, "5.2.4",
            "WITH, which FFLL ignores"),
    FFLL_NO_DEFAULT("FCL-D114", Severity.WARNING, "5.2.3",
            "no DEFAULT: FFLL returns the smallest positive float when no rule fires; fclcert reads DEFAULT := 0"),
    FFLL_MOM("FCL-D115", Severity.WARNING, "Table 10",
            "METHOD MoM: FFLL takes the peak of the single most activated term, fclcert the mean of maximum"),
    FFLL_COG("FCL-D116", Severity.WARNING, "Table 1",
            "METHOD CoG on point terms: FFLL adds each activated term's area separately on a grid"),
    FFLL_METHOD_NOT_HONOURED("FCL-D117", Severity.WARNING, "Table 1",
            "a METHOD other than 'CoG' or 'MoM' spelled so, which FFLL replaces by CoG"),
    FFLL_NO_RANGE_COMMENT("FCL-D118", Severity.WARNING, "5.2.3",
            "a declaration without the RANGE comment FFLL needs to load the program"),
    FFLL_POINT_COUNT("FCL-D119", Severity.WARNING, "5.2.2",
            "a term of a number of points FFLL does not load (it takes 1, 3, 4 or 7)"),
    FFLL_RANGES_DISAGREE("FCL-D120", Severity.WARNING, "5.2.3",
            "an output whose RANGE and RANGE comment disagree; fclcert uses the RANGE"),
    FFLL_PARENTHESISED_SUBCONCLUSION("FCL-D121", Severity.WARNING, "5.4",
            "a subconclusion in parentheses, as FFLL writes them; read without them"),
    FFLL_DEFUZZIFY_NAME_IGNORED("FCL-D122", Severity.WARNING, "5.2.3",
            "DEFUZZIFY naming no declared variable: FFLL ignores the name and defuzzifies its one output"),

    // the jFuzzyLogic and fuzzylite readers (one shared reading core, DialectParser, with a LibraryDialect strategy each): FCL-S3nn errors, FCL-W3nn
    // warnings where the library gives the program another meaning than fclcert reads
    UNEXPECTED_CHARACTER("FCL-S301", Severity.ERROR, "IEC 61131-3 B.1",
            "a character the dialect does not accept"),
    UNTERMINATED_COMMENT("FCL-S302", Severity.ERROR, "IEC 61131-3 B.1.5.1",
            "a comment never closed"),
    COMMENT_STYLE("FCL-S303", Severity.ERROR, "IEC 61131-3 B.1.5.1",
            "a comment style the dialect rejects (e.g. '(* *)' in fuzzylite)"),
    BAD_NUMBER("FCL-S304", Severity.ERROR, "IEC 61131-3 B.1.2",
            "a malformed number, or inf / nan where the dialect takes none"),
    SYNTAX("FCL-S305", Severity.ERROR, "5.4",
            "text that does not fit the dialect's grammar (what was expected is named)"),
    NOT_IN_DIALECT("FCL-S306", Severity.ERROR, "5.4",
            "a construct the library itself rejects or silently drops (VAR, initial values, upper-case rule keywords in fuzzylite, ...)"),
    UNKNOWN_SHAPE("FCL-S307", Severity.ERROR, "Table 10",
            "a membership-function name the dialect does not define"),
    UNSUPPORTED("FCL-S308", Severity.ERROR, "Table 10",
            "a construct of the library fclcert does not evaluate (ENABLED : FALSE, other norms, hedges in conclusions, ...)"),
    ACCUMULATION_CONFLICT("FCL-S309", Severity.ERROR, "Table 5",
            "outputs concluded by one rule block with different ACCU in their DEFUZZIFY blocks (fuzzylite)"),
    STATEMENT_SPANS_LINES("FCL-S310", Severity.ERROR, "5.4",
            "a rule or term continued on another line; fuzzylite reads one statement per line"),
    DIALECT_UNCLEAR("FCL-S311", Severity.ERROR, "—",
            "--dialect auto found signs of several libraries, none clearly ahead; name the dialect with --dialect"),
    TOO_MANY_ERRORS("FCL-S399", Severity.ERROR, "—",
            "more errors than the reader reports (the rest are not reported)"),
    COUPLED_AND_OR("FCL-W301", Severity.WARNING, "Table 3",
            "jFuzzyLogic couples AND and OR: the later declaration replaces the other by its pair"),
    AND_OR_PRIORITY("FCL-W302", Severity.WARNING, "Table 6",
            "jFuzzyLogic gives AND and OR one priority, left to right; fclcert binds AND tighter (Table 6)"),
    NAMES_DIFFER_IN_CASE("FCL-W303", Severity.WARNING, "IEC 61131-3 B.1.1",
            "two spellings of one name that differ only in case: one name in FCL, two in jFuzzyLogic"),
    SUPPLIED_SETTING("FCL-W304", Severity.WARNING, "5.2.3, 5.2.4",
            "a setting left out that the library supplies (jFuzzyLogic: ACCU SUM, METHOD CoG, DEFAULT NC, AND MIN)"),
    LOCK_PREVIOUS("FCL-W305", Severity.WARNING, "5.2.3",
            "LOCK : PREVIOUS read as DEFAULT NC: before the first result fclcert gives the initial value"),
    COGS_PER_RULE("FCL-W306", Severity.WARNING, "Table 5",
            "fuzzylite's COGS counts every rule separately; fclcert accumulates per term first (Table 5)"),
    NSUM_AS_BSUM("FCL-W307", Severity.WARNING, "Table 5",
            "the library computes NSUM as BSUM; fclcert normalises (Table 5)"),
    TOLERATED("FCL-W308", Severity.WARNING, "5.4",
            "a construct the library tolerates and the standard does not (text after END_FUNCTION_BLOCK, a block"
                    + " name that is no identifier, a repeated rule name, AND/OR outside the pairs of Table 3); read as"
                    + " the library reads it"),
    IMPLIED_RANGE("FCL-W309", Severity.WARNING, "5.2.3",
            "an output without RANGE that needs one: the library defuzzifies over the span of its terms, read as that"
                    + " RANGE"),
    WEIGHT_BEFORE_ACTIVATION("FCL-W310", Severity.WARNING, "5.2.4",
            "fuzzylite multiplies a rule's degree by its WITH weight before activation (and hedges); fclcert weighs"
                    + " the activated set, which differs under any ACT but PROD on fuzzy-set outputs"),
    FIRST_PLATEAU("FCL-W311", Severity.WARNING, "Table 10",
            "fuzzylite's MM takes the middle of the first plateau of maximum; fclcert the mean of every maximal point"),
    TSUKAMOTO_INVERSE("FCL-W312", Severity.WARNING, "Table 10",
            "fuzzylite 6.0 inverts SShape, ZShape and Concave terms wrongly in Tsukamoto's method; fclcert exactly"),
    OUTPUT_AT_START("FCL-W313", Severity.WARNING, "5.2.4",
            "jFuzzyLogic reads an output in a condition at its value when the evaluation begins (its DEFAULT), so rule"
                    + " blocks do not chain; read so"),
    FIS_SUM("FCL-W314", Severity.WARNING, "Table 5",
            "a FIS aggregation Octave and fuzzylite evaluate differently, read as MATLAB: 'sum' adds the rules' sets"
                    + " (fuzzylite 6: probor); a Sugeno output averages every rule's value (Octave first aggregates the"
                    + " rules concluding one term by AggMethod)"),
    FIS_HEDGE("FCL-W315", Severity.WARNING, "Table 10",
            "a hedge in a FIS rule that Octave evaluates otherwise than fuzzylite (read as fuzzylite): 'extremely' (.3)"
                    + " Octave cubes; a hedge in a consequent Octave applies to the output's term, not the rule's degree"),
    FIS_DSIGMF("FCL-W316", Severity.WARNING, "Table 10",
            "a FIS dsigmf whose second sigmoid exceeds its first somewhere, read as fuzzylite (the absolute difference):"
                    + " the Octave toolkit gives 0 there");

    private final Entry entry;

    DialectCode(String code, Severity severity, String clause, String meaning) {
        this.entry = new Entry(code, severity, clause, meaning);
    }

    @Override
    public Entry entry() {
        return entry;
    }
}
