package org.fclcert.model;

import java.util.Arrays;
import java.util.Optional;

/**
 * The conformance feature catalogue: one entry per row of Table 8 (Basic Level, mandatory),
 * Table 9 (Extension Level, optional) and Table 10 (Open Level features fclcert can recognise).
 * Ids are stable: reports, the corpus and the feature detector key on them. Descriptions are
 * fclcert's own wording of the row.
 */
public enum Feature {
    // Table 8 - Basic Level
    B_FB("B-FB", ConformanceLevel.BASIC, "function block declaration",
            "function block with VAR_INPUT and VAR_OUTPUT variables"),
    B_IN_TERM("B-IN-TERM", ConformanceLevel.BASIC, "membership function, input",
            "input term of at most three constant points, degrees 0 or 1"),
    B_OUT_SINGLETON("B-OUT-SINGLETON", ConformanceLevel.BASIC, "membership function, output",
            "constant singleton output terms"),
    B_AND_MIN("B-AND-MIN", ConformanceLevel.BASIC, "conditional aggregation",
            "AND operator with the MIN algorithm"),
    B_ACCU_MAX("B-ACCU-MAX", ConformanceLevel.BASIC, "accumulation",
            "ACCU with the MAX algorithm"),
    B_COGS("B-COGS", ConformanceLevel.BASIC, "defuzzification",
            "METHOD CoGS, centre of gravity for singletons"),
    B_DEFAULT_VALUE("B-DEFAULT-VALUE", ConformanceLevel.BASIC, "default value",
            "DEFAULT with a constant value when no rule fired"),
    B_DEFAULT_NC("B-DEFAULT-NC", ConformanceLevel.BASIC, "default value",
            "DEFAULT NC: output keeps its previous value when no rule fired"),
    B_ONE_RULEBLOCK("B-ONE-RULEBLOCK", ConformanceLevel.BASIC, "ruleblock",
            "a single rule block"),
    B_SUBCONDITIONS("B-SUBCONDITIONS", ConformanceLevel.BASIC, "condition",
            "any number of subconditions 'variable IS term'"),
    B_ONE_SUBCONCLUSION("B-ONE-SUBCONCLUSION", ConformanceLevel.BASIC, "conclusion",
            "one subconclusion per rule"),

    // Table 9 - Extension Level
    E_VAR_LOCAL("E-VAR-LOCAL", ConformanceLevel.EXTENSION, "function block declaration",
            "local variables in a VAR section"),
    E_IN_TERM_4("E-IN-TERM-4", ConformanceLevel.EXTENSION, "membership function, input",
            "input terms of four points"),
    E_OUT_TERM_4("E-OUT-TERM-4", ConformanceLevel.EXTENSION, "membership function, output",
            "output terms of up to four points (degrees 0 or 1)"),
    E_TERM_VARIABLE_POINT("E-TERM-VARIABLE-POINT", ConformanceLevel.EXTENSION, "membership function",
            "term points or singletons given by input variables"),
    E_AND_PROD("E-AND-PROD", ConformanceLevel.EXTENSION, "conditional aggregation",
            "AND operator with the PROD algorithm"),
    E_AND_BDIF("E-AND-BDIF", ConformanceLevel.EXTENSION, "conditional aggregation",
            "AND operator with the BDIF algorithm"),
    E_OR_MAX("E-OR-MAX", ConformanceLevel.EXTENSION, "conditional aggregation",
            "OR operator with the MAX algorithm (the pair of AND MIN, Table 3)"),
    E_OR_ASUM("E-OR-ASUM", ConformanceLevel.EXTENSION, "conditional aggregation",
            "OR operator with the ASUM algorithm"),
    E_OR_BSUM("E-OR-BSUM", ConformanceLevel.EXTENSION, "conditional aggregation",
            "OR operator with the BSUM algorithm"),
    E_NOT("E-NOT", ConformanceLevel.EXTENSION, "conditional aggregation",
            "NOT operator, 1 - argument (also IS NOT)"),
    E_PARENS("E-PARENS", ConformanceLevel.EXTENSION, "conditional aggregation",
            "parentheses in conditions"),
    E_ACT_MIN("E-ACT-MIN", ConformanceLevel.EXTENSION, "activation",
            "ACT with the MIN algorithm"),
    E_ACT_PROD("E-ACT-PROD", ConformanceLevel.EXTENSION, "activation",
            "ACT with the PROD algorithm"),
    E_ACCU_BSUM("E-ACCU-BSUM", ConformanceLevel.EXTENSION, "accumulation",
            "ACCU with the BSUM algorithm"),
    E_ACCU_NSUM("E-ACCU-NSUM", ConformanceLevel.EXTENSION, "accumulation",
            "ACCU with the NSUM algorithm"),
    E_RANGE("E-RANGE", ConformanceLevel.EXTENSION, "range",
            "RANGE limiting the output membership functions"),
    E_COG("E-COG", ConformanceLevel.EXTENSION, "defuzzification method",
            "METHOD CoG, centre of gravity"),
    E_COA("E-COA", ConformanceLevel.EXTENSION, "defuzzification method",
            "METHOD CoA, centre of area"),
    E_LM("E-LM", ConformanceLevel.EXTENSION, "defuzzification method",
            "METHOD LM, left-most maximum"),
    E_RM("E-RM", ConformanceLevel.EXTENSION, "defuzzification method",
            "METHOD RM, right-most maximum"),
    E_RULEBLOCKS("E-RULEBLOCKS", ConformanceLevel.EXTENSION, "ruleblock",
            "several rule blocks"),
    E_COND_VARIABLE("E-COND-VARIABLE", ConformanceLevel.EXTENSION, "condition",
            "input (or local) variables used directly as subconditions"),
    E_SUBCONCLUSIONS("E-SUBCONCLUSIONS", ConformanceLevel.EXTENSION, "conclusion",
            "several subconclusions or output variables per rule, bare variable conclusions"),
    E_WITH_CONST("E-WITH-CONST", ConformanceLevel.EXTENSION, "weighting factor",
            "WITH a constant weighting factor"),
    E_WITH_VAR("E-WITH-VAR", ConformanceLevel.EXTENSION, "weighting factor",
            "WITH a VAR_INPUT variable as weighting factor"),

