package org.fclcert.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;
import org.fclcert.model.Names;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.FclLexer;

/**
 * What each name in a text is, from its tokens alone: function blocks, variables, terms, rule blocks and rules,
 * where each is declared and where each is used. Built from the tokens rather than the model so that navigation,
 * the outline and completion work on a text with any errors (the model exists only for a readable text).
 * The roles follow Fcl.g4: a name after TERM declares a term of the enclosing FUZZIFY or DEFUZZIFY variable, a
 * name after {@code IS [NOT]} uses a term of the variable before IS, a name in a VAR section before its colon
 * declares a variable; a word after a colon (a type, an algorithm, a method) and OPTIONS content name nothing.
 */
final class Outline {
    enum Kind { FUNCTION_BLOCK, VARIABLE, TERM, RULE_BLOCK, RULE }

    /** One token of the default channel: type, text, 1-based line, 0-based start and end columns (code points). */
    record Tok(int type, String text, int line, int column, int endColumn) {
        boolean isName() {
            return type == FclLexer.IDENT;
        }
    }

    /**
     * One name: its role, the function block it belongs to, for a term its variable, whether this is where it is
     * declared, and for a variable declaration its section.
     */
    record Occurrence(Kind kind, String block, String owner, String name, int token, boolean declaration,
            VariableKind section) {
        boolean sameSymbol(Occurrence o) {
            return kind == o.kind && same(block, o.block) && same(owner, o.owner) && same(name, o.name);
        }

        private static boolean same(String a, String b) {
            return a == null ? b == null : b != null && Names.same(a, b);
        }
    }

    /** A block of the text (function block, FUZZIFY, DEFUZZIFY, RULEBLOCK or rule), first to last token. */
    record Span(Kind kind, String block, String name, int first, int last) {
    }

    private final List<Tok> tokens;
    private final List<Occurrence> occurrences = new ArrayList<>();
    private final List<Span> spans = new ArrayList<>();
    private final int comments;

    private Outline(List<Tok> tokens, int comments) {
        this.tokens = tokens;
        this.comments = comments;
    }

