package org.fclcert.lsp;

import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fclcert.syntax.SyntaxCode;

/**
 * For hover on a keyword: the clause or table of IEC 61131-7 that defines it and what it means, in one line of
 * fclcert's own words. The clause of a setting is the clause its syntax diagnostic cites ({@link SyntaxCode}),
 * so the two never disagree.
 */
final class KeywordHelp {
    record Help(String clause, String meaning) {
    }

    private static final Map<String, Help> HELP = Map.ofEntries(
            entry("FUNCTION_BLOCK", "5.2.1, 5.4", "opens a fuzzy function block: its interface, fuzzification, rules and defuzzification"),
            entry("END_FUNCTION_BLOCK", "5.4", "closes the function block"),
            entry("VAR_INPUT", "5.2.1", "declares the input variables, the crisp values the block fuzzifies"),
            entry("VAR_OUTPUT", "5.2.1", "declares the output variables, the crisp values the block defuzzifies"),
            entry("VAR", "5.2.1", "declares local variables"),
            entry("END_VAR", "5.2.1", "closes a variable section"),
            entry("FUZZIFY", "5.2.2", "the linguistic terms of an input variable (fuzzification)"),
            entry("END_FUZZIFY", "5.2.2", "closes a FUZZIFY block"),
            entry("DEFUZZIFY", "5.2.3", "the terms, range, method and default of an output variable (defuzzification)"),
            entry("END_DEFUZZIFY", "5.2.3", "closes a DEFUZZIFY block"),
            entry("TERM", "5.2.2, 5.2.3", "a linguistic term and its membership function (points or a singleton)"),
            entry("RANGE", SyntaxCode.RANGE.clause(), "the interval of values an output may take"),
            entry("METHOD", SyntaxCode.METHOD.clause(), "the defuzzification method of the output"),
            entry("DEFAULT", SyntaxCode.DEFAULT.clause(), "the output's value when no rule fires (a value, or NC: no change)"),
            entry("NC", SyntaxCode.DEFAULT.clause(), "as DEFAULT: the output keeps its previous value when no rule fires"),
            entry("COG", SyntaxCode.METHOD.clause(), "centre of gravity of the accumulated set"),
            entry("COGS", SyntaxCode.METHOD.clause(), "centre of gravity for singletons: the weighted mean of their values"),
            entry("COA", SyntaxCode.METHOD.clause(), "centre of area: the value that halves the area of the accumulated set"),
            entry("LM", SyntaxCode.METHOD.clause(), "left-most maximum of the accumulated set"),
            entry("RM", SyntaxCode.METHOD.clause(), "right-most maximum of the accumulated set"),
            entry("RULEBLOCK", "5.2.4", "a block of rules with its operators, activation and accumulation"),
            entry("END_RULEBLOCK", "5.2.4", "closes a rule block"),
            entry("AND", SyntaxCode.OPERATOR_DEFINITION.clause() + ", Table 6",
                    "conjunction of subconditions; 'AND : algorithm' picks its t-norm, the OR paired with it"),
            entry("OR", SyntaxCode.OPERATOR_DEFINITION.clause() + ", Table 6",
                    "disjunction of subconditions; 'OR : algorithm' picks its s-norm, the AND paired with it"),
            entry("NOT", "Table 6, Table 9", "complement of a degree: 1 minus it"),
            entry("ACT", SyntaxCode.ACTIVATION.clause(), "the activation method: how a rule's degree cuts its conclusion's term"),
            entry("ACCU", SyntaxCode.ACCUMULATION.clause(), "the accumulation method: how the activated terms of an output are combined"),
            entry("MIN", "Table 3, Table 4", "minimum (AND with MAX; activation by clipping)"),
            entry("MAX", "Table 3, Table 5", "maximum (OR with MIN; accumulation)"),
            entry("PROD", "Table 3, Table 4", "algebraic product (AND with ASUM; activation by scaling)"),
            entry("ASUM", "Table 3", "algebraic sum a + b - ab (OR with PROD)"),
            entry("BDIF", "Table 3", "bounded difference max(0, a + b - 1) (AND with BSUM)"),
            entry("BSUM", "Table 3, Table 5", "bounded sum min(1, a + b) (OR with BDIF; accumulation)"),
            entry("NSUM", "Table 5", "normalised sum: accumulation by the sum divided by max(1, largest sum)"),
            entry("RULE", "5.2.4", "a rule: RULE number : IF condition THEN conclusion;"),
            entry("IF", "5.2.4", "starts a rule's condition"),
            entry("THEN", "5.2.4", "starts a rule's conclusion: one or more subconclusions separated by ','"),
            entry("IS", "5.2.4", "'variable IS term': the degree of membership of the variable in the term"),
            entry("WITH", "5.2.4", "the weighting factor of a subconclusion, in [0, 1]"),
            entry("OPTIONS", "5.2.5", "manufacturer-specific options, outside what the standard defines"),
            entry("END_OPTIONS", "5.2.5", "closes an OPTIONS block"),
            entry("REAL", "5.2.1, IEC 61131-3", "32-bit floating-point type"),
            entry("LREAL", "5.2.1, IEC 61131-3", "64-bit floating-point type"),
            entry("SINT", "5.2.1, IEC 61131-3", "8-bit signed integer type"),
            entry("INT", "5.2.1, IEC 61131-3", "16-bit signed integer type"),
            entry("DINT", "5.2.1, IEC 61131-3", "32-bit signed integer type"),
            entry("LINT", "5.2.1, IEC 61131-3", "64-bit signed integer type"),
            entry("USINT", "5.2.1, IEC 61131-3", "8-bit unsigned integer type"),
            entry("UINT", "5.2.1, IEC 61131-3", "16-bit unsigned integer type"),
            entry("UDINT", "5.2.1, IEC 61131-3", "32-bit unsigned integer type"),
            entry("ULINT", "5.2.1, IEC 61131-3", "64-bit unsigned integer type"));

    private KeywordHelp() {
    }

    private static Map.Entry<String, Help> entry(String keyword, String clause, String meaning) {
        return Map.entry(keyword, new Help(clause, meaning));
    }

    static Optional<Help> of(String keyword) {
        return Optional.ofNullable(HELP.get(keyword.toUpperCase(Locale.ROOT)));
    }
}
