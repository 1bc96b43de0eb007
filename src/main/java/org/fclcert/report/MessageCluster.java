package org.fclcert.report;

import java.util.HashSet;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The key that clusters an implementation's messages: the same complaint about different cases gets the same key,
 * so that "term cool needs 2 or 3 points" and "term mid needs 2 or 3 points" fall into one group, and "'Or' is not
 * supported" joins "'OR' is not supported". What is particular to one case goes: positions (ANTLR's {@code line L:C},
 * {@code at line N}, {@code (at …)}), the statement a library quotes ({@code in line: …}), numbers, the program's own
 * names (a word that is a name in the case's program, or any quoted word not all in capitals and no keyword), and
 * letter case. Keywords — {@code 'RANGE'}, {@code 'Or'}, {@code <END_VAR>} — stay, since they say what was refused.
 * The key is never shown; a group shows its first message verbatim.
 */
final class MessageCluster {
    private static final Pattern WORD = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");
    private static final Pattern QUOTED_WORD = Pattern.compile("(['\"<`])([A-Za-z_][A-Za-z0-9_]*)(['\">`])");
    /** Words of messages that a program may also use as a name, kept so that a name does not swallow the sentence. */
    private static final Set<String> PROSE = Set.of("a", "an", "the", "in", "on", "at", "to", "of", "is", "it", "or",
            "and", "not", "no", "for", "by", "be", "as", "with", "from", "line", "term", "terms", "rule", "rules",
            "value", "values", "input", "inputs", "output", "outputs", "variable", "variables", "block", "number",
            "name", "point", "points", "found", "expected", "unknown", "missing", "method", "default", "range", "type",
            "error", "level", "basic", "supported", "needs", "set");

    /** FCL's keywords in capitals (the grammar's literal tokens): a keyword in any letter case is not a name. */
    private static final Set<String> KEYWORDS = keywords();

    private MessageCluster() {
    }

    private static Set<String> keywords() {
        Set<String> words = new HashSet<>();
        org.antlr.v4.runtime.Vocabulary v = org.fclcert.syntax.FclLexer.VOCABULARY;
        for (int t = 0; t <= v.getMaxTokenType(); t++) {
            String literal = v.getLiteralName(t);
            if (literal != null && literal.matches("'[A-Za-z_]+'")) {
                words.add(literal.substring(1, literal.length() - 1).toUpperCase(Locale.ROOT));
            }
        }
        return Set.copyOf(words);
    }

    static String key(String message, String program) {
        Set<String> names = names(program);
        String s = message.strip();
        s = s.replaceAll("\\s+(?:in|from) line\\b.*$", "");      // the statement a library quotes
        s = s.replaceAll("\\bline \\d+:\\d+\\s*", "");           // ANTLR's position
        s = s.replaceAll("\\bat line \\d+", "at line N");
        s = s.replaceAll("\\s*\\(at [^)]*\\)", "");               // a stack frame
        Matcher q = QUOTED_WORD.matcher(s);
        StringBuilder out = new StringBuilder();
        while (q.find()) {
            String word = q.group(2);
            boolean keyword = KEYWORDS.contains(word.toUpperCase(Locale.ROOT))
                    || word.equals(word.toUpperCase(Locale.ROOT)) && !names.contains(word);
            q.appendReplacement(out, Matcher.quoteReplacement(q.group(1) + (keyword ? word : "…") + q.group(3)));
        }
        q.appendTail(out);
        Matcher w = WORD.matcher(out.toString());
        StringBuilder masked = new StringBuilder();
        while (w.find()) {
            String word = w.group();
            boolean name = names.contains(word) && !PROSE.contains(word.toLowerCase(Locale.ROOT));
            w.appendReplacement(masked, Matcher.quoteReplacement(name ? "…" : word));
        }
        w.appendTail(masked);
        s = masked.toString().replaceAll("(?<![\\w.])[-+]?\\d+(?:\\.\\d+)?(?:[eE][-+]?\\d+)?(?![\\w.])", "N");
        return s.replaceAll("\\s+", " ").strip().toLowerCase(Locale.ROOT);
    }

    /** The words of a program that are not all capitals: its names (FCL's keywords are written in capitals). */
    private static Set<String> names(String program) {
        Set<String> names = new HashSet<>();
        if (program == null) {
            return names;
        }
        String code = program.replaceAll("(?s)\\(\\*.*?\\*\\)", " ");
        Matcher m = WORD.matcher(code);
        while (m.find()) {
            String word = m.group();
            if (!word.equals(word.toUpperCase(Locale.ROOT)) && !KEYWORDS.contains(word.toUpperCase(Locale.ROOT))) {
                names.add(word);
            }
        }
        return names;
    }
}
