package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.ReadResult;

/**
 * The reader of each dialect, and {@code --dialect auto}: which dialect a text is written in, or that it
 * cannot tell.
 */
public final class DialectReaders {
    /** A dialect wins only with at least this many times the weight of the runner-up; closer is a close call. */
    static final double CLEAR_LEAD = 2.0;
    private static final java.util.regex.Pattern TERM = java.util.regex.Pattern.compile(
            "(?i)(^|[^A-Za-z0-9_])TERM($|[^A-Za-z0-9_])");

    private DialectReaders() {
    }

    /** The reader of a dialect: the strict reader for {@link Dialect#STRICT}. */
    public static FclReader reader(Dialect dialect) {
        return dialect.reader();
    }

    /** The dialect readers (every format but the standard), in the order of {@link Dialect}: how candidates are named. */
    static List<DialectReader> dialectReaders() {
        List<DialectReader> out = new ArrayList<>();
        for (Dialect d : Dialect.values()) {
            if (d.reader() instanceof DialectReader r) {
                out.add(r);
            }
        }
        return out;
    }

    /** One dialect's evidence in a text: its giveaways and their total weight. */
    public record Evidence(Dialect dialect, List<DialectReader.Giveaway> giveaways) {
        public Evidence {
            giveaways = List.copyOf(giveaways);
        }

        /**
         * The giveaways' weights added up; a supporting giveaway (weight 0: a standard construct the library's
         * users write, such as lower-case rule keywords) adds 1, but only to evidence that has a weight already.
         */
        public int weight() {
            int primary = giveaways.stream().mapToInt(DialectReader.Giveaway::weight).sum();
            return primary == 0 ? 0 : primary + (int) giveaways.stream().filter(g -> g.weight() == 0).count();
        }
    }

    /**
     * What {@link #auto} found.
     *
     * @param dialect    the dialect chosen; when {@link #unsure()}, the one with the most weight (not to be read in)
     * @param giveaways  the constructs that decided it (empty for strict)
     * @param tiedWith   the other candidates of a close call (empty when the choice is clear)
     * @param problem    a located error instead of a choice: a close call (FCL-S311) or an internal error of a
     *                   detector (FCL-S999); empty when the choice can be read in
     */
    public record Choice(Dialect dialect, List<DialectReader.Giveaway> giveaways, List<Dialect> tiedWith,
            Optional<Diagnostic> problem) {
        public Choice {
            giveaways = List.copyOf(giveaways);
            tiedWith = List.copyOf(tiedWith);
        }

        public Choice(Dialect dialect, List<DialectReader.Giveaway> giveaways, List<Dialect> tiedWith) {
            this(dialect, giveaways, tiedWith, Optional.empty());
        }

        /** True when auto cannot tell the dialect (or its detection failed): {@link #problem()} says why. */
        public boolean unsure() {
            return problem.isPresent();
        }

        /**
         * The reader to read the text with: the chosen dialect's, or, when {@link #unsure()}, one that yields
         * only the located problem (so a close call is an error with a code, never a guess).
         */
        public FclReader reader() {
            if (problem.isEmpty()) {
                return DialectReaders.reader(dialect);
            }
            Diagnostic d = problem.get();
            return (source, text) -> new ReadResult(Optional.empty(), List.of(Diagnostic.error(
                    SourceLocation.of(source == null ? "<input>" : source, d.location().line(), d.location().column()),
                    d.diagnosticCode(), d.message())));
        }

        /** One line for the user: {@code read as FFLL: ACCUM: at line 30, term-only subcondition at line 41}. */
        public String explanation() {
            if (problem.isPresent()) {
                return "dialect not recognised: " + problem.get().message();
            }
            if (dialect == Dialect.STRICT) {
                return "read as standard FCL (strict)";
            }
            return "read as " + dialect.displayName() + ": " + shown(giveaways);
        }
    }

    static String shown(List<DialectReader.Giveaway> giveaways) {
        StringBuilder s = new StringBuilder();
        int shown = Math.min(giveaways.size(), 5);
        for (int i = 0; i < shown; i++) {
            DialectReader.Giveaway g = giveaways.get(i);
            s.append(i == 0 ? "" : ", ").append(g.construct()).append(" at line ").append(g.line());
        }
        if (giveaways.size() > shown) {
            s.append(" and ").append(giveaways.size() - shown).append(" more");
        }
        return s.toString();
    }

