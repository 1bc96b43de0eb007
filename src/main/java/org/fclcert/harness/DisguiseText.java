package org.fclcert.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The order and layout part of a {@link Disguise}: a program text as tokens (comments and blank runs kept as
 * tokens of their own, so that nothing inside a comment or a number is ever touched), reordered where clause 5.2
 * leaves the order free and laid out anew, each token remembering where it was so that a negative case's error
 * place follows the transformation:
 * <ul>
 * <li>declarations within each VAR_INPUT and VAR_OUTPUT section; FUZZIFY blocks among the FUZZIFY blocks next to
 * them, DEFUZZIFY blocks likewise; TERMs within a run of TERMs of one FUZZIFY or DEFUZZIFY block; RULEs within a run
 * of RULEs of one rule block (5.2 and the semantics: accumulation is commutative, so no result depends on the rule
 * order; the disguise checks that on the exact path before using a text);</li>
 * <li>now and then a blank line put between two statements ({@link #broken});</li>
 * <li>every line's indentation drawn anew.</li>
 * </ul>
 * A segment moves with the blanks and comments in front of it, so a comment on its own line stays with what it
 * describes.
 */
final class DisguiseText {
    private static final Pattern TOKEN = Pattern.compile("\\(\\*.*?(?:\\*\\)|\\z)|\\s+|[A-Za-z_][A-Za-z0-9_]*|.",
            Pattern.DOTALL);

    /** One token: its text, and its index in the text it was read from (-1: made by the transformation). */
    private record Token(String text, int origin) {
        boolean blank() {
            return text.isBlank();
        }

        boolean comment() {
            return text.startsWith("(*");
        }

        boolean significant() {
            return !blank() && !comment();
        }

        boolean is(String word) {
            return significant() && text.toUpperCase(Locale.ROOT).equals(word);
        }
    }

    /** A 1-based line and column. */
    record Place(int line, int column) {
    }

    private final List<Token> tokens;
    /** Offset of each token of the text read, by origin. */
    private final int[] offsets;

    private DisguiseText(List<Token> tokens, int[] offsets) {
        this.tokens = tokens;
        this.offsets = offsets;
    }

    static DisguiseText of(String text) {
        List<Token> tokens = new ArrayList<>();
        List<Integer> offsets = new ArrayList<>();
        Matcher m = TOKEN.matcher(text);
        while (m.find()) {
            offsets.add(m.start());
            tokens.add(new Token(m.group(), tokens.size()));
        }
        return new DisguiseText(tokens, offsets.stream().mapToInt(Integer::intValue).toArray());
    }

    String text() {
        StringBuilder b = new StringBuilder();
        tokens.forEach(t -> b.append(t.text()));
        return b.toString();
    }

    /**
     * The origin of the token at {@code place} of the text read: the token that covers it or, in blanks and
     * comments, the next significant one; -1 when none follows (the end of the text).
     */
    int originAt(String read, Place place) {
        int offset = offsetOf(read, place);
        if (offset < 0) {
            return -1;
        }
        for (int i = 0; i < offsets.length; i++) {
            int end = i + 1 < offsets.length ? offsets[i + 1] : read.length();
            if (offset < end && (offset >= offsets[i])) {
                for (int j = i; j < tokens.size(); j++) {
                    Token t = tokens.get(j);
                    if (t.origin() == j && t.significant()) {
                        return j;
                    }
                }
                return -1;
            }
        }
        return -1;
    }

    /** Where the token of {@code origin} now is; empty when it is not in the text (or origin is -1). */
    java.util.Optional<Place> placeOf(int origin) {
        int line = 1;
        int column = 1;
        for (Token t : tokens) {
            if (origin >= 0 && t.origin() == origin) {
                return java.util.Optional.of(new Place(line, column));
            }
            for (int i = 0; i < t.text().length(); i++) {
                if (t.text().charAt(i) == '\n') {
                    line++;
                    column = 1;
                } else {
                    column++;
                }
            }
        }
        return java.util.Optional.empty();
    }

    private static int offsetOf(String text, Place place) {
        int line = 1;
        int i = 0;
        while (line < place.line()) {
            int nl = text.indexOf('\n', i);
            if (nl < 0) {
                return -1;
            }
            i = nl + 1;
            line++;
        }
        int offset = i + place.column() - 1;
        return offset <= text.length() ? offset : -1;
    }

    /** Declarations, blocks, terms and rules reordered where the order is free. */
    DisguiseText reordered(SplittableRandom random) {
        List<Token> t = tokens;
        t = permuteRuns(t, "TERM", ";", random);
        t = permuteRuns(t, "RULE", ";", random);
        t = permuteDeclarations(t, random);
        t = permuteRuns(t, "FUZZIFY", "END_FUZZIFY", random);
        t = permuteRuns(t, "DEFUZZIFY", "END_DEFUZZIFY", random);
        return new DisguiseText(t, offsets);
    }

    /**
     * With one chance in {@code oneIn}, a line break between two statements doubled (a blank line put there). Breaks
     * within a statement would be as legal, but a line-oriented reader (fuzzylite's) then refuses every case for its
     * layout and the case's own deviation goes unseen; and they buy nothing against a lookup, which ignores blanks.
     */
    DisguiseText broken(SplittableRandom random, int oneIn) {
        List<Token> out = new ArrayList<>();
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            if (t.blank() && t.text().contains("\n") && i > 0 && i + 1 < tokens.size() && random.nextInt(oneIn) == 0) {
                out.add(new Token("\n" + t.text(), t.origin()));
            } else {
                out.add(t);
            }
        }
        return new DisguiseText(out, offsets);
    }

    /** Each line's indentation (the blanks after a line break, outside comments) drawn anew: 0 to 6 spaces. */
    DisguiseText indented(SplittableRandom random) {
        List<Token> out = new ArrayList<>();
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            if (t.blank() && t.text().contains("\n")) {
                String[] lines = t.text().split("\n", -1);
                StringBuilder b = new StringBuilder();
                for (int k = 0; k < lines.length - 1; k++) {
                    b.append('\n');   // blank lines stay empty; trailing blanks dropped
                }
                boolean more = i + 1 < tokens.size();
                b.append(more ? " ".repeat(random.nextInt(7)) : "");
                out.add(new Token(b.toString(), t.origin()));
            } else {
                out.add(t);
            }
        }
        return new DisguiseText(out, offsets);
    }

    /** Runs of segments that start with {@code start} and end with {@code end}, each run shuffled. */
    private static List<Token> permuteRuns(List<Token> in, String start, String end, SplittableRandom random) {
        List<Token> out = new ArrayList<>();
        int i = 0;
        while (i < in.size()) {
            int first = nextSignificant(in, i);
            if (first < 0) {
                out.addAll(in.subList(i, in.size()));
                break;
            }
            if (!in.get(first).is(start)) {
                out.addAll(in.subList(i, first + 1));
                i = first + 1;
                continue;
            }
            List<List<Token>> segments = new ArrayList<>();
            int from = i;
            int at = first;
            while (at >= 0 && in.get(at).is(start)) {
                int stop = find(in, at + 1, t -> t.is(end) || t.is(start) && !end.equals(";"));
                if (stop < 0 || !in.get(stop).is(end)) {
                    break;
                }
                segments.add(in.subList(from, stop + 1));
                from = stop + 1;
                at = nextSignificant(in, from);
            }
            if (segments.isEmpty()) {
                out.addAll(in.subList(i, first + 1));
                i = first + 1;
                continue;
            }
            shuffle(segments, random).forEach(out::addAll);
            i = from;
        }
        return out;
    }

    /** The declarations of each VAR_INPUT and VAR_OUTPUT section, shuffled within it. */
    private static List<Token> permuteDeclarations(List<Token> in, SplittableRandom random) {
        List<Token> out = new ArrayList<>();
        int i = 0;
        while (i < in.size()) {
            Token t = in.get(i);
            out.add(t);
            i++;
            if (!(t.is("VAR_INPUT") || t.is("VAR_OUTPUT"))) {
                continue;
            }
            int close = find(in, i, x -> x.is("END_VAR") || x.is("VAR_INPUT") || x.is("VAR_OUTPUT") || x.is("VAR"));
            if (close < 0 || !in.get(close).is("END_VAR")) {
                continue;
            }
            List<List<Token>> segments = new ArrayList<>();
            int from = i;
            int semi;
            while ((semi = find(in.subList(0, close), from, x -> x.is(";"))) >= 0) {
                segments.add(in.subList(from, semi + 1));
                from = semi + 1;
            }
            shuffle(segments, random).forEach(out::addAll);
            i = from;
        }
        return out;
    }

    private static List<List<Token>> shuffle(List<List<Token>> segments, SplittableRandom random) {
        List<List<Token>> s = new ArrayList<>(segments);
        for (int k = s.size() - 1; k > 0; k--) {
            int j = random.nextInt(k + 1);
            List<Token> x = s.get(k);
            s.set(k, s.get(j));
            s.set(j, x);
        }
        return s;
    }

    private static int nextSignificant(List<Token> in, int from) {
        return find(in, from, Token::significant);
    }

    private static int find(List<Token> in, int from, Predicate<Token> p) {
        for (int k = from; k < in.size(); k++) {
            if (in.get(k).significant() && p.test(in.get(k))) {
                return k;
            }
        }
        return -1;
    }
}
