package org.fclcert.model;

import java.util.Objects;

/**
 * A comment of the source text, kept so that a writer can put it back where it stood ({@code fclcert fmt}).
 * Where it stood is said as a line of the canonical layout, named by the model element that line writes, and
 * whether the comment stood on its own line(s) before that line or at the end of it (trailing). The reader
 * decides this once ({@code syntax.CommentPlaces}); the writer only looks it up.
 *
 * <p>Like a location, a comment says how a text is written, not what it means: {@link Program#equals} ignores
 * comments, so a program and its formatted text compare equal.
 *
 * @param text     the comment exactly as written, delimiters included ({@code (* 0 .. 100 °C *)})
 * @param location where the comment starts
 * @param line     which line of the layout it belongs to
 * @param item     the location of the element that names that line ({@link SourceLocation#UNKNOWN} for
 *                 {@link Line#END_OF_TEXT})
 * @param trailing true when it ends that line, false when it stands on its own line(s) before it
 */
public record Comment(String text, SourceLocation location, Line line, SourceLocation item, boolean trailing) {
    public Comment {
        Objects.requireNonNull(text, "text");
        Objects.requireNonNull(location, "location");
        Objects.requireNonNull(line, "line");
        Objects.requireNonNull(item, "item");
    }

    /** The lines of the layout a comment can belong to. */
    public enum Line {
        /**
         * The element's own line: a declaration, a term, RANGE, METHOD, DEFAULT, a setting, a rule (its last line
         * when it is written on several), or the header of a function block or block.
         */
        ITEM,
        /** The VAR_INPUT, VAR_OUTPUT or VAR line of the section whose first variable is the element. */
        SECTION_START,
        /**
         * The END_… line that closes the element: a function block, a block, or the variable section whose last
         * variable is the element.
         */
        END,
        /** After the last function block. */
        END_OF_TEXT
    }
}
