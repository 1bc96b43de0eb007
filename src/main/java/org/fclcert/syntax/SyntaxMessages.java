package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.misc.IntervalSet;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * Turns the parser's state at a syntax error (the rule it is in, what it has read so far, the tokens
 * it could accept, the token it found) into a sentence for a person, with the code of that kind of
 * mistake: {@code expected ';' after the term's membership function (5.2.2), found 'TERM'}.
 */
final class SyntaxMessages {
    private static final Pattern GLUED_RULE = Pattern.compile("RULE[0-9]+", Pattern.CASE_INSENSITIVE);
    private static final int MAX_LISTED = 8;
    private static final int MAX_SHOWN_TEXT = 40;

    record Message(SyntaxCode code, String text) {
    }

    private record Region(SyntaxCode code, String clause) {
    }

    private SyntaxMessages() {
    }

    static Message describe(ParserRuleContext ctx, Token offending, IntervalSet expected, List<Token> tokens) {
        int type = offending.getType();
        if (ctx instanceof FclParser.OptionBlockContext options) {
            return new Message(SyntaxCode.OPTIONS_BLOCK, "the OPTIONS block that starts at line "
                    + options.getStart().getLine() + " is not closed: expected END_OPTIONS before " + found(offending)
                    + " (5.2.5)");
        }
        if (type == Token.EOF) {
            return unexpectedEnd(ctx, expected);
        }
        if (type == FclLexer.EQUALS && within(ctx, FclParser.RULE_fuzzyRule)) {
            return new Message(SyntaxCode.EQUALS_IN_CONDITION,
                    "'=' is not FCL: a subcondition is 'variable IS term' or a bare variable (5.2.4)");
        }
        if ((type == FclLexer.AND || type == FclLexer.OR) && inConclusion(ctx)) {
            return new Message(SyntaxCode.OPERATOR_IN_CONCLUSION,
                    "subconclusions are separated by ',' (5.2.4), not " + Keywords.spelling(type));
        }
        if (type == FclLexer.NOT && previousType(offending, tokens) == FclLexer.NOT) {
            return new Message(SyntaxCode.DOUBLE_NOT, "NOT cannot follow NOT: 5.4 allows one NOT before a"
                    + " subcondition or a parenthesised condition; write NOT (NOT ...) if you mean it");
        }
        if (type == FclLexer.IDENT && GLUED_RULE.matcher(offending.getText()).matches()
                && expected.contains(FclLexer.RULE)) {
            return new Message(SyntaxCode.GLUED_RULE_NUMBER, "'" + offending.getText() + "' is read as one name;"
                    + " a rule starts with the keyword RULE, a space and its number: write 'RULE "
                    + offending.getText().substring(4) + "' (5.2.4)");
        }
        // a keyword followed by what follows a name (':', ':=', ...) was meant as a name
        if (Keywords.isKeyword(type) && expected.contains(FclLexer.IDENT) && followsName(nextType(offending, tokens))) {
            return new Message(SyntaxCode.RESERVED_KEYWORD, Keywords.reservedMessage(offending, roleAt(ctx)));
        }
        return generic(ctx, offending, expected);
    }

    private static Message generic(ParserRuleContext ctx, Token offending, IntervalSet expected) {
        if (ctx instanceof FclParser.ProgramContext) {
            return new Message(SyntaxCode.OUTSIDE_FUNCTION_BLOCK, "expected FUNCTION_BLOCK"
                    + (ctx.getChildCount() > 0 ? " or the end of the text after END_FUNCTION_BLOCK" : "")
                    + ", found " + found(offending) + ": everything in FCL stands inside"
                    + " FUNCTION_BLOCK ... END_FUNCTION_BLOCK (5.4)");
        }
        Region region = region(ctx);
        String after = after(ctx);
        String text = "expected " + expectedPhrase(ctx, expected)
                + (after == null ? "" : " after " + after)
                + " (" + region.clause() + "), found " + found(offending) + hint(ctx, offending);
        return new Message(region.code(), text);
    }

    /** A word about mistakes other FCL dialects make likely. */
    private static String hint(ParserRuleContext ctx, Token offending) {
        int type = offending.getType();
        if ((type == FclLexer.ACCU || type == FclLexer.ACT) && within(ctx, FclParser.RULE_defuzzifyBlock)) {
            return "; ACCU and ACT belong in a RULEBLOCK (5.2.4)";
        }
        boolean number = type == FclLexer.INTEGER || type == FclLexer.REAL_LITERAL || type == FclLexer.BASED_INTEGER;
        if (number && ctx instanceof FclParser.LinguisticTermContext term
                && term.membershipFunction() instanceof FclParser.SingletonFunctionContext s
                && s.operand().name() != null) {
            return "; named shapes such as '" + s.operand().getText() + "' are not FCL: a membership function is"
                    + " a singleton value or points (x, degree) (5.2.2)";
        }
        return "";
    }

    private static Message unexpectedEnd(ParserRuleContext ctx, IntervalSet expected) {
        for (ParserRuleContext c = ctx; c != null; c = c.getParent()) {
            String block = blockName(c);
            if (block != null) {
                return new Message(SyntaxCode.UNEXPECTED_END, "the text ends inside the " + block
                        + " that starts at line " + c.getStart().getLine() + ": expected "
                        + expectedPhrase(ctx, expected));
            }
        }
        return new Message(SyntaxCode.UNEXPECTED_END, "the text ends too early: expected " + expectedPhrase(ctx, expected));
    }

    private static String blockName(ParserRuleContext c) {
        if (c instanceof FclParser.FuzzyRuleContext) {
            return "rule";
        }
        if (c instanceof FclParser.OptionBlockContext) {
            return "OPTIONS block";
        }
        if (c instanceof FclParser.RuleBlockContext) {
            return "RULEBLOCK";
        }
        if (c instanceof FclParser.DefuzzifyBlockContext) {
            return "DEFUZZIFY block";
        }
        if (c instanceof FclParser.FuzzifyBlockContext) {
            return "FUZZIFY block";
        }
        if (c instanceof FclParser.VarSectionContext v) {
            return v.kind.getText().toUpperCase(java.util.Locale.ROOT) + " section";
        }
        if (c instanceof FclParser.FunctionBlockContext) {
            return "FUNCTION_BLOCK";
        }
        return null;
    }

    private static boolean within(ParserRuleContext ctx, int ruleIndex) {
        for (ParserRuleContext c = ctx; c != null; c = c.getParent()) {
            if (c.getRuleIndex() == ruleIndex) {
                return true;
            }
        }
        return false;
    }

    private static boolean inConclusion(ParserRuleContext ctx) {
        if (within(ctx, FclParser.RULE_conclusion)) {
            return true;
        }
        return ctx instanceof FclParser.FuzzyRuleContext r && r.conclusion() != null;
    }

    /** Tokens that stand after a name: if one follows the keyword, the keyword was meant as a name. */
    static boolean followsName(int type) {
        return type == FclLexer.ASSIGN || type == FclLexer.COLON || type == FclLexer.COMMA || type == FclLexer.SEMI
                || type == FclLexer.RPAREN || type == FclLexer.IS;
    }

    private static int nextType(Token t, List<Token> tokens) {
        int i = t.getTokenIndex();
        return i >= 0 && i + 1 < tokens.size() ? tokens.get(i + 1).getType() : Token.INVALID_TYPE;
    }

    private static int previousType(Token t, List<Token> tokens) {
        int i = t.getTokenIndex();
        return i > 0 && i - 1 < tokens.size() ? tokens.get(i - 1).getType() : Token.INVALID_TYPE;
    }

    private static String roleAt(ParserRuleContext ctx) {
        if (ctx instanceof FclParser.NameContext n) {
            return Keywords.role(n);
        }
        if (ctx instanceof FclParser.RuleNameContext) {
            return "a rule";
        }
        if (ctx instanceof FclParser.LinguisticTermContext) {
            return "a term";
        }
        if (ctx instanceof FclParser.RuleBlockContext) {
            return "a rule block";
        }
        if (ctx instanceof FclParser.FunctionBlockContext) {
            return "a function block";
        }
        if (ctx instanceof FclParser.SubconditionContext s && s.variable != null) {
            return "a term";
        }
        if (ctx instanceof FclParser.SubconclusionContext s && s.variable != null && s.WITH() == null) {
            return "a term";
        }
        return "a variable";
    }

    private static Region region(ParserRuleContext ctx) {
        switch (ctx.getRuleIndex()) {
            case FclParser.RULE_program:
                return new Region(SyntaxCode.OUTSIDE_FUNCTION_BLOCK, "5.4");
            case FclParser.RULE_functionBlock, FclParser.RULE_fbItem:
                return new Region(SyntaxCode.FUNCTION_BLOCK, "5.2.1, 5.4");
            case FclParser.RULE_varSection, FclParser.RULE_varDeclaration, FclParser.RULE_typeName:
                return new Region(SyntaxCode.VARIABLE_DECLARATION, "5.2.1");
            case FclParser.RULE_fuzzifyBlock:
                return new Region(SyntaxCode.FUZZIFY_BLOCK, "5.2.2");
            case FclParser.RULE_linguisticTerm, FclParser.RULE_membershipFunction:
                return new Region(SyntaxCode.TERM_DEFINITION, "5.2.2");
            case FclParser.RULE_point:
                return new Region(SyntaxCode.POINT, "5.2.2");
            case FclParser.RULE_defuzzifyBlock, FclParser.RULE_defuzzifyItem:
                return new Region(SyntaxCode.DEFUZZIFY_BLOCK, "5.2.3");
            case FclParser.RULE_range:
                return new Region(SyntaxCode.RANGE, "5.2.3");
            case FclParser.RULE_defuzzificationMethod:
                return new Region(SyntaxCode.METHOD, "5.2.3, Table 1");
            case FclParser.RULE_defaultValue:
                return new Region(SyntaxCode.DEFAULT, "5.2.3");
            case FclParser.RULE_ruleBlock, FclParser.RULE_ruleBlockItem:
                return new Region(SyntaxCode.RULE_BLOCK, "5.2.4");
            case FclParser.RULE_operatorDefinition:
                return new Region(SyntaxCode.OPERATOR_DEFINITION, "5.2.4, Table 3");
            case FclParser.RULE_activationMethod:
                return new Region(SyntaxCode.ACTIVATION, "5.2.4, Table 4");
            case FclParser.RULE_accumulationMethod:
                return new Region(SyntaxCode.ACCUMULATION, "5.2.4, Table 5");
            case FclParser.RULE_fuzzyRule:
                return ruleRegion((FclParser.FuzzyRuleContext) ctx);
            case FclParser.RULE_ruleName:
                return new Region(SyntaxCode.RULE_HEADER, "5.2.4");
            case FclParser.RULE_condition, FclParser.RULE_conjunction, FclParser.RULE_factor,
                    FclParser.RULE_subcondition:
                return new Region(SyntaxCode.CONDITION, "5.2.4");
            case FclParser.RULE_conclusion:
                return new Region(SyntaxCode.CONCLUSION, "5.2.4");
            case FclParser.RULE_subconclusion:
                return ((FclParser.SubconclusionContext) ctx).WITH() != null
                        ? new Region(SyntaxCode.WEIGHTING_FACTOR, "5.2.4")
                        : new Region(SyntaxCode.CONCLUSION, "5.2.4");
            case FclParser.RULE_optionBlock:
                return new Region(SyntaxCode.OPTIONS_BLOCK, "5.2.5");
            default:
                // name, word, softKeyword, literal, operand: the construct they belong to
                ParserRuleContext parent = ctx.getParent();
                return parent == null ? new Region(SyntaxCode.OUTSIDE_FUNCTION_BLOCK, "5.4") : region(parent);
        }
    }

    private static Region ruleRegion(FclParser.FuzzyRuleContext rule) {
        if (rule.conclusion() != null) {
            return new Region(SyntaxCode.CONCLUSION, "5.2.4");
        }
        if (rule.condition() != null) {
            return new Region(SyntaxCode.CONDITION, "5.2.4");
        }
        return new Region(SyntaxCode.RULE_HEADER, "5.2.4");
    }

    /** The last thing read before the error, e.g. "the term's membership function" or "'IS'". */
    private static String after(ParserRuleContext ctx) {
        ParseTree skip = null;
        for (ParserRuleContext c = ctx; c != null; skip = c, c = c.getParent()) {
            if (c.children == null) {
                continue;
            }
            int i = c.children.size() - 1;
            if (skip != null) {
                while (i >= 0 && c.children.get(i) != skip) {
                    i--;
                }
                i--;
            }
            for (; i >= 0; i--) {
                String d = describeElement(c.children.get(i));
                if (d != null) {
                    return d;
                }
            }
        }
        return null;
    }

    private static String describeElement(ParseTree node) {
        if (node instanceof TerminalNode t) {
            Token token = t.getSymbol();
            if (token.getTokenIndex() < 0 || token.getType() == Token.EOF) {
                return null;   // a token conjured by error recovery
            }
            return show(token);
        }
        if (!(node instanceof ParserRuleContext c) || c.exception != null) {
            return null;
        }
        if (c.getChildCount() == 0) {
            // a completed part the reader built early and dropped the subtree of (ModelBuilder.buildWhile)
            Token start = c.getStart();
            Token stop = c.getStop();
            if (stop == null || start == null || stop.getTokenIndex() < start.getTokenIndex()) {
                return null;
            }
            String block = blockName(c);
            return block != null ? "the " + block : "'" + shorten(stop.getText()) + "'";
        }
        if (c instanceof FclParser.MembershipFunctionContext) {
            return "the term's membership function";
        }
        if (c instanceof FclParser.ConditionContext || c instanceof FclParser.ConjunctionContext
                || c instanceof FclParser.FactorContext) {
            return "the condition";
        }
        if (c instanceof FclParser.SubconditionContext) {
            return "the subcondition";
        }
        if (c instanceof FclParser.ConclusionContext) {
            return "the conclusion";
        }
        if (c instanceof FclParser.SubconclusionContext) {
            return "the subconclusion";
        }
        if (c instanceof FclParser.PointContext) {
            return "the point";
        }
        if (c instanceof FclParser.NameContext || c instanceof FclParser.WordContext
                || c instanceof FclParser.TypeNameContext || c instanceof FclParser.LiteralContext
                || c instanceof FclParser.OperandContext || c instanceof FclParser.RuleNameContext
                || c instanceof FclParser.SoftKeywordContext) {
            return show(c.getStart());
        }
        String block = blockName(c);
        if (block != null) {
            return "the " + block;
        }
        if (c.getChildCount() == 1) {
            return describeElement(c.getChild(0));
        }
        return "'" + shorten(c.getStop() == null ? "" : c.getStop().getText()) + "'";
    }

    private static String expectedPhrase(ParserRuleContext ctx, IntervalSet expected) {
        boolean name = expected.contains(FclLexer.IDENT);
        if (name) {
            String specific = specificWord(ctx);
            if (specific != null) {
                return specific;
            }
        }
        if (expected.contains(FclLexer.END_FUNCTION_BLOCK) && expected.contains(FclLexer.FUZZIFY)) {
            return "a VAR_INPUT, VAR_OUTPUT or VAR section, a FUZZIFY, DEFUZZIFY, RULEBLOCK or OPTIONS block,"
                    + " or END_FUNCTION_BLOCK";
        }
        List<String> items = new ArrayList<>();
        if (name) {
            items.add(roleAt(ctx) + " name");
        }
        if (expected.contains(FclLexer.INTEGER) || expected.contains(FclLexer.REAL_LITERAL)) {
            items.add("a number");
        }
        boolean inDefuzzify = within(ctx, FclParser.RULE_defuzzifyBlock);
        for (int type : expected.toList()) {
            if (type == FclLexer.IDENT || type == FclLexer.INTEGER || type == FclLexer.REAL_LITERAL
                    || type == FclLexer.BASED_INTEGER || type == Token.EPSILON || (name && softKeyword(type))) {
                continue;
            }
            // spellings accepted only to be reported (the draft's END_FUZZIFY, 5.4's OPTION) are not advertised
            if (type == FclLexer.OPTION || type == FclLexer.END_OPTION || type == FclLexer.END_FUZZIFY && inDefuzzify) {
                continue;
            }
            items.add(type == Token.EOF ? "the end of the text" : "'" + Keywords.spelling(type) + "'");
        }
        return joinAlternatives(items);
    }

    /** Where a word names a type, an algorithm or a method, say which words fit. */
    private static String specificWord(ParserRuleContext ctx) {
        ParserRuleContext c = ctx instanceof FclParser.WordContext ? ctx.getParent() : ctx;
        if (c instanceof FclParser.TypeNameContext) {
            return "a data type (REAL, LREAL, SINT, INT, DINT, LINT, USINT, UINT, UDINT or ULINT)";
        }
        if (c instanceof FclParser.DefuzzificationMethodContext) {
            return "a defuzzification method (CoG, CoGS, CoA, LM or RM)";
        }
        if (c instanceof FclParser.OperatorDefinitionContext) {
            return "an algorithm (AND: MIN, PROD or BDIF; OR: MAX, ASUM or BSUM)";
        }
        if (c instanceof FclParser.ActivationMethodContext) {
            return "an activation method (MIN or PROD)";
        }
        if (c instanceof FclParser.AccumulationMethodContext) {
            return "an accumulation method (MAX, BSUM or NSUM)";
        }
        return null;
    }

    private static boolean softKeyword(int type) {
        return Keywords.isKeyword(type) && !Keywords.isStructural(type) && isSoft(type);
    }

    private static boolean isSoft(int type) {
        return switch (type) {
            case FclLexer.RANGE, FclLexer.METHOD, FclLexer.DEFAULT, FclLexer.NC, FclLexer.ACT, FclLexer.ACCU,
                    FclLexer.COG, FclLexer.COGS, FclLexer.COA, FclLexer.LM, FclLexer.RM, FclLexer.MIN, FclLexer.MAX,
                    FclLexer.PROD, FclLexer.ASUM, FclLexer.BSUM, FclLexer.BDIF, FclLexer.NSUM, FclLexer.REAL,
                    FclLexer.LREAL, FclLexer.SINT, FclLexer.INT, FclLexer.DINT, FclLexer.LINT, FclLexer.USINT,
                    FclLexer.UINT, FclLexer.UDINT, FclLexer.ULINT -> true;
            default -> false;
        };
    }

    private static String joinAlternatives(List<String> items) {
        if (items.isEmpty()) {
            return "something else";
        }
        List<String> shown = items.size() > MAX_LISTED ? items.subList(0, MAX_LISTED) : items;
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < shown.size(); i++) {
            if (i > 0) {
                sb.append(i == shown.size() - 1 && shown.size() == items.size() ? " or " : ", ");
            }
            sb.append(shown.get(i));
        }
        if (shown.size() < items.size()) {
            sb.append(", ...");
        }
        return sb.toString();
    }

    private static String found(Token t) {
        return t.getType() == Token.EOF ? "the end of the text" : show(t);
    }

    private static String show(Token t) {
        if (Keywords.isKeyword(t.getType())) {
            return "'" + t.getText() + "'";
        }
        return "'" + shorten(t.getText()) + "'";
    }

    private static String shorten(String text) {
        return text.length() <= MAX_SHOWN_TEXT ? text : text.substring(0, MAX_SHOWN_TEXT) + "...";
    }
}
