package org.fclcert.harness;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.ExpectedError;
import org.fclcert.corpus.Vector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.NumberReading;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.syntax.StrictReader;

/**
 * The disguise of one case in one run: the program text sent to the implementation is the corpus program with
 * its meaning kept and its look drawn from the run seed, so that an implementation cannot find the case by its
 * text and replay remembered answers. Drawn per case from {@link RunSeed#forCase}, so that {@code --seed}
 * replays it exactly:
 * <ul>
 * <li>every name the program declares (function blocks, variables, terms, rule blocks) renamed consistently —
 * names are not case-sensitive (IEC 61131-3 B.1.1), so all spellings of one name get the same new name; eval
 * requests and replies are mapped both ways ({@link DisguisedIut}), an exported text is mapped back;</li>
 * <li>rule numbers renumbered one to one (a duplicate stays a duplicate);</li>
 * <li>declarations, FUZZIFY and DEFUZZIFY blocks, terms and rules reordered where 5.2 leaves the order free, a
 * blank within a statement now and then turned into a line break, every line indented anew ({@link DisguiseText}),
 * comments rewritten (positive cases), and 1 to 3 blank lines put in front;</li>
 * <li>a negative case's expected error follows the transformation: the token the reference's error points at in
 * the corpus text is followed to its new line and column, and the reference must report the error there;</li>
 * <li>a negative case brings its accepted twin ({@link RepairedTwin}), disguised by the same steps.</li>
 * </ul>
 * Each disguise is checked before it is used: a positive case must read without error and evaluate, on the
 * reference's exact path, to the same values as the corpus text on every vector; a negative case must still
 * have its error, with the same code, at the moved line. Where a step of the disguise fails that check, the
 * weaker disguise without it is used (the leading blank lines alone always keep both), so the text sent never
 * equals the corpus text.
 */
public final class Disguise {
    private static final Pattern COMMENT_OR_WORD = Pattern.compile("\\(\\*.*?(\\*\\)|\\z)|[A-Za-z_][A-Za-z0-9_]*",
            Pattern.DOTALL);
    private static final Pattern RULE_NUMBER = Pattern.compile("(?i)(RULE\\s+)(\\d+)(\\s*:)");
    private static final String LETTERS = "abcdefghijklmnopqrstuvwxyz";
    private static final String ALNUM = LETTERS + "0123456789";
    /** One line break between statements in this many gets a blank line after it. */
    private static final int BREAK_ONE_IN = 6;

    /** New name per {@link Names#key} of an original name. */
    private final Map<String, String> names;
    /** Original spelling (as declared) per key of a new name. */
    private final Map<String, String> originals;
    private final String text;
    private final int lineShift;
    private final Optional<ExpectedError> expectedError;
    private final Optional<DisguiseText.Place> errorPlace;
    private final boolean reordered;
    private final Optional<Twin> twin;

    private Disguise(Map<String, String> names, Map<String, String> originals, String text, int lineShift,
            Optional<ExpectedError> expectedError, Optional<DisguiseText.Place> errorPlace, boolean reordered,
            Optional<Twin> twin) {
        this.names = names;
        this.originals = originals;
        this.text = text;
        this.lineShift = lineShift;
        this.expectedError = expectedError;
        this.errorPlace = errorPlace;
        this.reordered = reordered;
        this.twin = twin;
    }

    /**
     * A negative case's accepted twin as sent ({@link RepairedTwin}, disguised as the case is): the program with its
     * defect repaired, which an implementation must load for its rejection of the case to count; empty when the
     * case has none.
     */
    public Optional<Twin> twin() {
        return twin;
    }

    /** A negative case's accepted twin as sent, and whether it is loaded before the case (drawn) or after it. */
    public record Twin(String text, boolean first) {
    }

    /** Where the token the reference's error points at in the corpus text now is (line and column). */
    Optional<DisguiseText.Place> errorPlace() {
        return errorPlace;
    }

