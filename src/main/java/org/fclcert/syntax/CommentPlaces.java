package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.antlr.v4.runtime.Token;
import org.fclcert.model.Comment;
import org.fclcert.model.Comment.Line;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.OptionsBlock;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;

/**
 * Gives a program read from a text the text's comments, each with the line of the canonical layout it belongs
 * to ({@link Comment}): the one place where comments are attached, for every reader on the strict pipeline.
 *
 * <p>A comment that starts on the line where the token before it ends is a trailing comment of the line holding
 * that token: of a declaration, term, setting or rule, of a header, of a VAR_… line or of an END_… line. Any other
 * comment belongs before the line of the token after it; inside an element written over several lines (a rule
 * broken before THEN) it trails that element. Comments inside OPTIONS … END_OPTIONS are the block's verbatim
 * content already and are not attached again.
 */
final class CommentPlaces {
    private enum Kind { FUNCTION_BLOCK, VARIABLE, BLOCK, OTHER }

    /** An element of the model that names a line of the layout, by where it starts. */
    private record Item(int line, int column, Kind kind, SourceLocation location) {
    }

    private static final Comparator<Item> ORDER = Comparator.comparingInt(Item::line).thenComparingInt(Item::column);

    private final List<Item> items;
    private final java.util.Map<Kind, List<Item>> byKind = new java.util.EnumMap<>(Kind.class);

    private CommentPlaces(List<Item> items) {
        this.items = items;
        for (Kind k : Kind.values()) {
            byKind.put(k, items.stream().filter(i -> i.kind() == k).toList());
        }
    }

    /**
     * The program with the comments of {@code body} (the text it was read from, without a byte order mark);
     * the program itself when the text has none.
     */
    static Program attach(Program program, String body) {
        if (body.indexOf("(*") < 0) {
            return program;
        }
        return program.withComments(new CommentPlaces(items(program)).comments(program.sourceName(),
                new FclTokenSource(body, program.sourceName())));
    }

    /**
     * The same from the tokens the direct parser kept as it read {@code body} ({@link DirectParser#read}): every
     * comment with the tokens on either side, the tokens that open and close OPTIONS, and EOF. The walk below
     * decides from those alone, so it gives what it gives over every token.
     */
    static Program attach(Program program, String body, List<Token> aroundComments) {
        if (body.indexOf("(*") < 0) {
            return program;
        }
        return program.withComments(new CommentPlaces(items(program)).comments(program.sourceName(),
                new org.antlr.v4.runtime.ListTokenSource(aroundComments)));
    }

    /** Whether a token changes the walk's "inside OPTIONS" (the only state it keeps besides the token before). */
    static boolean changesOptions(int type) {
        return type == FclLexer.OPTIONS || type == FclLexer.OPTION || type == FclLexer.END_OPTIONS
                || type == FclLexer.END_OPTION;
    }

    private List<Comment> comments(String sourceName, org.antlr.v4.runtime.TokenSource lexer) {
        List<Comment> out = new ArrayList<>();
        List<Token> pending = new ArrayList<>();
        Token previous = null;
        boolean inOptions = false;
        while (true) {
            Token t = lexer.nextToken();
            int type = t.getType();
            if (type == FclLexer.COMMENT) {
                if (!inOptions) {
                    if (previous != null && previous.getLine() == t.getLine()) {
                        out.add(trailing(sourceName, t, previous));
                    } else {
                        pending.add(t);
                    }
                }
                continue;
            }
            for (Token c : pending) {
                out.add(before(sourceName, c, t));
            }
            pending.clear();
            if (type == Token.EOF) {
                return out;
            }
            inOptions = type == FclLexer.OPTIONS || type == FclLexer.OPTION
                    || inOptions && type != FclLexer.END_OPTIONS && type != FclLexer.END_OPTION;
            previous = t;
        }
    }

    /** A comment on the line where {@code previous} stands. */
    private Comment trailing(String sourceName, Token comment, Token previous) {
        int type = previous.getType();
        if (type == FclLexer.VAR_INPUT || type == FclLexer.VAR_OUTPUT || type == FclLexer.VAR) {
            return place(sourceName, comment, Line.SECTION_START, firstFrom(Kind.VARIABLE, previous), true);
        }
        Kind closed = closes(type);
        if (closed != null) {
            return place(sourceName, comment, Line.END, lastUpTo(closed, previous), true);
        }
        return place(sourceName, comment, Line.ITEM, lastUpTo(null, previous), true);
    }

