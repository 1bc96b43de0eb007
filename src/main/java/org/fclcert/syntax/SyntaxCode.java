package org.fclcert.syntax;

import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;

/**
 * The stable diagnostic codes of the strict reader, one per kind of mistake: {@code FCL-Snnn}
 * errors and {@code FCL-W1nn} warnings (constructs accepted only because the standard is
 * inconsistent), and {@link #INTERNAL_ERROR}, the one code of an internal error of any reader (the dialect
 * readers report it too). docs/diagnostics.md lists the same table; a test keeps the two in step.
 */
public enum SyntaxCode implements DiagnosticCode {
    UNEXPECTED_CHARACTER("FCL-S001", "IEC 61131-3 B.1",
            "a character that is not part of FCL"),
    UNTERMINATED_COMMENT("FCL-S002", "IEC 61131-3 B.1.5.1",
            "a '(*' comment never closed by '*)'"),
    BAD_IDENTIFIER("FCL-S003", "IEC 61131-3 B.1.1",
            "an identifier with '__' or a trailing '_'"),
    BAD_NUMBER("FCL-S004", "IEC 61131-3 B.1.2",
            "a malformed or out-of-range numeric literal ('.5', '5.', '1E5', '1__0', '2#102', ...)"),
    EMPTY_PROGRAM("FCL-S005", "5.4",
            "the text holds no FUNCTION_BLOCK"),
    OUTSIDE_FUNCTION_BLOCK("FCL-S006", "5.4",
            "text outside FUNCTION_BLOCK ... END_FUNCTION_BLOCK"),
    RESERVED_KEYWORD("FCL-S007", "Table 7, IEC 61131-3",
            "a reserved keyword used as a name"),
    NESTING_TOO_DEEP("FCL-S008", "Table 11",
            "parentheses nested deeper than fclcert's documented limit (Limits.MAX_NESTING_DEPTH)"),
    NOT_ELEMENTARY_TYPE("FCL-S009", "5.2.1, IEC 61131-3 2.3.1",
            "a variable type that is not one of the elementary numeric types"),
    BODY_ORDER("FCL-S010", "5.4",
            "function block parts out of the 5.4 order (VAR_INPUT/VAR_OUTPUT, VAR, FUZZIFY, DEFUZZIFY, RULEBLOCK, OPTIONS)"),
    VARIABLE_DECLARATION("FCL-S011", "5.2.1",
            "malformed VAR_INPUT / VAR_OUTPUT / VAR section or declaration"),
    FUZZIFY_BLOCK("FCL-S012", "5.2.2",
            "malformed FUZZIFY block"),
    DEFUZZIFY_BLOCK("FCL-S013", "5.2.3",
            "malformed DEFUZZIFY block or its items out of order"),
    TERM_DEFINITION("FCL-S014", "5.2.2",
            "malformed TERM definition"),
    POINT("FCL-S015", "5.2.2",
            "malformed point '(x, degree)'"),
    RANGE("FCL-S016", "5.2.3",
            "malformed RANGE"),
    METHOD("FCL-S017", "Table 1",
            "malformed METHOD or unknown defuzzification method"),
    DEFAULT("FCL-S018", "5.2.3",
            "malformed DEFAULT"),
    RULE_BLOCK("FCL-S019", "5.2.4",
            "malformed RULEBLOCK or its items out of order"),
    OPERATOR_DEFINITION("FCL-S020", "Table 3",
            "malformed AND:/OR: definition or unknown algorithm"),
    ACTIVATION("FCL-S021", "Table 4",
            "malformed ACT: or unknown activation method"),
    ACCUMULATION("FCL-S022", "Table 5",
            "malformed ACCU: or unknown accumulation method"),
    RULE_HEADER("FCL-S023", "5.2.4",
            "malformed 'RULE name : IF'"),
    CONDITION("FCL-S024", "5.2.4, Table 6",
            "malformed condition"),
    EQUALS_IN_CONDITION("FCL-S025", "Annex D",
            "'=' in a condition, where FCL writes 'variable IS term'"),
    DOUBLE_NOT("FCL-S026", "5.4",
            "NOT directly after NOT (5.4 allows one NOT per subcondition or parenthesis)"),
    CONCLUSION("FCL-S027", "5.2.4",
            "malformed conclusion"),
    OPERATOR_IN_CONCLUSION("FCL-S028", "Annex D",
            "AND or OR between subconclusions, which are separated by ','"),
    WEIGHTING_FACTOR("FCL-S029", "5.2.4",
            "malformed WITH weighting factor"),
    OPTIONS_BLOCK("FCL-S030", "5.2.5",
            "malformed or unclosed OPTIONS block"),
    GLUED_RULE_NUMBER("FCL-S031", "Annex D",
            "'RULE1' written without a space, read as one identifier"),
    DUPLICATE_SETTING("FCL-S032", "5.4",
            "a setting given twice in one block (RANGE, METHOD, DEFAULT, AND, OR, ACT, ACCU)"),
    WRONG_END_KEYWORD("FCL-S033", "5.4",
            "a block closed by another block's END keyword (e.g. DEFUZZIFY ... END_FUZZIFY)"),
    FUNCTION_BLOCK("FCL-S034", "5.4",
            "malformed FUNCTION_BLOCK header or end"),
    UNEXPECTED_END("FCL-S035", "5.4",
            "the text ends inside a block"),
    TOO_MANY_ERRORS("FCL-S099", "—",
            "more syntax errors than the reader reports (the rest are summarised)"),
    INTERNAL_ERROR("FCL-S999", "—",
            "an internal error of a reader, strict or dialect (a bug in fclcert; please report it)"),

    DRAFT_DEFUZZIFY_ORDER("FCL-W101", "5.2.3, 5.4",
            "DEFUZZIFY with RANGE last, the 1996 draft's order (5.4 puts RANGE first)"),
    OPTION_SPELLING("FCL-W102", "5.2.5, 5.4, Table 7",
            "OPTION / END_OPTION as 5.4 spells them, where 5.2.5 and Table 7 write OPTIONS / END_OPTIONS"),
    RANGE_ASSIGNMENT("FCL-W103", "5.2.3, 5.4",
            "'RANGE := (...)' as 5.2.3's prose writes it, where the 5.4 production writes 'RANGE (...)'"),
    RULE_NAMED_BY_IDENTIFIER("FCL-W104", "5.2.4, 5.4",
            "a rule named by an identifier (5.2.4 prose), where 5.4 requires a number"),
    WITH_AFTER_LAST_SUBCONCLUSION("FCL-W105", "5.2.4",
            "WITH after the last of several subconclusions; fclcert weights that subconclusion only (5.2.4)"),
    NESTED_COMMENT_OPENER("FCL-W106", "IEC 61131-3 B.1.5.1",
            "'(*' inside a comment; comments do not nest, the first '*)' ends it");

    private final Entry entry;

    /** Warnings for {@code FCL-W1nn}, errors otherwise. */
    SyntaxCode(String code, String clause, String meaning) {
        this.entry = new Entry(code, code.startsWith("FCL-W") ? Severity.WARNING : Severity.ERROR, clause, meaning);
    }

    @Override
    public Entry entry() {
        return entry;
    }

    public boolean isWarning() {
        return severity() == Severity.WARNING;
    }
}
