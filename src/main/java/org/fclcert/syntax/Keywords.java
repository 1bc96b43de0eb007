package org.fclcert.syntax;

import java.util.Set;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ParseTree;

/** Facts about FCL's reserved words, for messages: how they are spelled and where they are reserved. */
final class Keywords {
    private static final Set<Integer> DATA_TYPES = Set.of(
            FclLexer.REAL, FclLexer.LREAL, FclLexer.SINT, FclLexer.INT, FclLexer.DINT, FclLexer.LINT,
            FclLexer.USINT, FclLexer.UINT, FclLexer.UDINT, FclLexer.ULINT);

    /** Words that open or close a block or a statement: a message about them names the structure. */
    private static final Set<Integer> STRUCTURAL = Set.of(
            FclLexer.FUNCTION_BLOCK, FclLexer.END_FUNCTION_BLOCK, FclLexer.VAR_INPUT, FclLexer.VAR_OUTPUT,
            FclLexer.VAR, FclLexer.END_VAR, FclLexer.FUZZIFY, FclLexer.END_FUZZIFY, FclLexer.DEFUZZIFY,
            FclLexer.END_DEFUZZIFY, FclLexer.RULEBLOCK, FclLexer.END_RULEBLOCK, FclLexer.OPTIONS,
            FclLexer.END_OPTIONS, FclLexer.OPTION, FclLexer.END_OPTION, FclLexer.TERM, FclLexer.RULE);

    /** The grammar's softKeyword rule: the keywords it takes where a name or a word stands. */
    private static final Set<Integer> SOFT = Set.of(
            FclLexer.RANGE, FclLexer.METHOD, FclLexer.DEFAULT, FclLexer.NC, FclLexer.ACT, FclLexer.ACCU,
            FclLexer.COG, FclLexer.COGS, FclLexer.COA, FclLexer.LM, FclLexer.RM,
            FclLexer.MIN, FclLexer.MAX, FclLexer.PROD, FclLexer.ASUM, FclLexer.BSUM, FclLexer.BDIF, FclLexer.NSUM,
            FclLexer.REAL, FclLexer.LREAL, FclLexer.SINT, FclLexer.INT, FclLexer.DINT, FclLexer.LINT,
            FclLexer.USINT, FclLexer.UINT, FclLexer.UDINT, FclLexer.ULINT);

    private static final boolean[] IS_SOFT = new boolean[FclLexer.VOCABULARY.getMaxTokenType() + 1];

    static {
        SOFT.forEach(type -> IS_SOFT[type] = true);
    }

    private Keywords() {
    }

    /** True for the keywords Fcl.g4's softKeyword rule lists ({@code KeywordsTest} holds the two together). */
    static boolean isSoft(int tokenType) {
        return tokenType >= 0 && tokenType < IS_SOFT.length && IS_SOFT[tokenType];
    }

    /** True for every word token the lexer treats as a keyword. */
    static boolean isKeyword(int tokenType) {
        return tokenType >= FclLexer.FUNCTION_BLOCK && tokenType <= FclLexer.ULINT;
    }

    static boolean isStructural(int tokenType) {
        return STRUCTURAL.contains(tokenType);
    }

    /** The keyword as the standard spells it, e.g. {@code CoGS} for {@code cogs}. */
    static String spelling(int tokenType) {
        String literal = FclLexer.VOCABULARY.getLiteralName(tokenType);
        return literal == null ? FclLexer.VOCABULARY.getSymbolicName(tokenType) : literal.substring(1, literal.length() - 1);
    }

    /** Where the keyword is reserved: Table 7, IEC 61131-3 (data types) or 5.4 (OPTION). */
    static String reservedBy(int tokenType) {
        if (DATA_TYPES.contains(tokenType)) {
            return "an IEC 61131-3 data type";
        }
        if (tokenType == FclLexer.OPTION || tokenType == FclLexer.END_OPTION) {
            return "5.4";
        }
        if (tokenType == FclLexer.VAR_INPUT || tokenType == FclLexer.VAR_OUTPUT || tokenType == FclLexer.VAR
                || tokenType == FclLexer.END_VAR || tokenType == FclLexer.FUNCTION_BLOCK
                || tokenType == FclLexer.END_FUNCTION_BLOCK) {
            return "Table 7, IEC 61131-3";
        }
        return "Table 7";
    }

    /** "'MAX' is a reserved keyword (Table 7) and cannot name a term". */
    static String reservedMessage(Token keyword, String role) {
        return "'" + spelling(keyword.getType()) + "' is a reserved keyword (" + reservedBy(keyword.getType())
                + ") and cannot name " + role;
    }

    /** What a name at this place in the tree would name: "a variable", "a term", "a rule block", ... */
    static String role(FclParser.NameContext name) {
        ParseTree parent = name.getParent();
        if (parent instanceof FclParser.FunctionBlockContext) {
            return "a function block";
        }
        if (parent instanceof FclParser.LinguisticTermContext) {
            return "a term";
        }
        if (parent instanceof FclParser.RuleBlockContext) {
            return "a rule block";
        }
        if (parent instanceof FclParser.RuleNameContext) {
            return "a rule";
        }
        if (parent instanceof FclParser.SubconditionContext s) {
            return s.variable == null || s.variable == name ? "a variable" : "a term";
        }
        if (parent instanceof FclParser.SubconclusionContext s) {
            return s.variable == null || s.variable == name ? "a variable" : "a term";
        }
        return "a variable";
    }
}
