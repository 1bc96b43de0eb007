package org.fclcert.syntax;

/**
 * The stable diagnostic codes of the strict reader, one per kind of mistake: {@code FCL-Snnn}
 * errors and {@code FCL-W1nn} warnings (constructs accepted only because the standard is
 * inconsistent). docs/diagnostics.md lists the same table; a test keeps the two in step.
 */
public enum SyntaxCode {
    UNEXPECTED_CHARACTER("FCL-S001", "a character that is not part of FCL (IEC 61131-3 B.1)"),
    UNTERMINATED_COMMENT("FCL-S002", "a '(*' comment never closed by '*)'"),
    BAD_IDENTIFIER("FCL-S003", "an identifier with '__' or a trailing '_' (IEC 61131-3 B.1.1)"),
    BAD_NUMBER("FCL-S004", "a malformed or out-of-range numeric literal ('.5', '5.', '1E5', '1__0', '2#102', ...)"),
    EMPTY_PROGRAM("FCL-S005", "the text holds no FUNCTION_BLOCK"),
    OUTSIDE_FUNCTION_BLOCK("FCL-S006", "text outside FUNCTION_BLOCK ... END_FUNCTION_BLOCK"),
    RESERVED_KEYWORD("FCL-S007", "a reserved keyword (Table 7, IEC 61131-3) used as a name"),
    NESTING_TOO_DEEP("FCL-S008", "parentheses nested deeper than fclcert's documented limit (Limits.MAX_NESTING_DEPTH)"),
    NOT_ELEMENTARY_TYPE("FCL-S009", "a variable type that is not one of the elementary numeric types"),
    BODY_ORDER("FCL-S010", "function block parts out of the 5.4 order (VAR_INPUT/VAR_OUTPUT, VAR, FUZZIFY, DEFUZZIFY, RULEBLOCK, OPTIONS)"),
    VARIABLE_DECLARATION("FCL-S011", "malformed VAR_INPUT / VAR_OUTPUT / VAR section or declaration (5.2.1)"),
    FUZZIFY_BLOCK("FCL-S012", "malformed FUZZIFY block (5.2.2)"),
    DEFUZZIFY_BLOCK("FCL-S013", "malformed DEFUZZIFY block or its items out of order (5.2.3)"),
    TERM_DEFINITION("FCL-S014", "malformed TERM definition (5.2.2)"),
    POINT("FCL-S015", "malformed point '(x, degree)' (5.2.2)"),
    RANGE("FCL-S016", "malformed RANGE (5.2.3)"),
    METHOD("FCL-S017", "malformed METHOD or unknown defuzzification method (Table 1)"),
    DEFAULT("FCL-S018", "malformed DEFAULT (5.2.3)"),
    RULE_BLOCK("FCL-S019", "malformed RULEBLOCK or its items out of order (5.2.4)"),
    OPERATOR_DEFINITION("FCL-S020", "malformed AND:/OR: definition or unknown algorithm (Table 3)"),
    ACTIVATION("FCL-S021", "malformed ACT: or unknown activation method (Table 4)"),
    ACCUMULATION("FCL-S022", "malformed ACCU: or unknown accumulation method (Table 5)"),
    RULE_HEADER("FCL-S023", "malformed 'RULE name : IF' (5.2.4)"),
    CONDITION("FCL-S024", "malformed condition (5.2.4, Table 6)"),
    EQUALS_IN_CONDITION("FCL-S025", "'=' in a condition, where FCL writes 'variable IS term' (Annex D)"),
    DOUBLE_NOT("FCL-S026", "NOT directly after NOT (5.4 allows one NOT per subcondition or parenthesis)"),
    CONCLUSION("FCL-S027", "malformed conclusion (5.2.4)"),
    OPERATOR_IN_CONCLUSION("FCL-S028", "AND or OR between subconclusions, which are separated by ',' (Annex D)"),
    WEIGHTING_FACTOR("FCL-S029", "malformed WITH weighting factor (5.2.4)"),
    OPTIONS_BLOCK("FCL-S030", "malformed or unclosed OPTIONS block (5.2.5)"),
    GLUED_RULE_NUMBER("FCL-S031", "'RULE1' written without a space, read as one identifier (Annex D)"),
    DUPLICATE_SETTING("FCL-S032", "a setting given twice in one block (RANGE, METHOD, DEFAULT, AND, OR, ACT, ACCU)"),
    WRONG_END_KEYWORD("FCL-S033", "a block closed by another block's END keyword (e.g. DEFUZZIFY ... END_FUZZIFY)"),
    FUNCTION_BLOCK("FCL-S034", "malformed FUNCTION_BLOCK header or end"),
    UNEXPECTED_END("FCL-S035", "the text ends inside a block"),
    TOO_MANY_ERRORS("FCL-S099", "more syntax errors than the reader reports (the rest are summarised)"),
    INTERNAL_ERROR("FCL-S999", "an internal error of the reader (a bug in fclcert; please report it)"),

    DRAFT_DEFUZZIFY_ORDER("FCL-W101", "DEFUZZIFY with RANGE last, the 1996 draft's order (5.4 puts RANGE first)"),
    OPTION_SPELLING("FCL-W102", "OPTION / END_OPTION as 5.4 spells them, where 5.2.5 and Table 7 write OPTIONS / END_OPTIONS"),
    RANGE_ASSIGNMENT("FCL-W103", "'RANGE := (...)' as 5.2.3's prose writes it, where the 5.4 production writes 'RANGE (...)'"),
    RULE_NAMED_BY_IDENTIFIER("FCL-W104", "a rule named by an identifier (5.2.4 prose), where 5.4 requires a number"),
    WITH_AFTER_LAST_SUBCONCLUSION("FCL-W105", "WITH after the last of several subconclusions; fclcert weights that subconclusion only (5.2.4)"),
    NESTED_COMMENT_OPENER("FCL-W106", "'(*' inside a comment; comments do not nest, the first '*)' ends it");

    private final String code;
    private final String meaning;

    SyntaxCode(String code, String meaning) {
        this.code = code;
        this.meaning = meaning;
    }

    /** The stable code, e.g. {@code FCL-S014}. */
    public String code() {
        return code;
    }

    /** One line saying what the code means. */
    public String meaning() {
        return meaning;
    }

    public boolean isWarning() {
        return code.startsWith("FCL-W");
    }
}