    static Outline of(String text) {
        FclLexer lexer = new FclLexer(CharStreams.fromString(text));
        lexer.removeErrorListeners();
        List<Tok> tokens = new ArrayList<>();
        int comments = 0;
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            if (t.getChannel() != Token.DEFAULT_CHANNEL) {
                comments += t.getType() == FclLexer.COMMENT ? 1 : 0;
                continue;
            }
            String s = t.getText();
            tokens.add(new Tok(t.getType(), s, t.getLine(), t.getCharPositionInLine(),
                    t.getCharPositionInLine() + s.codePointCount(0, s.length())));
        }
        Outline o = new Outline(List.copyOf(tokens), comments);
        o.index();
        return o;
    }

    List<Tok> tokens() {
        return tokens;
    }

    List<Occurrence> occurrences() {
        return occurrences;
    }

    List<Span> spans() {
        return spans;
    }

    /** The number of comments in the text. */
    int comments() {
        return comments;
    }

    /** The index of the token at (or, with {@code touching}, ending at) a 1-based line and 0-based column, or -1. */
    int tokenAt(int line, int column, boolean touching) {
        int lo = 0;
        int hi = tokens.size() - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            Tok t = tokens.get(mid);
            if (t.line() < line || (t.line() == line && t.endColumn() < column)
                    || (t.line() == line && t.endColumn() == column && !touching)) {
                lo = mid + 1;
            } else if (t.line() > line || t.column() > column) {
                hi = mid - 1;
            } else {
                return mid;
            }
        }
        return -1;
    }

    /** The number of tokens that end before (or at) a 1-based line and 0-based column. */
    int tokensBefore(int line, int column) {
        int lo = 0;
        int hi = tokens.size();
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            Tok t = tokens.get(mid);
            if (t.line() < line || (t.line() == line && t.endColumn() <= column)) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    Optional<Occurrence> occurrenceAt(int token) {
        int lo = 0;
        int hi = occurrences.size() - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            int t = occurrences.get(mid).token();
            if (t < token) {
                lo = mid + 1;
            } else if (t > token) {
                hi = mid - 1;
            } else {
                return Optional.of(occurrences.get(mid));
            }
        }
        return Optional.empty();
    }

    /** Where a symbol is declared (the first declaration). */
    Optional<Occurrence> declaration(Occurrence of) {
        return occurrences.stream().filter(o -> o.declaration() && o.sameSymbol(of)).findFirst();
    }

    List<Occurrence> references(Occurrence of) {
        return occurrences.stream().filter(o -> o.sameSymbol(of)).toList();
    }

    /** The function block the token at {@code index} is in, if any. */
    Optional<String> blockAt(int index) {
        for (Span s : spans) {
            if (s.kind() == Kind.FUNCTION_BLOCK && s.first() <= index && index <= s.last()) {
                return Optional.of(s.name());
            }
        }
        return Optional.empty();
    }

    /** The variables a function block declares in a section, in order. */
    List<String> variables(String block, VariableKind section) {
        return occurrences.stream().filter(o -> o.kind() == Kind.VARIABLE && o.declaration() && o.section() == section
                && Names.same(o.block(), block)).map(Occurrence::name).distinct().toList();
    }

    /** The terms declared for a variable, in order. */
    List<String> terms(String block, String variable) {
        return occurrences.stream().filter(o -> o.kind() == Kind.TERM && o.declaration()
                && Names.same(o.block(), block) && Names.same(o.owner(), variable)).map(Occurrence::name).toList();
    }

    private enum Section { NONE, VAR, FUZZIFY, DEFUZZIFY, RULEBLOCK, OPTIONS }

    /** One pass over the tokens, keeping the block and section each token is in. */
    private void index() {
        String block = null;
        int blockStart = -1;
        Section section = Section.NONE;
        VariableKind varKind = null;
        String owner = null;
        int sectionStart = -1;
        String sectionName = null;
        int ruleStart = -1;
        String ruleName = null;
        boolean beforeColon = true;
        for (int i = 0; i < tokens.size(); i++) {
            Tok t = tokens.get(i);
            int type = t.type();
            int prev = i > 0 ? tokens.get(i - 1).type() : -1;
            if (section == Section.OPTIONS) {
                if (type == FclLexer.END_OPTIONS || type == FclLexer.END_OPTION) {
                    section = Section.NONE;
                }
                continue;
            }
            switch (type) {
                case FclLexer.FUNCTION_BLOCK -> {
                    block = "";
                    blockStart = i;
                    section = Section.NONE;
                }
                case FclLexer.END_FUNCTION_BLOCK -> {
                    if (block != null) {
                        spans.add(new Span(Kind.FUNCTION_BLOCK, block, block, blockStart, i));
                    }
                    block = null;
                    section = Section.NONE;
                }
                case FclLexer.VAR_INPUT, FclLexer.VAR_OUTPUT, FclLexer.VAR -> {
                    section = Section.VAR;
                    varKind = type == FclLexer.VAR_INPUT ? VariableKind.INPUT
                            : type == FclLexer.VAR_OUTPUT ? VariableKind.OUTPUT : VariableKind.LOCAL;
                    beforeColon = true;
                }
                case FclLexer.FUZZIFY, FclLexer.DEFUZZIFY -> {
                    section = type == FclLexer.FUZZIFY ? Section.FUZZIFY : Section.DEFUZZIFY;
                    sectionStart = i;
                    owner = null;
                }
                case FclLexer.RULEBLOCK -> {
                    section = Section.RULEBLOCK;
                    sectionStart = i;
                    sectionName = null;
                }
                case FclLexer.END_VAR -> section = Section.NONE;
                case FclLexer.END_FUZZIFY, FclLexer.END_DEFUZZIFY, FclLexer.END_RULEBLOCK -> {
                    if (section != Section.NONE && section != Section.VAR && sectionStart >= 0) {
                        String name = section == Section.RULEBLOCK ? sectionName : owner;
                        spans.add(new Span(section == Section.RULEBLOCK ? Kind.RULE_BLOCK : Kind.VARIABLE,
                                block, name == null ? "" : name, sectionStart, i));
                    }
                    section = Section.NONE;
                }
                case FclLexer.OPTIONS, FclLexer.OPTION -> section = Section.OPTIONS;
                case FclLexer.RULE -> {
                    ruleStart = i;
                    ruleName = i + 1 < tokens.size() ? tokens.get(i + 1).text() : "";
                }
                case FclLexer.SEMI -> {
                    beforeColon = true;
                    if (ruleStart >= 0 && section == Section.RULEBLOCK) {
                        spans.add(new Span(Kind.RULE, block, ruleName, ruleStart, i));
                    }
                    ruleStart = -1;
                }
                case FclLexer.COLON -> beforeColon = false;
                default -> {
                }
            }
            if (!t.isName() || block == null) {
                continue;
            }
            String fb = block;
            if (prev == FclLexer.FUNCTION_BLOCK) {
                block = t.text();
                add(Kind.FUNCTION_BLOCK, block, null, t.text(), i, true, null);
            } else if (prev == FclLexer.RULEBLOCK) {
                sectionName = t.text();
                add(Kind.RULE_BLOCK, fb, null, t.text(), i, true, null);
            } else if (prev == FclLexer.FUZZIFY || prev == FclLexer.DEFUZZIFY) {
                owner = t.text();
                add(Kind.VARIABLE, fb, null, t.text(), i, false, null);
            } else if (prev == FclLexer.TERM) {
                add(Kind.TERM, fb, owner, t.text(), i, true, null);
            } else if (prev == FclLexer.IS || (prev == FclLexer.NOT && i > 1 && tokens.get(i - 2).type() == FclLexer.IS)) {
                int is = prev == FclLexer.IS ? i - 1 : i - 2;
                String variable = is > 0 && tokens.get(is - 1).isName() ? tokens.get(is - 1).text() : null;
                add(Kind.TERM, fb, variable, t.text(), i, false, null);
            } else if (prev == FclLexer.RULE) {
                add(Kind.RULE, fb, null, t.text(), i, true, null);
            } else if (prev == FclLexer.COLON || prev == FclLexer.END_FUNCTION_BLOCK) {
                continue;   // a type, an algorithm or a method
            } else if (section == Section.VAR && beforeColon) {
                add(Kind.VARIABLE, fb, null, t.text(), i, true, varKind);
            } else {
                add(Kind.VARIABLE, fb, null, t.text(), i, false, null);
            }
        }
        if (block != null && !tokens.isEmpty()) {
            // a function block not yet closed (the text being typed) runs to the end
            spans.add(new Span(Kind.FUNCTION_BLOCK, block, block, blockStart, tokens.size() - 1));
        }
    }

    private void add(Kind kind, String block, String owner, String name, int token, boolean declaration,
            VariableKind section) {
        occurrences.add(new Occurrence(kind, block, owner, name, token, declaration, section));
    }
}
