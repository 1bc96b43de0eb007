package org.fclcert.corpus;

import java.nio.file.Path;

/**
 * Something wrong with a case file or with the corpus as a whole: where (file and 1-based line, 0 when the
 * problem concerns the whole file or corpus) and what, in a plain sentence.
 */
public record CorpusProblem(Path file, int line, String message) implements Comparable<CorpusProblem> {

    @Override
    public int compareTo(CorpusProblem o) {
        int c = file.toString().compareTo(o.file.toString());
        return c != 0 ? c : Integer.compare(line, o.line);
    }

    /** {@code file:line: message}, or {@code file: message} without a line. */
    @Override
    public String toString() {
        return line > 0 ? file + ":" + line + ": " + message : file + ": " + message;
    }
}
