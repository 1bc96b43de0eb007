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
import org.fclcert.model.Feature;

/**
 * Groups the cases that did not pass by their cause, so that a report says "47 cases: one statement per line"
 * instead of listing 47 rejections. A cause is derived, in this order, from what the implementation said and
 * did: for a program it rejected, its message and the program line the message points at (matched against a
 * short list of known reasons, else the message with its case-specific parts removed); for a wrong value, the
 * case's feature and the kind of deviation (NaN, small as from sampling, large); for an accepted invalid
 * program, an evaluation error, a crash or a timeout, that outcome and its normalised message. Rules are
 * documented in {@code docs/report-format.md}, "Causes".
 */
public final class Causes {
    /** A relative error up to this is "small": the size of the error of a sampled defuzzification. */
    static final double SMALL = 0.01;

    private static final Pattern HARNESS_PREFIX = Pattern.compile(
            "^rejected a program the standard accepts(?: at line (\\d+))?: ");
    private static final Pattern ANTLR_POSITION = Pattern.compile("\\bline (\\d+):\\d+ ");
    private static final Pattern QUOTED = Pattern.compile("\\bin line: (.*)$");
    private static final Pattern WRONG_STEP = Pattern.compile("^step \\d+ of \\d+: ");

    private Causes() {}

    /** One cause and the cases it explains; {@code kind} is the outcome it belongs to. */
    public record Cause(String kind, String cause, int count, List<String> cases, String example) {
        public Cause {
            cases = List.copyOf(cases);
        }

        /** {@code 47 cases: rejected at load: one statement per line}. */
        public String sentence() {
            return count + (count == 1 ? " case: " : " cases: ") + kind + ": " + cause;
        }
    }

    /** The causes of every failed or errored case (interpretation cases excluded), the largest group first. */
    public static List<Cause> of(List<CaseResult> cases) {
        Map<String, List<CaseResult>> groups = new LinkedHashMap<>();
        Map<String, String[]> labels = new LinkedHashMap<>();
        for (CaseResult c : cases) {
            if (c.interpretation() || (c.status() != CaseStatus.FAILED && c.status() != CaseStatus.ERRORED)) {
                continue;
            }
            String[] label = classify(c);
            String key = label[0] + "\u0000" + label[1];
            groups.computeIfAbsent(key, k -> new ArrayList<>()).add(c);
            labels.putIfAbsent(key, label);
        }
        List<Cause> out = new ArrayList<>();
        groups.forEach((key, members) -> out.add(new Cause(labels.get(key)[0], labels.get(key)[1], members.size(),
                members.stream().map(CaseResult::id).toList(), String.valueOf(members.get(0).message()))));
        out.sort(Comparator.comparingInt(Cause::count).reversed().thenComparing(Cause::kind).thenComparing(Cause::cause));
        return out;
    }

    /** The cause of a positive case's rejection at load; empty when the case was not rejected at load. */
    public static Optional<String> rejectionCause(CaseResult c) {
        if (c.status() != CaseStatus.FAILED || c.message() == null || !HARNESS_PREFIX.matcher(c.message()).find()) {
            return Optional.empty();
        }
        return Optional.of(classify(c)[1]);
    }

