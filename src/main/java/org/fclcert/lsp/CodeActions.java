package org.fclcert.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.fclcert.check.DefaultDeclared;
import org.fclcert.check.NoUndefinedTerms;
import org.fclcert.check.NoUndefinedVariables;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Names;
import org.fclcert.syntax.FclLexer;

/**
 * Quick fixes for what check already knows how to mend: its "did you mean" for an undefined variable (FCL-C001)
 * or term (FCL-C002), a missing DEFAULT (FCL-C017: {@code DEFAULT := NC;} or the RANGE's lower end), ACCU or ACT
 * written in a DEFUZZIFY block (moved into the function block's first RULEBLOCK) and a missing ';' (inserted where
 * the reader says it is missing). Each fix answers one diagnostic of the document's current reading.
 */
final class CodeActions {
    private static final Pattern DID_YOU_MEAN = Pattern.compile("did you mean '([^']+)'");
    private static final Pattern NOT_DECLARED = Pattern.compile("'([^']+)' is not a declared variable");
    private static final Pattern NOT_A_TERM = Pattern.compile("'([^']+)' is not a term of");

    private CodeActions() {
    }

    static List<CodeAction> in(Snapshot s, Range range) {
        int from = s.source().offset(range.getStart());
        int to = s.source().offset(range.getEnd());
        List<CodeAction> out = new ArrayList<>();
        for (Diagnostic d : s.diagnostics()) {
            Range at = Diagnostics.range(s, d);
            if (s.source().offset(at.getEnd()) < from || s.source().offset(at.getStart()) > to) {
                continue;
            }
            String code = d.code();
            if (code.equals(NoUndefinedVariables.CODE.code()) || code.equals(NoUndefinedTerms.CODE.code())) {
                didYouMean(s, d).ifPresent(out::add);
            } else if (code.equals(DefaultDeclared.CODE.code())) {
                out.addAll(addDefault(s, d));
            } else if (d.message().contains("ACCU and ACT belong in a RULEBLOCK")) {
                moveIntoRuleBlock(s, d).ifPresent(out::add);
            } else if (d.message().startsWith("expected ';'")) {
                Position p = Diagnostics.range(s, d).getStart();
                out.add(action("Insert the missing ';'", s, d, List.of(new TextEdit(new Range(p, p), ";"))));
            }
        }
        return out;
    }

    private static Optional<CodeAction> didYouMean(Snapshot s, Diagnostic d) {
        Matcher hint = DID_YOU_MEAN.matcher(d.message());
        boolean variable = d.code().equals(NoUndefinedVariables.CODE.code());
        Matcher wrong = (variable ? NOT_DECLARED : NOT_A_TERM).matcher(d.message());
        if (!hint.find() || !wrong.find()) {
            return Optional.empty();
        }
        // C001 stands on the misspelt name; C002 on its subcondition or subconclusion, whose term follows IS
        Outline o = s.outline();
        int start = tokenAt(s, d);
        for (int i = Math.max(start, 0); start >= 0 && i < o.tokens().size(); i++) {
            Outline.Tok t = o.tokens().get(i);
            if (t.type() == FclLexer.SEMI) {
                break;
            }
            boolean termPlace = i > 0 && (o.tokens().get(i - 1).type() == FclLexer.IS
                    || o.tokens().get(i - 1).type() == FclLexer.NOT);
            if (t.isName() && Names.same(t.text(), wrong.group(1)) && termPlace != variable) {
                return Optional.of(action("Change '" + t.text() + "' to '" + hint.group(1) + "'", s, d,
                        List.of(new TextEdit(Navigation.range(s, t), hint.group(1)))));
            }
        }
        return Optional.empty();
    }