    /** Every dialect's evidence in the text, in the order of {@link Dialect}. */
    public static List<Evidence> evidence(String text) {
        return evidence(text, new boolean[1]);
    }

    /** The same, noting in {@code ffllRead[0]} whether FFLL's first look sent the text through its full read. */
    private static List<Evidence> evidence(String text, boolean[] ffllRead) {
        String t = text == null ? "" : text;
        List<Evidence> out = new ArrayList<>();
        for (DialectReader r : dialectReaders()) {
            if (r instanceof FfllReader) {
                // FfllReader.giveaways, with its first look's answer kept for {@link #kept}
                ffllRead[0] = FfllSignals.possible(t);
                out.add(new Evidence(r.dialect(), ffllRead[0] ? FfllReader.readGiveaways(t) : List.of()));
            } else {
                out.add(new Evidence(r.dialect(), r.giveaways(t)));
            }
        }
        return out;
    }

    /**
     * {@link #auto}'s choice for a text, with what {@link #kept} needs to know of how it was made: whether FFLL's
     * first look sent the text through FFLL's full read (whose outcome, unlike every other giveaway scan, may
     * depend on a number's value).
     */
    public record Detection(Choice choice, boolean ffllRead) {
    }

    /** {@link #auto}, as a {@link Detection}. */
    public static Detection detect(String text) {
        boolean[] ffllRead = new boolean[1];
        List<Evidence> all;
        try {
            all = evidence(text, ffllRead);
        } catch (RuntimeException | StackOverflowError e) {
            return new Detection(detectionFailed(e), true);
        }
        return new Detection(choose(all), ffllRead[0]);
    }

    /**
     * Whether a detection made of {@code text} surely holds for the text after one edit (the characters
     * {@code from} to {@code to} replaced by {@code inserted}), without detecting again: what an editor sends
     * while a number is typed over. True only when ASCII digits are replaced by ASCII digits inside a number (a
     * run of digits and dots with no letter, digit, '_' or '#' around it), outside any TERM statement, and FFLL's
     * full read was not needed. Then no giveaway scan can see a difference: they look at words, signs, comments
     * and lines, which such an edit leaves as they were (the digits of a number are one word to FFLL's first
     * look, one number token to the dialect lexer, whatever they are), except two that read values, neither
     * reached: jFuzzyLogic's test of a DEFUZZIFY term's degrees ({@link JFuzzyLogicHabits}, inside TERM) and
     * FFLL's full read (which may succeed or fail on a value). FIS's and FLL's line patterns take any digits.
     */
    public static boolean kept(Detection before, String text, int from, int to, String inserted) {
        if (before.ffllRead() || before.choice().unsure() && before.choice().problem().get().diagnosticCode()
                != DialectCode.DIALECT_UNCLEAR || from < 0 || to > text.length() || from >= to
                || inserted.isEmpty() || !digits(inserted) || !digits(text.substring(from, to))) {
            return false;
        }
        int start = from;
        while (start > 0 && numberChar(text.charAt(start - 1))) {
            start--;
        }
        int end = to;
        while (end < text.length() && numberChar(text.charAt(end))) {
            end++;
        }
        if (start > 0 && wordChar(text.charAt(start - 1)) || end < text.length() && wordChar(text.charAt(end))) {
            return false;    // part of a name, a based number or an exponent: a token of another kind
        }
        return outsideTerm(text, start);
    }

    /**
     * True when the statement holding {@code at} is surely no TERM: back to the ';' before it there is no word
     * TERM, and that ';' is no comment's (no comment mark before it on its line, and no comment closes between it
     * and {@code at} that did not open there too; a comment still open at {@code at} holds the edit, which is then
     * no token's).
     */
    private static boolean outsideTerm(String text, int at) {
        int i = at - 1;
        while (i >= 0 && text.charAt(i) != ';') {
            i--;
        }
        if (i < 0) {
            return false;
        }
        String statement = text.substring(i + 1, at);
        String beforeSemicolon = text.substring(text.lastIndexOf('\n', i) + 1, i);
        return !beforeSemicolon.contains("(*") && !beforeSemicolon.contains("/*") && !beforeSemicolon.contains("//")
                && !beforeSemicolon.contains("#") && commentsOpenBeforeTheyClose(statement)
                && !TERM.matcher(statement).find();
    }

