package org.fclcert.report;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ReferenceTrace;
import org.fclcert.model.Feature;

/**
 * Groups the cases that did not pass by their cause, so that a report says "30 cases: rejected at load: 'RANGE' is
 * not supported at the Basic Level" instead of listing 30 rejections. The evidence is what the implementation said
 * and did:
 * <ul>
 * <li>a program it rejected, an evaluation it refused, a crash: grouped by its message, clustered by what is
 * particular to one case removed ({@link MessageCluster}: positions, numbers, the program's own names, the statement
 * it quotes, letter case), and shown verbatim as the first case of the group said it;</li>
 * <li>a wrong value: by the feature the failing step isolates ({@link Attribution}) and the kind of deviation (NaN,
 * small as from sampling, large);</li>
 * <li>an accepted invalid program, a timeout, a protocol fault: that outcome.</li>
 * </ul>
 * Only a rejection with no message at all gets fclcert's guess at the construct on the line it points at, marked as
 * a hint. Rules are documented in {@code docs/report-format.md}, "Causes".
 */
public final class Causes {
    /** A relative error up to this is "small": the size of the error of a sampled defuzzification. */
    static final double SMALL = 0.01;
    /** A rule degree up to this is "faint": fuzzylite's firing tolerance (its fuzzylite::macheps). */
    static final double FAINT = 1e-6;
    /** What a group shows of the message it quotes. */
    static final int SHOWN = 200;

    private static final Pattern HARNESS_PREFIX = Pattern.compile(
            "^rejected a program the standard accepts(?: at line (\\d+))?: ");
    private static final Pattern ANTLR_POSITION = Pattern.compile("\\bline (\\d+):\\d+ ");
    private static final Pattern WRONG_STEP = Pattern.compile("^step \\d+ of \\d+: ");

    private Causes() {}

    /**
     * One cause and the cases it explains; {@code kind} is the outcome it belongs to, {@code cause} what the
     * implementation said (verbatim, from the first case of the group) or, for wrong values, the isolated feature and
     * the kind of deviation; {@code example} the first case's message.
     */
    public record Cause(String kind, String cause, int count, List<String> cases, String example) {
        public Cause {
            cases = List.copyOf(cases);
        }

        /** {@code 30 cases: rejected at load: 'RANGE' is not supported at the Basic Level}. */
        public String sentence() {
            return count + (count == 1 ? " case: " : " cases: ") + kind + ": " + cause;
        }
    }

    /** How one case is filed: its outcome, the key that clusters it, and what its group shows. */
    record Label(String kind, String key, String shown) {
    }

    /** The causes of every failed or errored case (interpretation cases excluded), the largest group first. */
    public static List<Cause> of(List<CaseResult> cases) {
        Map<String, List<CaseResult>> groups = new LinkedHashMap<>();
        Map<String, Label> labels = new LinkedHashMap<>();
        for (CaseResult c : cases) {
            if (c.interpretation() || (c.status() != CaseStatus.FAILED && c.status() != CaseStatus.ERRORED)) {
                continue;
            }
            Label label = label(c);
            String key = label.kind() + "\u0000" + label.key();
            groups.computeIfAbsent(key, k -> new ArrayList<>()).add(c);
            labels.putIfAbsent(key, label);
        }
        List<Cause> out = new ArrayList<>();
        groups.forEach((key, members) -> out.add(new Cause(labels.get(key).kind(), labels.get(key).shown(),
                members.size(), members.stream().map(CaseResult::id).toList(), String.valueOf(members.get(0).message()))));
        out.sort(Comparator.comparingInt(Cause::count).reversed().thenComparing(Cause::kind).thenComparing(Cause::cause));
        return out;
    }

    /** The cause of a positive case's rejection at load (what it said); empty when the case was not rejected at load. */
    public static Optional<String> rejectionCause(CaseResult c) {
        if (c.status() != CaseStatus.FAILED || c.message() == null || !HARNESS_PREFIX.matcher(c.message()).find()) {
            return Optional.empty();
        }
        return Optional.of(label(c).shown());
    }

    /** {kind, what the group shows} of one case. */
    static String[] classify(CaseResult c) {
        Label label = label(c);
        return new String[] {label.kind(), label.shown()};
    }