    /** Whether declarations, blocks, terms and rules were reordered. */
    public boolean reordered() {
        return reordered;
    }

    /** The text sent in place of the corpus program. */
    public String text() {
        return text;
    }

    /** How many lines were put in front of the program (a negative case's error moved down by as many). */
    public int lineShift() {
        return lineShift;
    }

    /** How many names were renamed. */
    public int renamed() {
        return names.size();
    }

    /** The case as sent: its program the disguised text, a negative case's error at the moved line. */
    public RunCase apply(RunCase c) {
        return new RunCase(c.id(), c.title(), c.level(), c.features(), c.tests(), c.flags(), c.block(), c.vectors(),
                expectedError, c.tolerance(), text, c.source(), c.dialect());
    }

    /** The disguised name of {@code name} (a name the program does not declare stays as it is). */
    public String sent(String name) {
        return name == null ? null : names.getOrDefault(Names.key(name), name);
    }

    /** Inputs as sent: every name disguised. */
    public Map<String, Double> sent(Map<String, Double> values) {
        Map<String, Double> out = new LinkedHashMap<>();
        values.forEach((k, v) -> out.put(sent(k), v));
        return out;
    }

    /**
     * A reply mapped back to the corpus's names; a name that was never sent (an implementation answering with a
     * name it was not told, such as the corpus's own) is marked, so it never counts as the output asked for.
     */
    public Map<String, Double> received(Map<String, Double> values) {
        if (values == null) {
            return null;
        }
        Map<String, Double> out = new LinkedHashMap<>();
        values.forEach((k, v) -> out.put(k == null ? null : originals.getOrDefault(Names.key(k),
                names.isEmpty() ? k : "(a name not sent) " + k), v));
        return out;
    }

    /** An exported text with every disguised name turned back into the corpus's. */
    public String undisguised(String exported) {
        return rename(exported, originals);
    }

    /**
     * Why {@code c} is sent undisguised, or empty when it is disguised. A case written in a library's dialect is exempt:
     * every step of the disguise (renaming, rule numbers, comments, reordering, line breaks) rewrites standard FCL's
     * tokens and sections ({@link DisguiseText}) and is checked by reading the result with the standard's reader, and a
     * dialect's text (rules that end with their line, {@code #} comments, shape names, hedges) is neither, so a
     * rewritten dialect text could change its meaning unchecked. Such a case still gets its fresh vectors.
     */
    public static Optional<String> exemption(RunCase c) {
        return c.inDialect() ? Optional.of("written in " + c.dialect().displayName() + "'s dialect: the disguise rewrites"
                + " and checks standard FCL text only, so the program is sent as the corpus writes it") : Optional.empty();
    }