    /** {kind, cause} of one case. */
    static String[] classify(CaseResult c) {
        String message = c.message() == null ? "" : c.message();
        if (c.status() == CaseStatus.ERRORED) {
            if (message.contains("the implementation timed out")) {
                return new String[] {"errored", "timed out"};
            }
            if (message.contains("the implementation broke the protocol")) {
                return new String[] {"errored", "broke the protocol"};
            }
            if (message.contains("the implementation was given up")) {
                return new String[] {"errored", "given up (restart budget exhausted)"};
            }
            return new String[] {"errored", crash(message)};
        }
        Matcher rejected = HARNESS_PREFIX.matcher(message);
        if (rejected.find()) {
            String said = message.substring(rejected.end());
            // the statement as the library quotes it (fuzzylite: "in line: x : REAL := 1.0"), else the program line
            Matcher quoted = QUOTED.matcher(said);
            String statement = quoted.find() ? quoted.group(1) : lineOf(rejected.group(1), said).text(CaseFacts.program(c));
            return new String[] {"rejected at load", rejection(said, statement)};
        }
        if (message.startsWith("accepted a program the standard rejects")) {
            return new String[] {"accepted an invalid program", "no error reported where the standard requires one"};
        }
        String step = WRONG_STEP.matcher(message).replaceFirst("");
        if (step.startsWith("the implementation reported an evaluation error")
                || step.startsWith("the implementation refused")) {
            String said = step.replaceFirst("^[^:]*: ", "").replaceFirst("^the IUT reported an error on '\\w+': ", "");
            return new String[] {"refused to evaluate", normalise(said.split("[\\t\\n]", 2)[0])};
        }
        Optional<String> deviation = deviation(c);
        if (deviation.isPresent()) {
            return new String[] {"wrong value", feature(c) + ": " + deviation.get()};
        }
        return new String[] {"failed", normalise(message)};
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

    private record Rule(Pattern pattern, boolean onStatement, Function<Matcher, String> cause) {
    }

    private static Rule message(String regex, Function<Matcher, String> cause) {
        return new Rule(Pattern.compile(regex), false, cause);
    }

    private static Rule statement(String regex, Function<Matcher, String> cause) {
        return new Rule(Pattern.compile(regex, Pattern.CASE_INSENSITIVE), true, cause);
    }

    /** Known reasons, first match wins: what the message says, or what the statement it points at is. */
    private static final List<Rule> RULES = List.of(
            message("<\\(\\*>|unknown block definition <\\(\\*", m -> "`(* *)` comments"),
            message("(?:Defuzzifier|constructor) <(\\w+)> not registered", m -> "`" + m.group(1) + "` spelling of METHOD"),
            message("unexpected token <METHOD:>", m -> "`METHOD:` without a blank before the colon"),
            message("expected <END_\\w+> before <", m -> "one statement per line"),
            message("in line: \\w+\\s*:\\s*\\w+\\s+\\w+\\s*:", m -> "one statement per line"),
            message("'MoM'", m -> "`MoM` (mean of maximum)"),
            message("no viable alternative at character '_'", m -> "a name or number with `_`"),
            message("expecting TYPE_REAL|mismatched input '(\\w*INT|LREAL)'", m -> "data types other than REAL"),
            message("unknown block definition <VAR>|mismatched input 'VAR'", m -> "`VAR` (local variables)"),
            message("unknown block definition <(\\w*[a-z]\\w*)>", m -> "keyword in lower or mixed case (`" + m.group(1) + "`)"),
            message("1_000", m -> "digit separators (`1_000`)"),
            statement("^RANGE\\s*\\(", m -> "`RANGE (a .. b)` without `:=`"),
            statement("^\\w+\\s*,", m -> "several variables in one declaration"),
            statement("^\\w+\\s*:\\s*\\w+\\s*:=", m -> "declared initial value"),
            statement("^\\w+\\s*:\\s*\\w+\\s+\\w+\\s*:", m -> "one statement per line"),
            statement("^\\w+\\s*:\\s*(?!REAL\\b)[A-Z]+\\s*$", m -> "data types other than REAL"),
            statement("\\bTHEN\\b.*,", m -> "several subconclusions separated by commas"),
            message("from <([A-Za-z_]\\w*)> to scalar|For input string: \"([A-Za-z_]\\w*)\"|Cannot find variable: '(\\w+)'",
                    m -> "a variable where a number is expected (term points, degrees)"),
            message("Variable (\\w+) does not exist|does not contain (?:input|output) variable <(\\w+)>",
                    m -> "a variable it does not know (names are case-sensitive to it)"),
            // last: a comment on the line is the cause only when nothing else on it is
            new Rule(Pattern.compile("\\(\\*"), true, m -> "`(* *)` comments"));

    static String rejection(String said, String statement) {
        String code = statement.replaceAll("\\(\\*.*?(\\*\\)|$)", " ").strip();
        for (Rule rule : RULES) {
            boolean comment = rule.onStatement() && rule.pattern().pattern().equals("\\(\\*");
            Matcher m = rule.pattern().matcher(!rule.onStatement() ? said : comment ? statement : code);
            if (m.find()) {
                return rule.cause().apply(m);
            }
        }
        return normalise(said);
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

    /** The case's own feature: its id without the number (B-COGS-001 tests B-COGS), else its first tested feature. */
    static String feature(CaseResult c) {
        String id = c.id().replaceFirst("-\\d+$", "");
        Optional<Feature> f = Feature.byId(id.toUpperCase(Locale.ROOT));
        if (f.isEmpty() && !c.tests().isEmpty()) {
            f = Feature.byId(c.tests().get(0).toUpperCase(Locale.ROOT));
        }
        return f.map(x -> x.id() + " (" + x.description() + ")").orElse(id);
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
        return Optional.of(worst <= SMALL ? "small deviation (relative error at most 1 %, as from sampling)"
                : "wrong value");
    }
}
