package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.fclcert.model.Limits;

/**
 * Runs over the lexer's tokens before parsing and does what is best done on tokens:
 * <ul>
 *   <li>reports lexical mistakes precisely (unexpected characters, unterminated comments, malformed
 *       identifiers and numbers) and hands the parser a well-formed token instead, so that one bad
 *       character does not also become a parse error;</li>
 *   <li>measures parenthesis nesting, so that too deep a nesting is rejected before the recursive
 *       parser could exhaust the stack;</li>
 *   <li>repairs the three mistakes of the standard's own Annex D (Figure D.4) after reporting them
 *       ({@code RULE1:}, {@code color = brown}, {@code AND} between subconclusions), so that each gets
 *       one clear message and the rest of the program is still read.</li>
 * </ul>
 * Tokens inside OPTIONS ... END_OPTIONS are manufacturer-specific and passed on unchecked.
 */
final class TokenPreScan {
    private static final Pattern GLUED_RULE = Pattern.compile("RULE([0-9]+)", Pattern.CASE_INSENSITIVE);

    private enum RulePart { NONE, CONDITION, CONCLUSION }

    private final ReaderDiagnostics diagnostics;
    private final List<Token> out = new ArrayList<>();
    private boolean inOptions;
    private boolean inRuleBlock;
    private RulePart rulePart = RulePart.NONE;
    private int depth;
    private int maxDepth;
    private boolean tooDeep;
    private int lastBadCharStop = -2;

    private TokenPreScan(ReaderDiagnostics diagnostics) {
        this.diagnostics = diagnostics;
    }

    /** The checked tokens for the parser (default channel, ending with EOF). */
    record Result(List<Token> tokens, boolean tooDeep, int maxDepth) {
    }

    static Result scan(TokenSource lexer, ReaderDiagnostics diagnostics) {
        TokenPreScan scan = new TokenPreScan(diagnostics);
        Token t;
        do {
            t = lexer.nextToken();
            scan.accept(t);
        } while (t.getType() != Token.EOF && !diagnostics.tooMany());   // enough said about garbage
        return new Result(scan.out, scan.tooDeep, scan.maxDepth);
    }

    private void accept(Token t) {
        int type = t.getType();
        if (type == FclLexer.COMMENT) {
            checkComment(t);
            return;
        }
        if (inOptions) {
            if (type == FclLexer.END_OPTIONS || type == FclLexer.END_OPTION || type == FclLexer.END_FUNCTION_BLOCK) {
                inOptions = false;
            }
            out.add(t);
            return;
        }
        switch (type) {
            case FclLexer.ANY -> badCharacter(t);
            case FclLexer.IDENT -> identifier(t);
            case FclLexer.INTEGER, FclLexer.REAL_LITERAL, FclLexer.BASED_INTEGER, FclLexer.BAD_REAL -> number(t);
            case FclLexer.COLON -> colon(t);
            case FclLexer.EQUALS -> equalsSign(t);
            case FclLexer.AND, FclLexer.OR -> andOr(t);
            case FclLexer.LPAREN -> open(t);
            case FclLexer.RPAREN -> {
                depth = Math.max(0, depth - 1);
                out.add(t);
            }
            default -> structure(t);
        }
    }

    private void structure(Token t) {
        switch (t.getType()) {
            case FclLexer.OPTIONS, FclLexer.OPTION -> inOptions = true;
            case FclLexer.RULEBLOCK -> inRuleBlock = true;
            case FclLexer.END_RULEBLOCK, FclLexer.RULE, FclLexer.SEMI -> rulePart = RulePart.NONE;
            case FclLexer.IF -> rulePart = RulePart.CONDITION;
            case FclLexer.THEN -> rulePart = RulePart.CONCLUSION;
            default -> {
            }
        }
        if (t.getType() == FclLexer.END_RULEBLOCK) {
            inRuleBlock = false;
        }
        out.add(t);
    }

    private void checkComment(Token t) {
        String text = t.getText();
        if (text.length() < 4 || !text.endsWith("*)")) {
            diagnostics.error(t, SyntaxCode.UNTERMINATED_COMMENT,
                    "this comment is never closed: '(*' needs a matching '*)'");
            diagnostics.explainEndOfText();
        } else if (text.substring(2, text.length() - 2).contains("(*")) {
            diagnostics.warning(t, SyntaxCode.NESTED_COMMENT_OPENER,
                    "'(*' inside a comment: comments do not nest in FCL (IEC 61131-3), the first '*)' ends it");
        }
    }