    static Label label(CaseResult c) {
        String message = c.message() == null ? "" : c.message();
        String program = CaseFacts.program(c);
        if (c.status() == CaseStatus.ERRORED) {
            if (message.contains("the implementation timed out")) {
                return fixed("errored", "timed out");
            }
            if (message.contains("the implementation broke the protocol")) {
                return fixed("errored", "broke the protocol");
            }
            if (message.contains("the implementation was given up")) {
                return fixed("errored", "given up (restart budget exhausted)");
            }
            String crash = crash(message);
            return new Label("errored", MessageCluster.key(crash, program), crash);
        }
        Matcher rejected = HARNESS_PREFIX.matcher(message);
        if (rejected.find()) {
            String said = message.substring(rejected.end()).strip();
            if (said.isEmpty()) {
                // the implementation said nothing: fclcert's guess at the construct, marked as one
                String statement = lineOf(rejected.group(1), said).text(program);
                String hint = hint(statement).map(h -> "no message; hint: the line it points at has " + h)
                        .orElse("no message");
                return fixed("rejected at load", hint);
            }
            return said(said, program, "rejected at load");
        }
        if (message.startsWith("accepted a program the standard rejects")) {
            return fixed("accepted an invalid program", "no error reported where the standard requires one");
        }
        String step = WRONG_STEP.matcher(message).replaceFirst("");
        if (step.startsWith("the implementation reported an evaluation error")
                || step.startsWith("the implementation refused")) {
            String said = step.replaceFirst("^[^:]*: ", "").replaceFirst("^the IUT reported an error on '\\w+': ", "");
            return said(said.split("[\\t\\n]", 2)[0], program, "refused to evaluate");
        }
        Optional<String> deviation = deviation(c);
        if (deviation.isPresent()) {
            return fixed("wrong value", feature(c) + ": " + deviation.get());
        }
        return said(message, program, "failed");
    }

    private static Label fixed(String kind, String cause) {
        return new Label(kind, cause, cause);
    }

    /** What the implementation said: clustered by {@link MessageCluster}, shown as this case has it. */
    private static Label said(String said, String program, String kind) {
        String shown = said.length() <= SHOWN ? said : said.substring(0, SHOWN) + "…";
        return new Label(kind, MessageCluster.key(said, program), shown);
    }

    /** The program line a rejection points at, from the harness's "at line N" or ANTLR's "line N:C". */
    private record OptionalLine(int number) {
        String text(String program) {
            if (number < 1 || program == null) {
                return "";
            }
            String[] lines = program.split("\\R", -1);
            return number <= lines.length ? lines[number - 1].strip() : "";
        }
    }

    private static OptionalLine lineOf(String harnessLine, String said) {
        if (harnessLine != null) {
            return new OptionalLine(Integer.parseInt(harnessLine));
        }
        Matcher m = ANTLR_POSITION.matcher(said);
        return new OptionalLine(m.find() ? Integer.parseInt(m.group(1)) : 0);
    }

    private record Rule(Pattern pattern, Function<Matcher, String> cause) {
    }

    private static Rule statement(String regex, Function<Matcher, String> cause) {
        return new Rule(Pattern.compile(regex, Pattern.CASE_INSENSITIVE), cause);
    }

    /** Constructs a statement may have that some implementations do not read, first match wins. */
    private static final List<Rule> RULES = List.of(
            statement("^RANGE\\s*\\(", m -> "`RANGE (a .. b)`"),
            statement("^\\w+\\s*,", m -> "several variables in one declaration"),
            statement("^\\w+\\s*:\\s*\\w+\\s*:=", m -> "a declared initial value"),
            statement("^\\w+\\s*:\\s*\\w+\\s+\\w+\\s*:", m -> "several statements on one line"),
            statement("^\\w+\\s*:\\s*(?!REAL\\b)[A-Z]+\\s*$", m -> "a data type other than REAL"),
            statement("\\bTHEN\\b.*,", m -> "several subconclusions separated by commas"),
            statement("^VAR\\s*$", m -> "`VAR` (local variables)"),
            statement("\\bMoM\\b", m -> "`MoM` (mean of maximum)"),
            // last: a comment on the line is the construct only when nothing else on it is
            statement("\\(\\*", m -> "a `(* *)` comment"));

    /** fclcert's guess at the construct of a statement an implementation rejected without a word, if it has one. */
    static Optional<String> hint(String statement) {
        String code = statement.replaceAll("\\(\\*.*?(\\*\\)|$)", " ").strip();
        for (Rule rule : RULES) {
            boolean comment = rule.pattern().pattern().equals("\\(\\*");
            Matcher m = rule.pattern().matcher(comment ? statement : code);
            if (m.find()) {
                return Optional.of(rule.cause().apply(m));
            }
        }
        return Optional.empty();
    }

