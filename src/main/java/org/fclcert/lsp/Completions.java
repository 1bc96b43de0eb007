package org.fclcert.lsp;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionItemKind;
import org.eclipse.lsp4j.Position;
import org.fclcert.model.DataType;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.ExpectedKeywords;
import org.fclcert.syntax.FclLexer;
import org.fclcert.syntax.SyntaxCode;
import org.fclcert.syntax.dialect.DialectMethods;

/**
 * Completion that knows where the cursor is. Names of the function block: its inputs after IF, AND, OR, NOT and
 * '(' in a condition (and after WITH and FUZZIFY), its outputs after THEN and ',' in a conclusion (and after
 * DEFUZZIFY), a variable's terms after {@code v IS [NOT]}. The standard's choices after a colon: the algorithms of
 * Table 3 after {@code AND :} and {@code OR :}, the activation methods after {@code ACT :}, the accumulation methods
 * after {@code ACCU :}, the defuzzification methods after {@code METHOD :}, the data types in a declaration.
 * Anywhere else the keywords Fcl.g4 allows next ({@link ExpectedKeywords}).
 */
final class Completions {
    private Completions() {
    }

    static List<CompletionItem> at(Snapshot s, Position p) {
        int cursor = s.source().offset(p);
        int wordStart = s.source().wordStart(cursor);
        String before = s.text().substring(0, wordStart);
        Outline outline = s.outline();
        Position start = s.source().position(wordStart);
        int line = start.getLine() + 1;
        int column = before.codePointCount(s.source().offset(new Position(start.getLine(), 0)), wordStart);
        int n = outline.tokensBefore(line, column);
        List<Outline.Tok> tokens = outline.tokens();
        int last = n > 0 ? tokens.get(n - 1).type() : -1;
        int prev = n > 1 ? tokens.get(n - 2).type() : -1;
        String block = outline.blockAt(Math.max(0, n - 1)).orElse("");
        if (last == FclLexer.COLON) {
            DialectMethods standard = DialectMethods.STANDARD;
            DialectMethods dialect = DialectMethods.of(s.dialect());
            String in = s.dialect().displayName();
            switch (prev) {
                case FclLexer.AND -> {
                    return methods(standard.and(), dialect.and(), "AND algorithm, "
                            + SyntaxCode.OPERATOR_DEFINITION.clause(), in);
                }
                case FclLexer.OR -> {
                    return methods(standard.or(), dialect.or(), "OR algorithm, "
                            + SyntaxCode.OPERATOR_DEFINITION.clause(), in);
                }
                case FclLexer.ACT -> {
                    return methods(standard.activation(), dialect.activation(), "activation method, "
                            + SyntaxCode.ACTIVATION.clause(), in);
                }
                case FclLexer.ACCU -> {
                    return methods(standard.accumulation(), dialect.accumulation(), "accumulation method, "
                            + SyntaxCode.ACCUMULATION.clause(), in);
                }
                case FclLexer.METHOD -> {
                    return methods(standard.defuzzification(), dialect.defuzzification(), "defuzzification method, "
                            + SyntaxCode.METHOD.clause(), in);
                }
                default -> {
                    if (inSection(tokens, n, FclLexer.VAR_INPUT, FclLexer.VAR_OUTPUT, FclLexer.VAR, FclLexer.END_VAR)) {
                        return names(Arrays.stream(DataType.values()).map(Enum::name).toList(),
                                CompletionItemKind.EnumMember, "data type, " + SyntaxCode.NOT_ELEMENTARY_TYPE.clause());
                    }
                }
            }
        }
        boolean inRule = inSection(tokens, n, FclLexer.RULE, -1, -1, FclLexer.SEMI);
        boolean inConclusion = inRule && inSection(tokens, n, FclLexer.THEN, -1, -1, FclLexer.SEMI);
        if (last == FclLexer.IS || (last == FclLexer.NOT && prev == FclLexer.IS)) {
            int is = last == FclLexer.IS ? n - 1 : n - 2;
            if (is > 0 && tokens.get(is - 1).isName()) {
                String variable = tokens.get(is - 1).text();
                List<CompletionItem> out = names(outline.terms(block, variable), CompletionItemKind.EnumMember,
                        "term of " + variable);
                if (last == FclLexer.IS && !inConclusion) {
                    out.addAll(keywords(List.of("NOT")));
                }
                return out;
            }
        }
        List<CompletionItem> out = new ArrayList<>();
        if ((inRule && !inConclusion && (last == FclLexer.IF || last == FclLexer.AND || last == FclLexer.OR
                || last == FclLexer.NOT || last == FclLexer.LPAREN)) || last == FclLexer.WITH || last == FclLexer.FUZZIFY) {
            out.addAll(names(outline.variables(block, VariableKind.INPUT), CompletionItemKind.Variable, "VAR_INPUT"));
        } else if ((inConclusion && (last == FclLexer.THEN || last == FclLexer.COMMA)) || last == FclLexer.DEFUZZIFY) {
            out.addAll(names(outline.variables(block, VariableKind.OUTPUT), CompletionItemKind.Variable, "VAR_OUTPUT"));
        }
        // the grammar is asked from the function block the cursor is in (program ::= function blocks)
        int fb = n - 1;
        while (fb >= 0 && tokens.get(fb).type() != FclLexer.FUNCTION_BLOCK) {
            fb--;
        }
        String from = fb < 0 ? before
                : before.substring(s.source().offset(tokens.get(fb).line(), tokens.get(fb).column()));
        out.addAll(keywords(ExpectedKeywords.after(from)));
        return out;
    }

    /** True when the last of {@code open..} before token n comes after the last {@code close}. */
    private static boolean inSection(List<Outline.Tok> tokens, int n, int open1, int open2, int open3, int close) {
        for (int i = n - 1; i >= 0; i--) {
            int t = tokens.get(i).type();
            if (t == close) {
                return false;
            }
            if (t == open1 || t == open2 || t == open3) {
                return true;
            }
        }
        return false;
    }

    /**
     * The standard's words, then those only the document's dialect reads (its spellings, e.g. jFuzzyLogic's
     * {@code NIPMIN}), each said to be the dialect's.
     */
    private static List<CompletionItem> methods(List<String> standard, List<String> dialect, String detail,
            String dialectName) {
        List<String> words = new ArrayList<>(standard);
        words.addAll(dialect);
        return items(words, CompletionItemKind.EnumMember, w -> standard.stream().anyMatch(w::equalsIgnoreCase)
                ? detail : detail.substring(0, detail.indexOf(',')) + " of " + dialectName + " (not in the standard)");
    }

    private static List<CompletionItem> names(List<String> names, CompletionItemKind kind, String detail) {
        return items(names, kind, w -> detail);
    }

    private static List<CompletionItem> keywords(List<String> words) {
        return items(words, CompletionItemKind.Keyword,
                w -> KeywordHelp.of(w).map(h -> h.clause() + ": " + h.meaning()).orElse("keyword"));
    }

    /** One item per word, the first spelling of words equal but for case. */
    private static List<CompletionItem> items(List<String> words, CompletionItemKind kind, Function<String, String> detail) {
        Set<String> seen = new java.util.HashSet<>();
        List<CompletionItem> out = new ArrayList<>();
        for (String w : words) {
            if (!seen.add(w.toUpperCase(java.util.Locale.ROOT))) {
                continue;
            }
            CompletionItem item = new CompletionItem(w);
            item.setKind(kind);
            item.setDetail(detail.apply(w));
            out.add(item);
        }
        return out;
    }
}