    /** Draws the disguise of {@code c} from {@code random} (none for a case {@link #exemption exempt} from it). */
    public static Disguise draw(RunCase c, SplittableRandom random) {
        if (exemption(c).isPresent()) {
            return new Disguise(Map.of(), Map.of(), c.program(), 0, c.expectedError(), Optional.empty(), false,
                    Optional.empty());
        }
        // a negative case's program has an error: the reader's program (when it has one) still names what it declares
        Program original = (c.expectReject() ? partial(c.program()) : read(c.program())).orElse(null);
        Map<String, String> renames = new LinkedHashMap<>();
        Map<String, String> spellings = new LinkedHashMap<>();
        if (original != null) {
            Set<String> taken = new HashSet<>();
            COMMENT_OR_WORD.matcher(c.program()).results().forEach(m -> taken.add(Names.key(m.group())));
            for (String name : declaredNames(original)) {
                String key = Names.key(name);
                if (!renames.containsKey(key)) {
                    String fresh;
                    do {
                        fresh = freshName(random);
                    } while (!taken.add(Names.key(fresh)));
                    renames.put(key, fresh);
                    spellings.put(Names.key(fresh), name);
                }
            }
        }
        Map<String, String> twinRenames = new LinkedHashMap<>(renames);
        twinRenames.put(Names.key(RepairedTwin.NEW_NAME), freshName(random));
        boolean twinFirst = random.nextBoolean();
        int shift = 1 + random.nextInt(3);
        // blank lines, not comments: a comment before the first block is itself a reason some libraries refuse a
        // program (fuzzylite), and the disguise must not add reasons of its own
        String head = "\n".repeat(shift);
        long commentSeed = random.nextLong();
        long layoutSeed = random.nextLong();
        int ruleBase = 1 + random.nextInt(900);
        long orderSeed = random.nextLong();
        long breakSeed = random.nextLong();
        String renamed = renumberRules(rename(c.program(), renames), ruleBase);
        Optional<String> twin = RepairedTwin.of(c).map(t -> renumberRules(rename(t, twinRenames), ruleBase));
        Steps steps = new Steps(orderSeed, breakSeed, layoutSeed);
        // strongest first; each later one drops a step whose check failed
        List<Step[]> levels = List.of(new Step[] {Step.ORDER, Step.BREAKS, Step.INDENT},
                new Step[] {Step.ORDER, Step.INDENT}, new Step[] {Step.INDENT}, new Step[] {});
        if (!c.expectReject()) {
            String commented = rewriteComments(renamed, commentSeed);
            for (Step[] level : levels) {
                for (String base : level.length == 0 ? List.of(renamed) : List.of(commented, renamed)) {
                    String candidate = steps.apply(DisguiseText.of(head + base), level).text();
                    if (sameMeaning(c, original, candidate, renames)) {
                        return new Disguise(renames, spellings, candidate, shift, Optional.empty(), Optional.empty(),
                                level.length > 0 && level[0] == Step.ORDER, Optional.empty());
                    }
                }
            }
        } else {
            ExpectedError want = c.expectedError().orElseThrow();
            // the error as the reference places it in the renamed text, and the token there, followed through every step
            Optional<Diagnostic> at = errorAt(renamed, want);
            DisguiseText read = DisguiseText.of(head + renamed);
            int origin = at.map(d -> read.originAt(head + renamed, new DisguiseText.Place(d.location().line() + shift,
                    d.location().column()))).orElse(-1);
            for (Step[] level : origin < 0 ? List.<Step[]>of() : levels) {
                DisguiseText sent = steps.apply(read, level);
                Optional<DisguiseText.Place> place = sent.placeOf(origin);
                if (place.isEmpty()) {
                    continue;
                }
                ExpectedError moved = new ExpectedError(want.code(), place.get().line());
                if (stillRejected(sent.text(), moved)) {
                    Optional<Twin> sentTwin = twin.map(t -> steps.apply(DisguiseText.of(head + t), level).text())
                            .filter(Disguise::loads).map(t -> new Twin(t, twinFirst));
                    return new Disguise(renames, spellings, sent.text(), shift, Optional.of(moved), place,
                            level.length > 0 && level[0] == Step.ORDER, sentTwin);
                }
            }
        }
        // the leading blank lines alone: they change neither the meaning nor the error; the error's line is
        // where the reference places it (an empty program's error stays at line 1)
        String text = head + c.program();
        Optional<ExpectedError> moved = c.expectedError().map(e -> new ExpectedError(e.code(), e.line() + shift));
        Optional<ExpectedError> placed = moved.map(e -> new ExpectedError(e.code(), lineOf(text, e.code()).orElse(e.line())));
        return new Disguise(Map.of(), Map.of(), text, shift, placed, Optional.empty(), false,
                RepairedTwin.of(c).map(t -> head + t).filter(Disguise::loads).map(t -> new Twin(t, twinFirst)));
    }

    /** The order and layout steps of one disguise, each drawing from its own seed. */
    private enum Step {
        ORDER, BREAKS, INDENT
    }

