package org.fclcert.lsp;

import java.util.Arrays;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/**
 * A document's text with its line starts: converts between fclcert's positions (1-based line, column in code
 * points) and the protocol's (0-based line, character in UTF-16 units), and finds the extent of a token.
 */
final class SourceText {
    private final String text;
    private final int[] lineStarts;

    SourceText(String text) {
        this.text = text;
        int[] starts = new int[16];
        int n = 1;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                if (n == starts.length) {
                    starts = Arrays.copyOf(starts, n * 2);
                }
                starts[n++] = i + 1;
            }
        }
        this.lineStarts = Arrays.copyOf(starts, n);
    }

    private SourceText(String text, int[] lineStarts) {
        this.text = text;
        this.lineStarts = lineStarts;
    }

    /**
     * The text with the characters {@code from} to {@code to} replaced by {@code inserted}: equal to a SourceText made
     * of the new text, but its line starts moved rather than found again (a keystroke in a 1 MB text changes a few).
     */
    SourceText edited(int from, int to, String inserted) {
        String edited = new StringBuilder(text.length() - (to - from) + inserted.length())
                .append(text, 0, from).append(inserted).append(text, to, text.length()).toString();
        int[] starts = new int[lineStarts.length + inserted.length()];
        int n = 0;
        int i = 0;
        // a line start s follows the line break at s - 1: kept before the edit, dropped inside it, moved after it
        for (; i < lineStarts.length && lineStarts[i] <= from; i++) {
            starts[n++] = lineStarts[i];
        }
        for (int k = 0; k < inserted.length(); k++) {
            if (inserted.charAt(k) == '\n') {
                starts[n++] = from + k + 1;
            }
        }
        int shift = inserted.length() - (to - from);
        for (; i < lineStarts.length; i++) {
            if (lineStarts[i] - 1 >= to) {
                starts[n++] = lineStarts[i] + shift;
            }
        }
        return new SourceText(edited, Arrays.copyOf(starts, n));
    }

    String text() {
        return text;
    }

    /** The line starts (for the test that holds {@link #edited} to a fresh count). */
    int[] lineStarts() {
        return lineStarts.clone();
    }

    int lineCount() {
        return lineStarts.length;
    }

    /** The char offset of a 1-based line and 0-based code-point column, clamped to the text. */
    int offset(int line, int codePointColumn) {
        if (line < 1) {
            return 0;
        }
        if (line > lineStarts.length) {
            return text.length();
        }
        int start = lineStarts[line - 1];
        int end = lineEnd(line);
        int at = start;
        for (int k = 0; k < codePointColumn && at < end; k++) {
            at += Character.charCount(text.codePointAt(at));
        }
        return at;
    }

    /** The char offset of a protocol position, clamped to the text (a position past a line's end is its end). */
    int offset(Position p) {
        if (p.getLine() < 0) {
            return 0;
        }
        if (p.getLine() >= lineStarts.length) {
            return text.length();
        }
        int start = lineStarts[p.getLine()];
        return Math.min(start + Math.max(0, p.getCharacter()), lineEnd(p.getLine() + 1));
    }

    /** The protocol position of a char offset. */
    Position position(int offset) {
        int o = Math.max(0, Math.min(offset, text.length()));
        int line = Arrays.binarySearch(lineStarts, o);
        if (line < 0) {
            line = -line - 2;
        }
        return new Position(line, o - lineStarts[line]);
    }

    /** Where a line's text ends (before its line break). */
    private int lineEnd(int line) {
        int end = line < lineStarts.length ? lineStarts[line] - 1 : text.length();
        if (end > lineStarts[line - 1] && end <= text.length() && end > 0 && text.charAt(end - 1) == '\r') {
            end--;
        }
        return Math.max(end, lineStarts[line - 1]);
    }

    /**
     * The range of the token that starts at a diagnostic's place (1-based line and column): a word or number
     * runs over its letters, digits, underscores and dots; anything else is one character; at a line's end the
     * range is empty there.
     */
    Range tokenRange(int line, int column) {
        int start = offset(Math.max(line, 1), Math.max(column - 1, 0));
        int end = start;
        while (end < text.length() && isWordChar(text.charAt(end))) {
            end++;
        }
        if (end == start && start < text.length() && text.charAt(start) != '\n' && text.charAt(start) != '\r') {
            end = start + Character.charCount(text.codePointAt(start));
        }
        return new Range(position(start), position(end));
    }

    static boolean isWordChar(char c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '#' || c == '.';
    }

    /** The start of the identifier-like word that ends at {@code offset} (letters, digits, underscores). */
    int wordStart(int offset) {
        int s = offset;
        while (s > 0 && (Character.isLetterOrDigit(text.charAt(s - 1)) || text.charAt(s - 1) == '_')) {
            s--;
        }
        return s;
    }
}