    /** A comment on lines of its own, before {@code next}. */
    private Comment before(String sourceName, Token comment, Token next) {
        int type = next.getType();
        if (type == Token.EOF) {
            return comment(sourceName, comment, Line.END_OF_TEXT, SourceLocation.UNKNOWN, false);
        }
        if (type == FclLexer.VAR_INPUT || type == FclLexer.VAR_OUTPUT || type == FclLexer.VAR) {
            return place(sourceName, comment, Line.SECTION_START, firstFrom(Kind.VARIABLE, next), false);
        }
        Kind closed = closes(type);
        if (closed != null) {
            return place(sourceName, comment, Line.END, lastUpTo(closed, next), false);
        }
        Item at = lastUpTo(null, next);
        boolean starts = at != null && at.line() == next.getLine() && at.column() == next.getCharPositionInLine() + 1;
        // inside an element written over several lines: it trails that element
        return place(sourceName, comment, Line.ITEM, at, !starts);
    }

    /** What an END_… token closes, or null. */
    private static Kind closes(int type) {
        return switch (type) {
            case FclLexer.END_VAR -> Kind.VARIABLE;
            case FclLexer.END_FUNCTION_BLOCK -> Kind.FUNCTION_BLOCK;
            case FclLexer.END_FUZZIFY, FclLexer.END_DEFUZZIFY, FclLexer.END_RULEBLOCK, FclLexer.END_OPTIONS,
                    FclLexer.END_OPTION -> Kind.BLOCK;
            default -> null;
        };
    }

    private Comment place(String sourceName, Token comment, Line line, Item item, boolean trailing) {
        if (item == null) {
            // no element of that kind where the text says (an empty section): before the next element, or at the end
            Item next = firstFrom(null, comment);
            return next == null ? comment(sourceName, comment, Line.END_OF_TEXT, SourceLocation.UNKNOWN, false)
                    : comment(sourceName, comment, Line.ITEM, next.location(), false);
        }
        return comment(sourceName, comment, line, item.location(), trailing);
    }

    private static Comment comment(String sourceName, Token comment, Line line, SourceLocation item,
            boolean trailing) {
        return new Comment(comment.getText(), ReaderDiagnostics.location(sourceName, comment), line, item, trailing);
    }

    /** The last element of that kind (any kind when null) starting at or before the token. */
    private Item lastUpTo(Kind kind, Token t) {
        List<Item> list = of(kind);
        int i = firstAfter(list, t, true) - 1;
        return i < 0 ? null : list.get(i);
    }

    /** The first element of that kind (any kind when null) starting at or after the token. */
    private Item firstFrom(Kind kind, Token t) {
        List<Item> list = of(kind);
        int i = firstAfter(list, t, false);
        return i == list.size() ? null : list.get(i);
    }

    private List<Item> of(Kind kind) {
        return kind == null ? items : byKind.get(kind);
    }

    /**
     * Binary search in a list in text order (a large program's comments each look up once): the index of the
     * first element after the token's start, or, when {@code orAt} is false, at or after it.
     */
    private static int firstAfter(List<Item> list, Token t, boolean orAt) {
        int low = 0;
        int high = list.size();
        while (low < high) {
            int mid = (low + high) >>> 1;
            int c = compare(list.get(mid), t);
            if (c < 0 || c == 0 && orAt) {
                low = mid + 1;
            } else {
                high = mid;
            }
        }
        return low;
    }

    private static int compare(Item i, Token t) {
        int c = Integer.compare(i.line(), Math.max(1, t.getLine()));
        return c != 0 ? c : Integer.compare(i.column(), t.getCharPositionInLine() + 1);
    }

    /** Every element that names a line of the layout, in text order. */
    private static List<Item> items(Program program) {
        List<Item> items = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            add(items, Kind.FUNCTION_BLOCK, fb.location());
            fb.variables().forEach(v -> add(items, Kind.VARIABLE, v.location()));
            for (Fuzzification f : fb.fuzzifications()) {
                add(items, Kind.BLOCK, f.location());
                f.terms().forEach(t -> add(items, Kind.OTHER, t.location()));
            }
            for (Defuzzification d : fb.defuzzifications()) {
                add(items, Kind.BLOCK, d.location());
                d.range().ifPresent(r -> add(items, Kind.OTHER, r.location()));
                d.terms().forEach(t -> add(items, Kind.OTHER, t.location()));
                d.method().ifPresent(m -> add(items, Kind.OTHER, m.location()));
                d.defaultValue().ifPresent(v -> add(items, Kind.OTHER, v.location()));
            }
            for (RuleBlock b : fb.ruleBlocks()) {
                add(items, Kind.BLOCK, b.location());
                b.and().ifPresent(s -> add(items, Kind.OTHER, s.location()));
                b.or().ifPresent(s -> add(items, Kind.OTHER, s.location()));
                b.activation().ifPresent(s -> add(items, Kind.OTHER, s.location()));
                b.accumulation().ifPresent(s -> add(items, Kind.OTHER, s.location()));
                b.rules().forEach(r -> add(items, Kind.OTHER, r.location()));
            }
            for (OptionsBlock o : fb.options()) {
                add(items, Kind.BLOCK, o.location());
            }
        }
        items.sort(ORDER);
        return items;
    }

    private static void add(List<Item> items, Kind kind, SourceLocation at) {
        items.add(new Item(at.line(), at.column(), kind, at));
    }
}
