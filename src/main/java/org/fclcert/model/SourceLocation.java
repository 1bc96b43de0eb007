package org.fclcert.model;

import java.util.Objects;

/**
 * Where an element was written: file name, 1-based line and 1-based column.
 *
 * <p>A location is metadata, not part of what a program means: {@link #equals} is true for any two
 * locations, so two model elements written at different places (for example a program and the same
 * program after the canonical writer re-laid it out) compare equal. Compare locations with
 * {@link #sameAs} when the position itself matters.
 */
public final class SourceLocation implements Comparable<SourceLocation> {
    /** For elements made by tools rather than read from text. */
    public static final SourceLocation UNKNOWN = new SourceLocation("<generated>", 0, 0);

    private final String file;
    private final int line;
    private final int column;

    public SourceLocation(String file, int line, int column) {
        this.file = Objects.requireNonNull(file, "file");
        this.line = line;
        this.column = column;
    }

    public static SourceLocation of(String file, int line, int column) {
        return new SourceLocation(file, line, column);
    }

    public String file() {
        return file;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /** True when both name the same file, line and column. */
    public boolean sameAs(SourceLocation other) {
        return other != null && file.equals(other.file) && line == other.line && column == other.column;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof SourceLocation;
    }

    @Override
    public int hashCode() {
        return 0;
    }

    @Override
    public int compareTo(SourceLocation o) {
        int c = file.compareTo(o.file);
        if (c != 0) {
            return c;
        }
        c = Integer.compare(line, o.line);
        return c != 0 ? c : Integer.compare(column, o.column);
    }

    /** {@code file:line:col}, the form compilers use. */
    @Override
    public String toString() {
        return file + ":" + line + ":" + column;
    }
}