    /** The message without what is particular to one case: positions, quoted statements, numbers. */
    static String normalise(String message) {
        String s = message.strip();
        s = s.replaceAll("\\bline \\d+:\\d+ ", "");
        s = s.replaceAll("\\s+(?:in|from) line\\b.*$", "");
        s = s.replaceAll("\\s*\\(at [^)]*\\)", "");
        s = s.replaceAll("(?<![\\w.])\\d+(?:\\.\\d+)?(?:[eE][-+]?\\d+)?(?![\\w.])", "N");
        return s.length() <= 160 ? s : s.substring(0, 160) + "…";
    }

    /** An internal failure: the exception's class and where in the library, without the case's details. */
    static String crash(String message) {
        Matcher exception = Pattern.compile("([a-z][\\w]*\\.)+([A-Z]\\w*(?:Exception|Error))").matcher(message);
        String where = "";
        Matcher at = Pattern.compile("\\(at ([^)]*)\\)").matcher(message);
        if (at.find()) {
            where = " in " + at.group(1);
        }
        if (exception.find()) {
            return "crashed: " + exception.group(2) + where;
        }
        return "crashed: " + normalise(message.replaceFirst("^[^:]*: ", ""));
    }

    /**
     * The feature a wrong value is filed under: the one row its failing step isolates ({@link Attribution}); among
     * several, the case's own (its id without the number: B-COGS-001 tests B-COGS), else the first.
     */
    static String feature(CaseResult c) {
        List<String> rows = Attribution.rows(c);
        String own = c.id().replaceFirst("-\\d+$", "").toUpperCase(Locale.ROOT);
        String id = rows.size() == 1 ? rows.get(0) : rows.contains(own) ? own : !rows.isEmpty() ? rows.get(0)
                : Feature.byId(own).isPresent() || c.tests().isEmpty() ? own : c.tests().get(0).toUpperCase(Locale.ROOT);
        return Feature.byId(id).map(x -> x.id() + " (" + x.description() + ")").orElse(id);
    }

    /** NaN, a small (relative error ≤ 1 %) or a large deviation, on the first wrong output of the case. */
    static Optional<String> deviation(CaseResult c) {
        if (!(CaseFacts.expected(c) instanceof Map<?, ?> expected) || !(CaseFacts.actual(c) instanceof Map<?, ?> actual)) {
            return Optional.empty();
        }
        double worst = 0;
        boolean nan = false;
        for (Map.Entry<?, ?> e : expected.entrySet()) {
            Object got = actual.get(e.getKey());
            if (!(e.getValue() instanceof Number want) || !(got instanceof Number have)) {
                continue;
            }
            double w = want.doubleValue();
            double h = have.doubleValue();
            if (Double.isNaN(h) && !Double.isNaN(w)) {
                nan = true;
            } else if (Double.isFinite(w) && Double.isFinite(h)) {
                worst = Math.max(worst, Math.abs(h - w) / Math.max(Math.abs(w), 1));
            }
        }
        if (nan) {
            return Optional.of("NaN where a value is expected");
        }
        if (worst == 0) {
            return Optional.empty();
        }
        if (worst <= SMALL) {
            Optional<ReferenceTrace.RuleDegree> faint = faintRule(c);
            if (faint.isPresent()) {
                return Optional.of("small deviation where a rule fired at a degree of at most 1e-6 (as from a"
                        + " library that does not fire a rule below a tolerance, as fuzzylite's 1e-6)");
            }
        }
        return Optional.of(worst <= SMALL ? "small deviation (relative error at most 1 %, as from sampling)"
                : "wrong value");
    }

    /**
     * A rule the reference fired at the failing step with a degree above 0 but at most {@link #FAINT}: a library
     * that treats such degrees as 0 (fuzzylite and jfuzzylite compare with 1e-6) gives another value there.
     */
    static Optional<ReferenceTrace.RuleDegree> faintRule(CaseResult c) {
        ReferenceTrace t = c.evidence().reference();
        return t == null ? Optional.empty()
                : t.rules().stream().filter(r -> r.degree() > 0 && r.degree() <= FAINT).findFirst();
    }
}
