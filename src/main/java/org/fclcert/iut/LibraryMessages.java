package org.fclcert.iut;

import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds the program line a library's error message points at. Libraries name lines in their own ways:
 * fuzzylite and jfuzzylite give a number ({@code in line 24: …}) or quote the statement as they read it
 * ({@code in line: METHOD: CoGS}, semicolons dropped); ANTLR-based readers such as jFuzzyLogic write
 * {@code line 12:5 mismatched input …}. Public so that adapters outside this package (a vendor's
 * {@code java:} or {@code process:} adapter for the same library) can use the same heuristics.
 */
public final class LibraryMessages {
    /** {@code … in line 24: function_block Valve_Control}, or jfuzzylite's {@code in line <30>: VAR} */
    private static final Pattern LINE_NUMBER = Pattern.compile("\\bline <?(\\d+)>?(?=\\W|$)");
    /** {@code … in line: METHOD: CoGS} or {@code … from line: FUZZIFY u}: the statement as fuzzylite read it. */
    private static final Pattern LINE_TEXT = Pattern.compile("\\bline: (.*)$", Pattern.MULTILINE);
    /** ANTLR's {@code line 12:5 …}. */
    private static final Pattern ANTLR_LINE = Pattern.compile("\\bline (\\d+):(\\d+)\\b");

    private LibraryMessages() {}

    /**
     * The 1-based line of {@code program} a fuzzylite or jfuzzylite message points at: the first line whose
     * text (semicolons dropped, blanks collapsed — as fuzzylite quotes it) equals the quoted statement, else
     * the number the message gives. Empty when the message names no line, or the quote matches none.
     */
    public static OptionalInt fuzzyliteLine(String message, String program) {
        Matcher text = LINE_TEXT.matcher(message);
        if (text.find()) {
            String quoted = normalise(text.group(1));
            String[] lines = program.split("\\R", -1);
            for (int k = 0; k < lines.length; k++) {
                if (!quoted.isEmpty() && normalise(lines[k]).equals(quoted)) {
                    return OptionalInt.of(k + 1);
                }
            }
            return OptionalInt.empty();
        }
        return number(LINE_NUMBER.matcher(message));
    }

    /** The line of ANTLR's {@code line L:C} in a message (the first one), when there is one. */
    public static OptionalInt antlrLine(String message) {
        return number(ANTLR_LINE.matcher(message));
    }

    private static OptionalInt number(Matcher m) {
        if (!m.find()) {
            return OptionalInt.empty();
        }
        try {
            int n = Integer.parseInt(m.group(1));
            return n >= 1 ? OptionalInt.of(n) : OptionalInt.empty();
        } catch (NumberFormatException e) {
            return OptionalInt.empty();
        }
    }

    private static String normalise(String line) {
        return line.replace(";", " ").strip().replaceAll("\\s+", " ");
    }
}