    private void badCharacter(Token t) {
        Token previous = out.isEmpty() ? null : out.get(out.size() - 1);
        if (t.getText().equals(".") && previous != null && previous.getType() == FclLexer.INTEGER
                && previous.getStopIndex() + 1 == t.getStartIndex()) {
            diagnostics.error(previous, SyntaxCode.BAD_NUMBER, NumberSyntax.badRealProblem(previous.getText() + "."));
            return;
        }
        // a run of adjacent bad characters (binary garbage, a pasted symbol) is one mistake
        if (t.getStartIndex() != lastBadCharStop + 1) {
            diagnostics.error(t, SyntaxCode.UNEXPECTED_CHARACTER, describeCharacter(t.getText()));
        }
        lastBadCharStop = t.getStopIndex();
    }

    private static String describeCharacter(String c) {
        int cp = c.codePointAt(0);
        String shown = Character.isISOControl(cp) || Character.isWhitespace(cp)
                ? String.format("U+%04X", cp) : "'" + c + "'";
        if (c.equals("+") || c.equals("-")) {
            return "unexpected character " + shown + ": a sign must be written directly before its number";
        }
        return "unexpected character " + shown + ": it is not part of FCL";
    }

    private void identifier(Token t) {
        String text = t.getText();
        if (text.contains("__")) {
            diagnostics.error(t, SyntaxCode.BAD_IDENTIFIER, "'" + text + "' is not a valid identifier:"
                    + " two underscores in a row are not allowed (IEC 61131-3 B.1.1)");
        } else if (text.endsWith("_")) {
            diagnostics.error(t, SyntaxCode.BAD_IDENTIFIER, "'" + text + "' is not a valid identifier:"
                    + " an identifier cannot end with '_' (IEC 61131-3 B.1.1)");
        }
        out.add(t);
    }

    private void number(Token t) {
        Optional<String> problem = NumberSyntax.problem(t.getType(), t.getText());
        problem.ifPresent(p -> diagnostics.error(t, SyntaxCode.BAD_NUMBER, p));
        if (t.getType() == FclLexer.BAD_REAL) {
            ((CommonToken) t).setType(FclLexer.REAL_LITERAL);
        }
        out.add(t);
    }

    /** {@code RULE1:} is one identifier; split it into RULE and 1 after saying so (Figure D.4). */
    private void colon(Token t) {
        Token previous = out.isEmpty() ? null : out.get(out.size() - 1);
        if (inRuleBlock && previous != null && previous.getType() == FclLexer.IDENT) {
            Matcher m = GLUED_RULE.matcher(previous.getText());
            if (m.matches()) {
                diagnostics.error(previous, SyntaxCode.GLUED_RULE_NUMBER, "'" + previous.getText()
                        + "' is read as one name; a rule starts with the keyword RULE, a space and its number:"
                        + " write 'RULE " + m.group(1) + ":' (5.2.4)");
                out.set(out.size() - 1, retyped(previous, FclLexer.RULE, 0, 4));
                out.add(retyped(previous, FclLexer.INTEGER, 4, previous.getText().length()));
                rulePart = RulePart.NONE;
            }
        }
        out.add(t);
    }

    private static Token retyped(Token from, int type, int begin, int end) {
        CommonToken part = new CommonToken(from);
        part.setType(type);
        part.setText(from.getText().substring(begin, end));
        part.setStartIndex(from.getStartIndex() + begin);
        part.setStopIndex(from.getStartIndex() + end - 1);
        part.setCharPositionInLine(from.getCharPositionInLine() + begin);
        return part;
    }

    /** {@code color = brown} in a condition (Figure D.4): report, then read it as IS. */
    private void equalsSign(Token t) {
        if (rulePart == RulePart.CONDITION) {
            diagnostics.error(t, SyntaxCode.EQUALS_IN_CONDITION, "'=' is not FCL: a subcondition is"
                    + " 'variable IS term' or a bare variable (5.2.4)");
            ((CommonToken) t).setType(FclLexer.IS);
        }
        out.add(t);
    }

    /** {@code dT1 IS zero AND dT2 IS zero} in a conclusion (Figure D.4): report, then read ','. */
    private void andOr(Token t) {
        if (rulePart == RulePart.CONCLUSION) {
            diagnostics.error(t, SyntaxCode.OPERATOR_IN_CONCLUSION, "subconclusions are separated by ',' (5.2.4),"
                    + " not " + Keywords.spelling(t.getType()));
            ((CommonToken) t).setType(FclLexer.COMMA);
        }
        out.add(t);
    }

    private void open(Token t) {
        depth++;
        maxDepth = Math.max(maxDepth, depth);
        if (depth > Limits.MAX_NESTING_DEPTH && !tooDeep) {
            tooDeep = true;
            diagnostics.error(t, SyntaxCode.NESTING_TOO_DEEP, "parentheses are nested more than "
                    + Limits.MAX_NESTING_DEPTH + " deep here; fclcert reads at most " + Limits.MAX_NESTING_DEPTH
                    + " levels (a documented limit: the standard sets none)");
        }
        out.add(t);
    }
}