    private static List<CodeAction> addDefault(Snapshot s, Diagnostic d) {
        Outline o = s.outline();
        int at = tokenAt(s, d);
        int end = next(o, at, FclLexer.END_DEFUZZIFY);
        if (at < 0 || end < 0) {
            return List.of();
        }
        Outline.Tok closing = o.tokens().get(end);
        String indent = " ".repeat(closing.column() + 4);
        Position p = s.source().position(s.source().offset(closing.line(), 0));
        List<CodeAction> out = new ArrayList<>();
        out.add(action("Add 'DEFAULT := NC;'", s, d, List.of(new TextEdit(new Range(p, p), indent + "DEFAULT := NC;\n"))));
        // the lower end of the RANGE, when the block gives one
        for (int i = at; i < end; i++) {
            int lparen = i + 1 < end && o.tokens().get(i + 1).type() == FclLexer.LPAREN ? i + 1 : i + 2;
            if (o.tokens().get(i).type() == FclLexer.RANGE && lparen + 2 < end
                    && o.tokens().get(lparen).type() == FclLexer.LPAREN && o.tokens().get(lparen + 2).type() == FclLexer.DOTDOT) {
                String min = o.tokens().get(lparen + 1).text();
                out.add(action("Add 'DEFAULT := " + min + ";'", s, d,
                        List.of(new TextEdit(new Range(p, p), indent + "DEFAULT := " + min + ";\n"))));
                break;
            }
        }
        return out;
    }

    private static Optional<CodeAction> moveIntoRuleBlock(Snapshot s, Diagnostic d) {
        Outline o = s.outline();
        int at = tokenAt(s, d);
        int semi = next(o, at, FclLexer.SEMI);
        int ruleBlock = next(o, at, FclLexer.RULEBLOCK);
        if (at < 0 || semi < 0 || ruleBlock < 0 || ruleBlock + 1 >= o.tokens().size()
                || next(o, at, FclLexer.END_FUNCTION_BLOCK) < ruleBlock) {
            return Optional.empty();
        }
        Outline.Tok first = o.tokens().get(at);
        Outline.Tok last = o.tokens().get(semi);
        SourceText src = s.source();
        String statement = src.text().substring(src.offset(first.line(), first.column()), src.offset(last.line(), last.endColumn()));
        // the whole line when the statement stands alone on it, else just the statement
        int lineStart = src.offset(first.line(), 0);
        int stop = src.offset(last.line(), last.endColumn());
        int lineEnd = src.text().indexOf('\n', stop);
        boolean alone = src.text().substring(lineStart, src.offset(first.line(), first.column())).isBlank()
                && (lineEnd < 0 ? src.text().substring(stop) : src.text().substring(stop, lineEnd)).isBlank();
        Range remove = alone ? new Range(src.position(lineStart), src.position(lineEnd < 0 ? src.text().length() : lineEnd + 1))
                : new Range(src.position(src.offset(first.line(), first.column())), src.position(stop));
        Outline.Tok header = o.tokens().get(ruleBlock + 1);
        // before the block's first rule (or its end): after AND, OR and ACT, where 5.4 places accumulation
        int rule = next(o, ruleBlock, FclLexer.RULE);
        int end = next(o, ruleBlock, FclLexer.END_RULEBLOCK);
        int before = rule >= 0 && (end < 0 || rule < end) ? rule : end;
        if (before < 0) {
            return Optional.empty();
        }
        Outline.Tok place = o.tokens().get(before);
        Position lineStartOfPlace = src.position(src.offset(place.line(), 0));
        String indent = " ".repeat(before == rule ? place.column() : place.column() + 4);
        return Optional.of(action("Move '" + statement + "' into RULEBLOCK " + header.text(), s, d, List.of(
                new TextEdit(remove, ""), new TextEdit(new Range(lineStartOfPlace, lineStartOfPlace),
                        indent + statement + "\n"))));
    }

    private static int tokenAt(Snapshot s, Diagnostic d) {
        return s.outline().tokenAt(d.location().line(), Math.max(0, d.location().column() - 1), false);
    }

    private static int next(Outline o, int from, int type) {
        for (int i = Math.max(from, 0); from >= 0 && i < o.tokens().size(); i++) {
            if (o.tokens().get(i).type() == type) {
                return i;
            }
        }
        return -1;
    }

    private static CodeAction action(String title, Snapshot s, Diagnostic d, List<TextEdit> edits) {
        CodeAction a = new CodeAction(title);
        a.setKind(CodeActionKind.QuickFix);
        a.setDiagnostics(List.of(Diagnostics.of(s, d)));
        a.setEdit(new WorkspaceEdit(Map.of(s.uri(), edits)));
        return a;
    }
}