    // Table 10 - Open Level
    O_MANY_POINTS("O-MANY-POINTS", ConformanceLevel.OPEN, "membership function",
            "more than four points in a term"),
    O_DEGREES_0_1("O-DEGREES-0-1", ConformanceLevel.OPEN, "membership function",
            "point degrees strictly between 0 and 1"),
    O_VAR_DEGREE("O-VAR-DEGREE", ConformanceLevel.OPEN, "membership function",
            "membership degrees given by variables"),
    O_MOM("O-MOM", ConformanceLevel.OPEN, "defuzzification method",
            "METHOD MoM, mean of maximum"),

    // Table 10 - Open Level constructs of the FFLL dialect (read by FfllReader; dialect syntax only)
    O_FFLL_TERM_ONLY_CONDITION("O-FFLL-TERM-ONLY-CONDITION", ConformanceLevel.OPEN, "condition",
            "a subcondition naming only a term, taken for the input in its position", true),
    O_FFLL_TERM_ONLY_CONCLUSION("O-FFLL-TERM-ONLY-CONCLUSION", ConformanceLevel.OPEN, "conclusion",
            "a subconclusion naming only a term, taken for the output in its position", true),
    O_FFLL_OUTPUT_FUZZIFY("O-FFLL-OUTPUT-FUZZIFY", ConformanceLevel.OPEN, "membership function, output",
            "output terms given in a FUZZIFY block of the output", true),
    O_END_FUZZIFY("O-END-FUZZIFY", ConformanceLevel.OPEN, "defuzzification",
            "a DEFUZZIFY block closed by END_FUZZIFY", true),
    O_ACCUM("O-ACCUM", ConformanceLevel.OPEN, "accumulation",
            "ACCUM: as the keyword of the accumulation method", true),
    O_RANGE_COMMENT("O-RANGE-COMMENT", ConformanceLevel.OPEN, "range",
            "a variable's range in a comment (* RANGE(lo .. hi) *)", true),
    O_FFLL_NO_DEFAULT("O-FFLL-NO-DEFAULT", ConformanceLevel.OPEN, "default value",
            "an output without DEFAULT", true),
    O_FFLL_NO_METHOD("O-FFLL-NO-METHOD", ConformanceLevel.OPEN, "defuzzification method",
            "an output without METHOD, defuzzified by CoG", true),
    O_DECLARATION_WITHOUT_COLON("O-DECLARATION-WITHOUT-COLON", ConformanceLevel.OPEN, "function block declaration",
            "a variable declaration without ':' before its type", true),
    O_VAR_RETAIN("O-VAR-RETAIN", ConformanceLevel.OPEN, "function block declaration",
            "RETAIN or NON_RETAIN on a variable section (IEC 61131-3)", true),