    private record Steps(long order, long breaks, long indent) {
        DisguiseText apply(DisguiseText t, Step[] level) {
            DisguiseText out = t;
            for (Step s : level) {
                out = switch (s) {
                    case ORDER -> out.reordered(new SplittableRandom(order));
                    case BREAKS -> out.broken(new SplittableRandom(breaks), BREAK_ONE_IN);
                    case INDENT -> out.indented(new SplittableRandom(indent));
                };
            }
            return out;
        }
    }

    /** The first error of {@code code} at {@code want}'s line of {@code text}. */
    private static Optional<Diagnostic> errorAt(String text, ExpectedError want) {
        try {
            return Analysis.analyze(StrictReader.openLevel(), "disguise", text).diagnostics().stream()
                    .filter(Diagnostic::isError).filter(d -> d.code().equals(want.code()))
                    .filter(d -> d.location().line() == want.line()).findFirst();
        } catch (RuntimeException | StackOverflowError e) {
            return Optional.empty();
        }
    }

    /** The reference reads {@code text} without error and loads it. */
    private static boolean loads(String text) {
        try {
            Analysis a = Analysis.analyze(StrictReader.openLevel(), "twin", text);
            if (a.hasErrors() || a.program().isEmpty()) {
                return false;
            }
            Evaluator.load(a.program().get());
            return true;
        } catch (RuntimeException | StackOverflowError e) {
            return false;
        }
    }

    private static Optional<Program> partial(String text) {
        try {
            return StrictReader.openLevel().read("disguise", text).program();
        } catch (RuntimeException | StackOverflowError e) {
            return Optional.empty();
        }
    }

    private static Optional<Integer> lineOf(String text, String code) {
        try {
            return Analysis.analyze(StrictReader.openLevel(), "disguise", text).diagnostics().stream()
                    .filter(Diagnostic::isError).filter(d -> d.code().equals(code)).map(d -> d.location().line())
                    .findFirst();
        } catch (RuntimeException | StackOverflowError e) {
            return Optional.empty();
        }
    }

    private static List<String> declaredNames(Program p) {
        List<String> out = new ArrayList<>();
        for (FunctionBlock fb : p.functionBlocks()) {
            out.add(fb.name());
            for (Variable v : fb.variables()) {
                out.add(v.name());
            }
            fb.fuzzifications().forEach(f -> f.terms().stream().map(Term::name).forEach(out::add));
            fb.defuzzifications().forEach(d -> d.terms().stream().map(Term::name).forEach(out::add));
            fb.ruleBlocks().stream().map(RuleBlock::name).forEach(out::add);
        }
        return out;
    }

    /** A name no keyword can be: a letter, a digit, four letters or digits. */
    private static String freshName(SplittableRandom random) {
        StringBuilder b = new StringBuilder();
        b.append(LETTERS.charAt(random.nextInt(LETTERS.length()))).append((char) ('0' + random.nextInt(10)));
        for (int i = 0; i < 4; i++) {
            b.append(ALNUM.charAt(random.nextInt(ALNUM.length())));
        }
        return b.toString();
    }

