package org.fclcert.syntax;

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
 * Tokens inside OPTIONS ... END_OPTIONS are manufacturer-specific and passed on unchecked, except that
 * parentheses are counted everywhere: the pre-scan cannot be sure the parser will read them as options.
 */
final class TokenPreScan {
    private static final Pattern GLUED_RULE = Pattern.compile("RULE([0-9]+)", Pattern.CASE_INSENSITIVE);

    private enum RulePart { NONE, CONDITION, CONCLUSION }

    private final ReaderDiagnostics diagnostics;
    private final TokenTable out;
    /** The last token added to {@link #out}, which the next token may change. */
    private Token last;
    private boolean inOptions;
    private boolean inRuleBlock;
    private RulePart rulePart = RulePart.NONE;
    private int depth;
    private int maxDepth;
    private boolean tooDeep;
    private int lastBadCharStop = -2;

    private TokenPreScan(ReaderDiagnostics diagnostics, TokenTable out) {
        this.diagnostics = diagnostics;
        this.out = out;
    }

    /** The checked tokens for the parser (default channel, ending with EOF). */
    record Result(TokenTable tokens, boolean tooDeep, int maxDepth) {
    }

    /** Scans the lexer's tokens into {@code out} (compact, or keeping the token objects a filter made). */
    static Result scan(TokenSource lexer, ReaderDiagnostics diagnostics, TokenTable out) {
        TokenPreScan scan = new TokenPreScan(diagnostics, out);
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
        if (type == FclLexer.LPAREN) {
            open(t);
            return;
        }
        if (type == FclLexer.RPAREN) {
            depth = Math.max(0, depth - 1);
            add(t);
            return;
        }
        if (inOptions) {
            if (type == FclLexer.END_OPTIONS || type == FclLexer.END_OPTION || type == FclLexer.END_FUNCTION_BLOCK) {
                inOptions = false;
            }
            add(t);
            return;
        }
        switch (type) {
            case FclLexer.ANY -> badCharacter(t);
            case FclLexer.BAD_IDENT -> badIdentifier(t);
            case FclLexer.INTEGER, FclLexer.REAL_LITERAL, FclLexer.BASED_INTEGER, FclLexer.BAD_REAL -> number(t);
            case FclLexer.COLON -> colon(t);
            case FclLexer.EQUALS -> equalsSign(t);
            case FclLexer.AND, FclLexer.OR -> andOr(t);
            default -> structure(t);
        }
    }

    private void structure(Token t) {
        switch (t.getType()) {
            case FclLexer.OPTIONS, FclLexer.OPTION -> inOptions = true;
            case FclLexer.RULEBLOCK -> inRuleBlock = true;
            case FclLexer.END_RULEBLOCK, FclLexer.RULE -> rulePart = RulePart.NONE;
            case FclLexer.SEMI -> {
                rulePart = RulePart.NONE;
                depth = 0;   // no parenthesis spans a ';': an unclosed one is the parser's error, not nesting
            }
            case FclLexer.IF -> rulePart = RulePart.CONDITION;
            case FclLexer.THEN -> rulePart = RulePart.CONCLUSION;
            default -> {
            }
        }
        if (t.getType() == FclLexer.END_RULEBLOCK) {
            inRuleBlock = false;
        }
        add(t);
    }

    private void checkComment(Token t) {
        String text = t.getText();
        if (unterminated(text)) {
            diagnostics.error(t, SyntaxCode.UNTERMINATED_COMMENT,
                    "this comment is never closed: '(*' needs a matching '*)'");
            diagnostics.explainEndOfText();
        } else if (opensInside(text)) {
            diagnostics.warning(t, SyntaxCode.NESTED_COMMENT_OPENER,
                    "'(*' inside a comment: comments do not nest in FCL (IEC 61131-3), the first '*)' ends it");
        }
    }

    /** Whether a COMMENT token's text runs to the end of the text without its '*)'. */
    static boolean unterminated(String comment) {
        return comment.length() < 4 || !comment.endsWith("*)");
    }

    /** Whether a terminated comment holds '(*' between its own '(*' and '*)'. */
    static boolean opensInside(String comment) {
        int opener = comment.indexOf("(*", 2);
        return opener >= 0 && opener <= comment.length() - 4;
    }

    private void badCharacter(Token t) {
        Token previous = last;
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
        String code = String.format("U+%04X", cp);
        String shown = Character.isISOControl(cp) || Character.isSpaceChar(cp) || Character.getType(cp) == Character.FORMAT
                ? code : cp > 0x7E ? "'" + c + "' (" + code + ")" : "'" + c + "'";
        if (c.equals("+") || c.equals("-")) {
            return "unexpected character " + shown + ": a sign must be written directly before its number";
        }
        if (c.equals("/") || c.equals("#")) {
            return "unexpected character " + shown + ": it is not part of FCL; comments are written (* ... *)";
        }
        return "unexpected character " + shown + ": it is not part of FCL";
    }

    private void badIdentifier(Token t) {
        String text = t.getText();
        if (text.contains("__")) {
            diagnostics.error(t, SyntaxCode.BAD_IDENTIFIER, "'" + text + "' is not a valid identifier:"
                    + " two underscores in a row are not allowed (IEC 61131-3 B.1.1)");
        } else if (text.endsWith("_")) {
            diagnostics.error(t, SyntaxCode.BAD_IDENTIFIER, "'" + text + "' is not a valid identifier:"
                    + " an identifier cannot end with '_' (IEC 61131-3 B.1.1)");
        }
        ((CommonToken) t).setType(FclLexer.IDENT);
        add(t);
    }

    private void number(Token t) {
        Optional<String> problem = NumberSyntax.problem(t.getType(), t.getText());
        problem.ifPresent(p -> diagnostics.error(t, SyntaxCode.BAD_NUMBER, p));
        if (t.getType() == FclLexer.BAD_REAL) {
            ((CommonToken) t).setType(FclLexer.REAL_LITERAL);
        }
        add(t);
    }

    /** {@code RULE1:} is one identifier; split it into RULE and 1 after saying so (Figure D.4). */
    private void colon(Token t) {
        Token previous = last;
        if (inRuleBlock && previous != null && previous.getType() == FclLexer.IDENT) {
            Matcher m = GLUED_RULE.matcher(previous.getText());
            if (m.matches()) {
                diagnostics.error(previous, SyntaxCode.GLUED_RULE_NUMBER, "'" + previous.getText()
                        + "' is read as one name; a rule starts with the keyword RULE, a space and its number:"
                        + " write 'RULE " + m.group(1) + ":' (5.2.4)");
                out.setLast(retyped(previous, FclLexer.RULE, 0, 4));
                add(retyped(previous, FclLexer.INTEGER, 4, previous.getText().length()));
                rulePart = RulePart.NONE;
            }
        }
        add(t);
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
        add(t);
    }

    /** {@code dT1 IS zero AND dT2 IS zero} in a conclusion (Figure D.4): report, then read ','. */
    private void andOr(Token t) {
        if (rulePart == RulePart.CONCLUSION) {
            diagnostics.error(t, SyntaxCode.OPERATOR_IN_CONCLUSION, "subconclusions are separated by ',' (5.2.4),"
                    + " not " + Keywords.spelling(t.getType()));
            ((CommonToken) t).setType(FclLexer.COMMA);
        }
        add(t);
    }

    private void add(Token t) {
        out.add(t);
        last = t;
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
        add(t);
    }
}