    // Table 10 - Open Level: the jFuzzyLogic and fuzzylite dialects (read by JFuzzyLogicReader and FuzzyliteReader; dialect syntax only, docs/dialects.md)
    O_SHAPE_TRIANGLE("O-SHAPE-TRIANGLE", ConformanceLevel.OPEN, "membership function",
            "named shape: triangle", true),
    O_SHAPE_TRAPEZOID("O-SHAPE-TRAPEZOID", ConformanceLevel.OPEN, "membership function",
            "named shape: trapezoid", true),
    O_SHAPE_RECTANGLE("O-SHAPE-RECTANGLE", ConformanceLevel.OPEN, "membership function",
            "named shape: rectangle", true),
    O_SHAPE_RAMP("O-SHAPE-RAMP", ConformanceLevel.OPEN, "membership function",
            "named shape: ramp", true),
    O_SHAPE_GAUSSIAN("O-SHAPE-GAUSSIAN", ConformanceLevel.OPEN, "membership function",
            "named shape: Gaussian", true),
    O_SHAPE_GAUSSIAN_PRODUCT("O-SHAPE-GAUSSIAN-PRODUCT", ConformanceLevel.OPEN, "membership function",
            "named shape: product of two Gaussian shoulders (gauss2, GaussianProduct)", true),
    O_SHAPE_BELL("O-SHAPE-BELL", ConformanceLevel.OPEN, "membership function",
            "named shape: generalised bell (gbell, Bell)", true),
    O_SHAPE_SIGMOID("O-SHAPE-SIGMOID", ConformanceLevel.OPEN, "membership function",
            "named shape: sigmoid (sigm, Sigmoid)", true),
    O_SHAPE_SIGMOID_DIFFERENCE("O-SHAPE-SIGMOID-DIFFERENCE", ConformanceLevel.OPEN, "membership function",
            "named shape: difference of two sigmoids (dsigm, SigmoidDifference)", true),
    O_SHAPE_SIGMOID_PRODUCT("O-SHAPE-SIGMOID-PRODUCT", ConformanceLevel.OPEN, "membership function",
            "named shape: product of two sigmoids (SigmoidProduct)", true),
    O_SHAPE_COSINE("O-SHAPE-COSINE", ConformanceLevel.OPEN, "membership function",
            "named shape: raised cosine", true),
    O_SHAPE_S("O-SHAPE-S", ConformanceLevel.OPEN, "membership function",
            "named shape: S-shaped smooth step up (SShape)", true),
    O_SHAPE_Z("O-SHAPE-Z", ConformanceLevel.OPEN, "membership function",
            "named shape: Z-shaped smooth step down (ZShape)", true),
    O_SHAPE_PI("O-SHAPE-PI", ConformanceLevel.OPEN, "membership function",
            "named shape: pi-shaped smooth bump (PiShape)", true),
    O_SHAPE_CONCAVE("O-SHAPE-CONCAVE", ConformanceLevel.OPEN, "membership function",
            "named shape: fuzzylite's Concave", true),
    O_SHAPE_SPIKE("O-SHAPE-SPIKE", ConformanceLevel.OPEN, "membership function",
            "named shape: fuzzylite's Spike, exp(-|10 (u - center) / width|)", true),
    O_TAKAGI_SUGENO("O-TAKAGI-SUGENO", ConformanceLevel.OPEN, "membership function, output",
            "Takagi-Sugeno output term: a value computed from the inputs (fuzzylite Constant, Linear, Function;"
                    + " jFuzzyLogic function), defuzzified as a weighted average", true),
    O_IMPLIED_RANGE("O-IMPLIED-RANGE", ConformanceLevel.OPEN, "range",
            "an output without RANGE whose universe the library implies from its terms (jFuzzyLogic)", true),
    O_UNNAMED_BLOCK("O-UNNAMED-BLOCK", ConformanceLevel.OPEN, "function block declaration",
            "a FUNCTION_BLOCK or RULEBLOCK without a name (fuzzylite, FFLL, jFuzzyLogic)", true),
    O_BLOCK_NAME_VERBATIM("O-BLOCK-NAME-VERBATIM", ConformanceLevel.OPEN, "function block declaration",
            "a block name with blanks or '-' (fuzzylite 5 wrote engine names verbatim)", true),
    O_DECLARATION_RANGE("O-DECLARATION-RANGE", ConformanceLevel.OPEN, "range",
            "'x : REAL; RANGE := (lo .. hi);' in a VAR section (jFuzzyLogic)", true),
    O_SPACED_ASSIGN("O-SPACED-ASSIGN", ConformanceLevel.OPEN, "function block declaration",
            "':=' written ': =' with a blank inside (FFLL's API sample)", true),
    O_TRAILING_TEXT("O-TRAILING-TEXT", ConformanceLevel.OPEN, "function block declaration",
            "text after the last END_FUNCTION_BLOCK, which the library ignores", true),
    O_UNPAIRED_OPERATORS("O-UNPAIRED-OPERATORS", ConformanceLevel.OPEN, "conditional aggregation",
            "AND and OR algorithms that are not a pair of Table 3, each evaluated as written (fuzzylite; jFuzzyLogic's"
                    + " HAMACHER with EINSTEIN)", true),
    O_OUTPUT_CONDITION("O-OUTPUT-CONDITION", ConformanceLevel.OPEN, "condition",
            "'output IS term' in a condition: the degree the term has reached so far in this evaluation (fuzzylite)",
            true),
    O_OUTPUT_VALUE_CONDITION("O-OUTPUT-VALUE-CONDITION", ConformanceLevel.OPEN, "condition",
            "'output IS term' in a condition: the term's degree at the output's value when the evaluation begins, its"
                    + " DEFAULT or (DEFAULT NC) its last value (jFuzzyLogic)", true),
    O_HEDGE_IN_CONCLUSION("O-HEDGE-IN-CONCLUSION", ConformanceLevel.OPEN, "conclusion",
            "hedges before a conclusion's term, applied to the rule's degree (fuzzylite: for every later"
                    + " subconclusion of the rule too)", true),
    O_OTHER_NORM("O-OTHER-NORM", ConformanceLevel.OPEN, "conditional aggregation",
            "AND / OR algorithms outside Table 3: Einstein, Hamacher, drastic and nilpotent norms", true),
    O_SHAPE_SINGLETONS("O-SHAPE-SINGLETONS", ConformanceLevel.OPEN, "membership function",
            "jFuzzyLogic 'singletons (x, 1)' written for a single singleton", true),
    O_SHAPE_DISCRETE("O-SHAPE-DISCRETE", ConformanceLevel.OPEN, "membership function",
            "fuzzylite 'Discrete x1 y1 x2 y2 ...', read as points", true),
    O_HEDGE_VERY("O-HEDGE-VERY", ConformanceLevel.OPEN, "hedge",
            "hedge 'very': the degree squared", true),
    O_HEDGE_SOMEWHAT("O-HEDGE-SOMEWHAT", ConformanceLevel.OPEN, "hedge",
            "hedge 'somewhat': the square root of the degree", true),
    O_HEDGE_EXTREMELY("O-HEDGE-EXTREMELY", ConformanceLevel.OPEN, "hedge",
            "hedge 'extremely': fuzzylite's contrast intensification", true),
    O_HEDGE_SELDOM("O-HEDGE-SELDOM", ConformanceLevel.OPEN, "hedge",
            "hedge 'seldom': fuzzylite's contrast dilution", true),
    O_HEDGE_ANY("O-HEDGE-ANY", ConformanceLevel.OPEN, "hedge",
            "'x is any': degree 1, no term", true),
    O_HEDGE_NOT("O-HEDGE-NOT", ConformanceLevel.OPEN, "hedge",
            "'not' as a hedge after another hedge ('very not small')", true),
    O_ACCU_PROBOR("O-ACCU-PROBOR", ConformanceLevel.OPEN, "accumulation",
            "ACCU probabilistic OR, a + b - ab (PROBOR, fuzzylite ASUM)", true),
    O_ACCU_SUM("O-ACCU-SUM", ConformanceLevel.OPEN, "accumulation",
            "ACCU unbounded sum (SUM)", true),
    O_ACT_OTHER_NORM("O-ACT-OTHER-NORM", ConformanceLevel.OPEN, "activation",
            "ACT by a t-norm outside Table 4: bounded difference, Einstein, Hamacher, drastic, nilpotent (fuzzylite)", true),
    O_ACCU_OTHER_NORM("O-ACCU-OTHER-NORM", ConformanceLevel.OPEN, "accumulation",
            "ACCU by an s-norm outside Table 5: Einstein, Hamacher, drastic sum, nilpotent maximum (fuzzylite)", true),
    O_TSUKAMOTO("O-TSUKAMOTO", ConformanceLevel.OPEN, "defuzzification method",
            "Tsukamoto's method: each monotonic term inverted at its degree, the weighted average of those points"
                    + " (fuzzylite's COGS on monotonic terms)", true),
    O_COGSS("O-COGSS", ConformanceLevel.OPEN, "defuzzification method",
            "METHOD COGSS, weighted sum of singletons (not divided)", true),
    O_METHOD_MM("O-METHOD-MM", ConformanceLevel.OPEN, "defuzzification method",
            "'MM', the jFuzzyLogic and fuzzylite spelling of mean of maximum", true),
    O_METHOD_COGF("O-METHOD-COGF", ConformanceLevel.OPEN, "defuzzification method",
            "jFuzzyLogic's 'COGF', read as CoG", true),
    O_COMMENT_STYLE("O-COMMENT-STYLE", ConformanceLevel.OPEN, "comments",
            "comments written '//', '/* */' or '#'", true),
    O_INPUT_RANGE("O-INPUT-RANGE", ConformanceLevel.OPEN, "range",
            "RANGE in a FUZZIFY block (no effect on evaluation)", true),
    O_INFINITE_RANGE("O-INFINITE-RANGE", ConformanceLevel.OPEN, "range",
            "RANGE with -inf or inf, read as no RANGE", true),
    O_ACCU_IN_DEFUZZIFY("O-ACCU-IN-DEFUZZIFY", ConformanceLevel.OPEN, "accumulation",
            "ACCU written in the DEFUZZIFY block (fuzzylite)", true),
    O_IMPLICIT_SETTING("O-IMPLICIT-SETTING", ConformanceLevel.OPEN, "defaults",
            "a setting left out that the dialect supplies (jFuzzyLogic ACCU SUM, METHOD CoG, DEFAULT NC)", true),
    O_ENABLED("O-ENABLED", ConformanceLevel.OPEN, "fuzzylite settings",
            "'ENABLED : TRUE;' (no effect)", true),
    O_LOCK_PREVIOUS("O-LOCK-PREVIOUS", ConformanceLevel.OPEN, "fuzzylite settings",
            "'LOCK : PREVIOUS': keep the previous output when nothing fired, read as DEFAULT NC", true),
    O_LOCK_RANGE("O-LOCK-RANGE", ConformanceLevel.OPEN, "fuzzylite settings",
            "'LOCK : RANGE': clamp the output to its RANGE", true),
    O_DEFAULT_NAN("O-DEFAULT-NAN", ConformanceLevel.OPEN, "default value",
            "'DEFAULT := nan': no number when nothing fired", true),
    O_RULE_WITHOUT_SEMICOLON("O-RULE-WITHOUT-SEMICOLON", ConformanceLevel.OPEN, "rule",
            "a rule not ended by ';' (fuzzylite)", true),
    O_CONCLUSION_AND("O-CONCLUSION-AND", ConformanceLevel.OPEN, "conclusion",
            "subconclusions joined by 'and' instead of ',' (fuzzylite)", true);