    private static String noise(SplittableRandom random, int length) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < length; i++) {
            b.append(random.nextInt(6) == 0 ? ' ' : ALNUM.charAt(random.nextInt(ALNUM.length())));
        }
        return b.toString().strip();
    }

    /** Every word outside comments whose key is renamed gets its new name. */
    private static String rename(String text, Map<String, String> renames) {
        if (renames.isEmpty()) {
            return text;
        }
        Matcher m = COMMENT_OR_WORD.matcher(text);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String token = m.group();
            String replacement = token.startsWith("(*") ? token : renames.getOrDefault(Names.key(token), token);
            m.appendReplacement(out, Matcher.quoteReplacement(replacement));
        }
        m.appendTail(out);
        return out.toString();
    }

    /** Rule numbers outside comments mapped one to one onto {@code base}, {@code base + 1}, … in order of first use. */
    private static String renumberRules(String text, int base) {
        Map<String, Integer> numbers = new HashMap<>();
        Matcher m = COMMENT_OR_WORD.matcher(text);
        StringBuilder out = new StringBuilder();
        int last = 0;
        while (m.find()) {
            if (!m.group().startsWith("(*")) {
                continue;
            }
            out.append(renumberOutsideComments(text.substring(last, m.start()), base, numbers)).append(m.group());
            last = m.end();
        }
        out.append(renumberOutsideComments(text.substring(last), base, numbers));
        return out.toString();
    }

    private static String renumberOutsideComments(String part, int base, Map<String, Integer> numbers) {
        Matcher m = RULE_NUMBER.matcher(part);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String n = m.group(2).replaceFirst("^0+(?=.)", "");
            int mapped = numbers.computeIfAbsent(n, k -> base + numbers.size());
            m.appendReplacement(out, Matcher.quoteReplacement(m.group(1) + mapped + m.group(3)));
        }
        m.appendTail(out);
        return out.toString();
    }

    /** Every comment's text replaced by noise of as many lines. */
    private static String rewriteComments(String text, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Matcher m = COMMENT_OR_WORD.matcher(text);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String token = m.group();
            if (token.startsWith("(*") && token.endsWith("*)") && !token.substring(2, token.length() - 2).contains("(*")) {
                long breaks = token.chars().filter(ch -> ch == '\n').count();
                StringBuilder comment = new StringBuilder("(* ").append(noise(random, 4 + random.nextInt(16)));
                for (long i = 0; i < breaks; i++) {
                    comment.append('\n').append(noise(random, 3 + random.nextInt(10)));
                }
                token = comment.append(" *)").toString();
            }
            m.appendReplacement(out, Matcher.quoteReplacement(token));
        }
        m.appendTail(out);
        return out.toString();
    }

    private static Optional<Program> read(String text) {
        try {
            return Analysis.analyze(StrictReader.openLevel(), "disguise", text).program();
        } catch (RuntimeException | StackOverflowError e) {
            return Optional.empty();
        }
    }

    private static boolean stillRejected(String text, ExpectedError want) {
        try {
            Analysis a = Analysis.analyze(StrictReader.openLevel(), "disguise", text);
            return a.diagnostics().stream().filter(Diagnostic::isError)
                    .anyMatch(d -> d.code().equals(want.code()) && d.location().line() == want.line());
        } catch (RuntimeException | StackOverflowError e) {
            return false;
        }
    }

    /** The disguised text evaluates exactly as the corpus text on every vector of the case (exact path). */
    private static boolean sameMeaning(RunCase c, Program original, String text, Map<String, String> renames) {
        if (original == null) {
            return false;
        }
        Optional<Program> disguised = read(text);
        if (disguised.isEmpty()) {
            return false;
        }
        Disguise map = new Disguise(renames, Map.of(), text, 0, Optional.empty(), Optional.empty(), false,
                Optional.empty());
        try {
            String block = c.block().orElse(null);
            ExactInstance a = Evaluator.load(original).newExactInstance(block, NumberReading.DECIMAL);
            ExactInstance b = Evaluator.load(disguised.get()).newExactInstance(map.sent(block), NumberReading.DECIMAL);
            for (Vector v : c.vectors()) {
                for (Map.Entry<String, Double> in : v.in().entrySet()) {
                    a.set(in.getKey(), in.getValue());
                    b.set(map.sent(in.getKey()), in.getValue());
                }
                String refusedA = EvaluationException.refusalOf(a::evaluate);
                if (!java.util.Objects.equals(refusedA, EvaluationException.refusalOf(b::evaluate))) {
                    return false;
                }
                if (refusedA != null) {
                    continue;   // a step that must be refused, refused with the same code both ways
                }
                for (String out : v.out().keySet()) {
                    if (Double.compare(a.get(out), b.get(map.sent(out))) != 0) {
                        return false;
                    }
                }
            }
            return true;
        } catch (EvaluationException | RuntimeException e) {
            return false;
        }
    }
}
