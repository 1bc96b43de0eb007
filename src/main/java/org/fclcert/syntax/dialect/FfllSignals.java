package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * Whether a text can hold an FFLL giveaway at all, from its words alone: the cheap first look of
 * {@link FfllReader#giveaways}, so that {@code --dialect auto} (and the language server on every edit) reads a
 * text through FFLL's whole pipeline only when it may find something. It errs one way only: {@code false} means
 * that the full scan would find no giveaway it counts; anything it is unsure of is {@code true}.
 *
 * <p>What the scan counts without a RANGE comment is only what weighs more than 1 ({@link FfllReader}): ACCUM,
 * RETAIN, {@code : =}, END_FUZZIFY closing DEFUZZIFY, a declaration without ':', FUZZIFY of an output, and a
 * subcondition or subconclusion without IS. Each has a word-level sign, looked for here.
 */
final class FfllSignals {
    private static final Pattern RANGE_COMMENT = Pattern.compile("\\(\\*\\s*RANGE", Pattern.CASE_INSENSITIVE);
    private static final Pattern SPACED_ASSIGN = Pattern.compile(":\\s+=");
    private static final Set<String> RULE_WORDS = Set.of("IF", "THEN", "AND", "OR", "NOT", "IS", "WITH");

    private FfllSignals() {
    }

    /** False only when FFLL's full giveaway scan of {@code text} surely finds nothing it counts. */
    static boolean possible(String text) {
        if (RANGE_COMMENT.matcher(text).find()) {
            return true;    // a RANGE comment makes even what is merely left out count
        }
        String code = blankComments(FfllReader.blankForeignComments(text));
        if (SPACED_ASSIGN.matcher(code).find()) {
            return true;
        }
        List<String> w = words(code);
        Rules rules = new Rules();
        Set<String> outputs = new HashSet<>();
        boolean inDefuzzify = false;
        for (int i = 0; i < w.size(); i++) {
            String x = w.get(i);
            switch (x) {
                case "ACCUM", "RETAIN", "NON_RETAIN" -> {
                    return true;
                }
                case "DEFUZZIFY" -> inDefuzzify = true;
                case "END_DEFUZZIFY" -> inDefuzzify = false;
                case "END_FUZZIFY" -> {
                    if (inDefuzzify) {
                        return true;
                    }
                }
                case "VAR_INPUT", "VAR_OUTPUT", "VAR" -> {
                    int end = declarations(w, i + 1, x.equals("VAR_OUTPUT") ? outputs : null);
                    if (end < 0) {
                        return true;
                    }
                    i = end;
                }
                case "FUZZIFY" -> {
                    if (i + 1 >= w.size() || outputs.contains(w.get(i + 1))) {
                        return true;
                    }
                }
                case "RULE" -> {
                    int end = rule(w, i + 1, rules);
                    if (end < 0) {
                        return true;
                    }
                    i = end;
                }
                default -> {
                }
            }
        }
        // a name without IS counts only in a model, and a rule running into the next is a syntax error: no model
        return rules.nameWithoutIs && !rules.runsOn;
    }

    /** What the look at the rules found. */
    private static final class Rules {
        /** A name in a rule stands without IS beside it (a term-only subcondition or subconclusion, or a degree). */
        boolean nameWithoutIs;
        /**
         * A rule runs into the next RULE or END_RULEBLOCK without its ';'. Fcl.g4's fuzzyRule ends with ';' and takes
         * RULE nowhere after IF (a keyword is no name), so FFLL's read of the text has a syntax error and gives no
         * program; the term-only constructs are found in the program only ({@link FfllReader#readGiveaways}: what
         * the token filter finds alone is ACCUM, RETAIN, ': =', END_FUZZIFY, a declaration without ':', a RANGE
         * comment, MoM and an unnamed block, each looked for on its own here).
         */
        boolean runsOn;
    }

    /**
     * Reads a VAR section from {@code from}: the index of its END_VAR, or -1 when a declaration lacks its ':',
     * RETAIN is written or the section does not end; the names declared are added to {@code names} when given.
     */
    private static int declarations(List<String> w, int from, Set<String> names) {
        boolean colon = false;
        List<String> pending = new ArrayList<>();
        for (int i = from; i < w.size(); i++) {
            String x = w.get(i);
            if (x.equals("END_VAR")) {
                return colon || pending.isEmpty() ? i : -1;
            }
            if (x.equals("RETAIN") || x.equals("NON_RETAIN")) {
                return -1;
            }
            if (x.equals(";")) {
                if (!colon) {
                    return -1;
                }
                colon = false;
                pending.clear();
            } else if (x.equals(":")) {
                colon = true;
                if (names != null) {
                    names.addAll(pending);
                }
            } else if (!colon) {
                pending.add(x);
            }
        }
        return -1;
    }

    /**
     * Reads a rule from after RULE: the index of its ';', or of the word before the RULE or END_RULEBLOCK it runs
     * into; -1 when it has no IF before a ';' or runs to the end of the text. A name in it standing without IS
     * beside it (a term-only subcondition or subconclusion, or a variable as a degree: the full scan decides those)
     * and a rule running on are noted in {@code found}.
     */
    private static int rule(List<String> w, int from, Rules found) {
        int i = from;
        while (i < w.size() && !w.get(i).equals("IF")) {
            if (w.get(i).equals(";")) {
                return -1;
            }
            i++;
        }
        for (i = i + 1; i < w.size(); i++) {
            String x = w.get(i);
            if (x.equals(";")) {
                return i;
            }
            if (x.equals("RULE") || x.equals("END_RULEBLOCK")) {
                found.runsOn = true;
                return i - 1;
            }
            if (!Character.isLetter(x.charAt(0)) && x.charAt(0) != '_' || RULE_WORDS.contains(x)) {
                continue;
            }
            boolean before = w.get(i - 1).equals("IS") || w.get(i - 1).equals("NOT") && w.get(i - 2).equals("IS");
            boolean after = i + 1 < w.size() && w.get(i + 1).equals("IS");
            if (!before && !after) {
                found.nameWithoutIs = true;
            }
        }
        return -1;
    }

    /** The words and signs of a text without comments, upper-cased; a number is one word. */
    private static List<String> words(String code) {
        List<String> w = new ArrayList<>(code.length() / 4);
        int n = code.length();
        int i = 0;
        while (i < n) {
            char c = code.charAt(i);
            if (Character.isWhitespace(c)) {
                i++;
            } else if (Character.isLetter(c) || c == '_') {
                int start = i;
                while (i < n && (Character.isLetterOrDigit(code.charAt(i)) || code.charAt(i) == '_')) {
                    i++;
                }
                w.add(code.substring(start, i).toUpperCase(Locale.ROOT));
            } else if (Character.isDigit(c)) {
                while (i < n && (Character.isLetterOrDigit(code.charAt(i)) || code.charAt(i) == '.')) {
                    i++;
                }
                w.add("0");
            } else if (c == ':' && i + 1 < n && code.charAt(i + 1) == '=') {
                w.add(":=");
                i += 2;
            } else {
                w.add(String.valueOf(c));
                i++;
            }
        }
        return w;
    }

    /** The text with its {@code (* *)} comments blanked out, lines kept. */
    private static String blankComments(String text) {
        StringBuilder b = new StringBuilder(text);
        int i = text.indexOf("(*");
        while (i >= 0) {
            int end = text.indexOf("*)", i + 2);
            int stop = end < 0 ? text.length() : end + 2;
            for (int j = i; j < stop; j++) {
                if (text.charAt(j) != '\n') {
                    b.setCharAt(j, ' ');
                }
            }
            i = stop >= text.length() ? -1 : text.indexOf("(*", stop);
        }
        return b.toString();
    }
}