    private final String id;
    private final ConformanceLevel level;
    private final String element;
    private final String description;
    private final boolean dialectSyntax;

    Feature(String id, ConformanceLevel level, String element, String description) {
        this(id, level, element, description, false);
    }

    Feature(String id, ConformanceLevel level, String element, String description, boolean dialectSyntax) {
        this.id = id;
        this.level = level;
        this.element = element;
        this.description = description;
        this.dialectSyntax = dialectSyntax;
    }

    /**
     * True for an Open Level construct that only a dialect reader accepts (its syntax is not the standard's):
     * only a corpus case written in a dialect ({@code dialect:} in its metadata) can carry it, so the corpus
     * coverage rule does not ask for a case, and the reports show its row only where the corpus has one. False for
     * every Table 8 and 9 row and for Open Level features a standard-syntax program can carry (O-MANY-POINTS,
     * O-MOM, ...).
     */
    public boolean dialectSyntax() {
        return dialectSyntax;
    }

    /** Stable id, e.g. {@code E-ACCU-NSUM}. */
    public String id() {
        return id;
    }

    public ConformanceLevel level() {
        return level;
    }

    /** The table this row belongs to: 8, 9 or 10. */
    public int table() {
        return switch (level) {
            case BASIC -> 8;
            case EXTENSION -> 9;
            case OPEN -> 10;
        };
    }

    /** The language element column of the table row (e.g. "accumulation"). */
    public String element() {
        return element;
    }

    /** One line in fclcert's words. */
    public String description() {
        return description;
    }


    public static Optional<Feature> byId(String id) {
        return Arrays.stream(values()).filter(f -> f.id.equals(id)).findFirst();
    }
}
