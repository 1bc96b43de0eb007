package org.fclcert.iut;

import java.util.ArrayList;
import java.util.List;

/**
 * Splits one command string into words the way a POSIX shell does for a simple command, without any
 * expansion: blanks separate words; single quotes keep everything literally; double quotes keep
 * everything except that a backslash escapes {@code $ ` " \} and a newline; outside quotes a
 * backslash makes the next character literal (and a backslash-newline disappears). No variables,
 * globs, tildes, pipes or redirections: those characters are kept as they are.
 */
public final class CommandLineSplitter {
    private CommandLineSplitter() {}

    /**
     * @throws IutException of kind {@link IutException.Kind#INFRA} for an unterminated quote, a
     *     trailing backslash, or a command with no words
     */
    public static List<String> split(String command) throws IutException {
        List<String> words = new Scanner(command).words();
        if (words.isEmpty()) {
            throw new IutException(IutException.Kind.INFRA, "the process command is empty");
        }
        return words;
    }

    private static final class Scanner {
        private final String s;
        private final List<String> words = new ArrayList<>();
        private final StringBuilder word = new StringBuilder();
        private boolean inWord;
        private int i;

        Scanner(String s) {
            this.s = s;
        }

        List<String> words() throws IutException {
            while (i < s.length()) {
                char c = s.charAt(i++);
                if (c == ' ' || c == '\t' || c == '\n') {
                    endWord();
                } else if (c == '\'') {
                    singleQuoted();
                } else if (c == '"') {
                    doubleQuoted();
                } else if (c == '\\') {
                    escaped();
                } else {
                    append(c);
                }
            }
            endWord();
            return List.copyOf(words);
        }

        private void singleQuoted() throws IutException {
            int end = s.indexOf('\'', i);
            if (end < 0) {
                throw unterminated("single");
            }
            inWord = true;
            word.append(s, i, end);
            i = end + 1;
        }

        private void doubleQuoted() throws IutException {
            inWord = true;
            while (i < s.length()) {
                char c = s.charAt(i++);
                if (c == '"') {
                    return;
                }
                if (c == '\\' && i < s.length() && "$`\"\\\n".indexOf(s.charAt(i)) >= 0) {
                    char next = s.charAt(i++);
                    if (next != '\n') {
                        word.append(next);
                    }
                } else {
                    word.append(c);
                }
            }
            throw unterminated("double");
        }

        private void escaped() throws IutException {
            if (i >= s.length()) {
                throw new IutException(IutException.Kind.INFRA, "the process command ends with a lone backslash");
            }
            char next = s.charAt(i++);
            if (next != '\n') {
                append(next);
            }
        }

        private void append(char c) {
            inWord = true;
            word.append(c);
        }

        private void endWord() {
            if (inWord) {
                words.add(word.toString());
                word.setLength(0);
                inWord = false;
            }
        }

        private IutException unterminated(String which) {
            return new IutException(
                    IutException.Kind.INFRA, "the process command has an unterminated " + which + " quote: " + s);
        }
    }
}