    /** False when a {@code *)} or {@code *\/} in {@code s} closes a comment that did not open in {@code s}. */
    private static boolean commentsOpenBeforeTheyClose(String s) {
        int k = 0;
        while (k < s.length()) {
            if (s.startsWith("*)", k) || s.startsWith("*/", k)) {
                return false;
            }
            String close = s.startsWith("(*", k) ? "*)" : s.startsWith("/*", k) ? "*/"
                    : s.startsWith("//", k) || s.charAt(k) == '#' ? "\n" : null;
            if (close == null) {
                k++;
                continue;
            }
            int end = s.indexOf(close, k + (close.equals("\n") ? 1 : 2));
            if (end < 0) {
                return true;     // still open at the edit
            }
            k = end + close.length();
        }
        return true;
    }

    private static boolean digits(String s) {
        for (int k = 0; k < s.length(); k++) {
            if (s.charAt(k) < '0' || s.charAt(k) > '9') {
                return false;
            }
        }
        return true;
    }

    private static boolean numberChar(char c) {
        return c >= '0' && c <= '9' || c == '.';
    }

    private static boolean wordChar(char c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '#';
    }

    /**
     * The dialect of a text: the dialect whose giveaways weigh most, weighed by how specific each is
     * ({@link DialectReader.Giveaway#weight}), when it weighs at least {@link #CLEAR_LEAD} times the runner-up;
     * strict when no dialect shows any (the case of every standard program: giveaways are constructs outside
     * the standard), and then the strict reader's errors, if any, say what is wrong. On a close call the choice
     * is {@link Choice#unsure()} with a located FCL-S311 naming the candidates and asking for {@code --dialect};
     * a failure of a detector is a located FCL-S999. Giveaways decide even when the strict reader reads the text
     * without a syntax error: an FFLL rule naming only terms parses as standard FCL but means something else.
     * Never throws.
     */
    public static Choice auto(String text) {
        return detect(text).choice();
    }

    private static Choice detectionFailed(Throwable e) {
        Throwable cause = e.getCause() == null ? e : e.getCause();
        return new Choice(Dialect.STRICT, List.of(), List.of(),
                Optional.of(DialectParser.internalError("<input>", "dialect detection ("
                        + e.getMessage() + ")", cause)));
    }

    /** The choice the evidence makes (see {@link #auto}). */
    private static Choice choose(List<Evidence> all) {
        List<Evidence> ranked = new ArrayList<>(all.stream().filter(e -> e.weight() > 0).toList());
        ranked.sort((a, b) -> Integer.compare(b.weight(), a.weight()));     // stable: ties keep the order of Dialect
        if (ranked.isEmpty()) {
            return new Choice(Dialect.STRICT, List.of(), List.of());
        }
        Evidence best = ranked.get(0);
        List<Evidence> close = ranked.subList(1, ranked.size()).stream()
                .filter(e -> best.weight() < CLEAR_LEAD * e.weight()).toList();
        if (close.isEmpty()) {
            return new Choice(best.dialect(), best.giveaways(), List.of());
        }
        StringBuilder m = new StringBuilder("signs of ");
        List<Evidence> candidates = new ArrayList<>();
        candidates.add(best);
        candidates.addAll(close);
        for (int i = 0; i < candidates.size(); i++) {
            Evidence e = candidates.get(i);
            m.append(i == 0 ? "" : i == candidates.size() - 1 ? " and of " : ", of ").append(e.dialect().displayName())
                    .append(" (weight ").append(e.weight()).append(": ").append(shown(e.giveaways())).append(')');
        }
        m.append(", none clearly ahead; name the dialect with --dialect ")
                .append(String.join(" or --dialect ", candidates.stream().map(e -> e.dialect().cliName()).toList()));
        DialectReader.Giveaway first = best.giveaways().get(0);
        Diagnostic d = Diagnostic.error(SourceLocation.of("<input>", first.line(), 1), DialectCode.DIALECT_UNCLEAR,
                m.toString());
        return new Choice(best.dialect(), best.giveaways(), close.stream().map(Evidence::dialect).toList(),
                Optional.of(d));
    }
}
