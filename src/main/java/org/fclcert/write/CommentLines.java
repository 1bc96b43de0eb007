package org.fclcert.write;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.model.Comment;
import org.fclcert.model.Comment.Line;
import org.fclcert.model.SourceLocation;

/**
 * A program's comments as the canonical writer asks for them, line by line of its layout ({@link Comment} says
 * which line each belongs to). Each comment is handed out once; {@link #rest} has those no line asked for, so
 * that the writer can still write them rather than lose them. One instance per text written.
 */
final class CommentLines {
    /** A line of the layout and which side of it; the element by file, line and column. */
    private record Key(Line line, String file, int row, int column, boolean trailing) {
        static Key of(Line line, SourceLocation item, boolean trailing) {
            return new Key(line, item.file(), item.line(), item.column(), trailing);
        }
    }

    private final List<Comment> comments;
    private final boolean[] used;
    /** The comments' indices by line, in text order (a large program's lines each look up once). */
    private final Map<Key, List<Integer>> byLine = new HashMap<>();

    CommentLines(List<Comment> comments) {
        this.comments = comments;
        this.used = new boolean[comments.size()];
        for (int i = 0; i < comments.size(); i++) {
            Comment c = comments.get(i);
            byLine.computeIfAbsent(Key.of(c.line(), c.item(), c.trailing()), k -> new ArrayList<>()).add(i);
        }
    }

    static CommentLines none() {
        return new CommentLines(List.of());
    }

    /** The comments standing before that line, each on its own line(s) at the indentation given. */
    String before(Line line, SourceLocation item, String indent) {
        StringBuilder out = new StringBuilder();
        for (Comment c : take(line, item, false)) {
            out.append(indent).append(c.text()).append('\n');
        }
        return out.toString();
    }

    /** The comments ending that line, each after a space. */
    String after(Line line, SourceLocation item) {
        StringBuilder out = new StringBuilder();
        for (Comment c : take(line, item, true)) {
            out.append(' ').append(c.text());
        }
        return out.toString();
    }

    /**
     * Both, for a line the layout does not write (a variable section the layout joined with the one before or
     * after it): the comments on lines of their own where that line would have stood.
     */
    String instead(Line line, SourceLocation item, String indent) {
        StringBuilder out = new StringBuilder(before(line, item, indent));
        for (Comment c : take(line, item, true)) {
            out.append(indent).append(c.text()).append('\n');
        }
        return out.toString();
    }

    /** The comments after the last function block, and any that no line asked for, in text order. */
    String rest() {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < comments.size(); i++) {
            if (!used[i]) {
                used[i] = true;
                out.append(comments.get(i).text()).append('\n');
            }
        }
        return out.toString();
    }

    private List<Comment> take(Line line, SourceLocation item, boolean trailing) {
        List<Integer> indices = byLine.remove(Key.of(line, item, trailing));
        if (indices == null) {
            return List.of();
        }
        List<Comment> found = new ArrayList<>();
        for (int i : indices) {
            used[i] = true;
            found.add(comments.get(i));
        }
        return found;
    }
}
