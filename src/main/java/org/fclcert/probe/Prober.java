package org.fclcert.probe;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.IntFunction;
import java.util.function.LongSupplier;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.iut.StopSignal;

/**
 * Measures the Table 11 data check list (clause 6.2) on an implementation under test by probing it with
 * generated programs ({@link Families}) whose right outputs the reference evaluator computes. A size
 * counts only when the program loads and every evaluation agrees with the reference. Limits are found
 * by growing the size 1, 2, 4, … up to the cap and bisecting between the last size that worked and the
 * first that did not; what happened at the first failing size is kept in the note.
 *
 * <p>A process implementation that crashes is restarted by its adapter; when its restart budget is used
 * up the prober closes it and opens a fresh one from the {@link IutSource}. The whole probe stays
 * within the time budget: each row gets an even share of what is left, and a row that runs out says so; at the
 * budget itself the probe is stopped ({@link StopSignal}), as when the caller stops it (Ctrl-C): the row under
 * way keeps what it had established ("at least" the last size that worked) or is not measured, every later row
 * is not measured, each with the reason, and the implementation is closed.
 * Library code: nothing is printed.
 */
public final class Prober {
    public static final long DEFAULT_CAP = 100_000;
    public static final int DEFAULT_BUDGET_MINUTES = 3;
    public static final Duration DEFAULT_BUDGET = Duration.ofMinutes(DEFAULT_BUDGET_MINUTES);
    static final List<String> DATA_TYPES =
            List.of("REAL", "LREAL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT");
    static final int WARMUP_EVALS = 500;
    static final int TIMED_EVALS = 2_000;
    static final int SWEEP_STEPS = 2_000;

    /**
     * How far to probe.
     *
     * @param cap    largest size tried for a "maximum number of" row (and identifier length)
     * @param budget wall-clock time for the whole probe of one implementation
     * @param rows   the rows to measure (empty: all); the others are reported as not measured
     */
    public record Options(long cap, Duration budget, Set<Table11> rows) {
        public Options {
            if (cap < 1) {
                throw new IllegalArgumentException("the probe cap must be at least 1, not " + cap);
            }
            if (budget.isNegative() || budget.isZero()) {
                throw new IllegalArgumentException("the probe budget must be positive: " + budget);
            }
            rows = rows.isEmpty() ? EnumSet.allOf(Table11.class) : EnumSet.copyOf(rows);
        }

        public static Options defaults() {
            return new Options(DEFAULT_CAP, DEFAULT_BUDGET, Set.of());
        }

        public Options withCap(long newCap) {
            return new Options(newCap, budget, rows);
        }

        public Options withBudget(Duration newBudget) {
            return new Options(cap, newBudget, rows);
        }
    }

    /** Opens a fresh session with the implementation (the first one, and again after it gave up). */
    @FunctionalInterface
    public interface IutSource {
        ImplementationUnderTest open() throws IutException;
    }

    /** Told when a row starts, for progress display, and when it is measured. */
    public interface Listener {
        void row(Table11 row, int index, int total);

        /** The row's entry, as it will be returned (an interrupted probe can still show the rows done). */
        default void measured(DataCheckEntry entry) {
        }

        Listener NONE = (row, index, total) -> { };
    }

    private final IutSource source;
    private final Options options;
    /** The budget's clock: System.nanoTime, or a test's simulated one (execution times use the real clock). */
    private final LongSupplier clock;
    private final long deadline;
    private ImplementationUnderTest iut;
    private IutInfo info;
    private final List<DataCheckEntry> done = new ArrayList<>();
    private final StopSignal stop;

    private Prober(IutSource source, Options options, LongSupplier clock, StopSignal stop) {
        this.source = source;
        this.options = options;
        this.clock = clock;
        this.deadline = clock.getAsLong() + options.budget().toNanos();
        this.stop = stop;
    }

    /**
     * Probes every row in the order of Table 11.
     *
     * @throws IutException when the implementation cannot be opened or does not answer {@code hello}
     */
    public static List<DataCheckEntry> probe(IutSource source, Options options, Listener listener)
            throws IutException {
        return probe(source, options, listener, (StopSignal) null);
    }

    /**
     * As {@link #probe(IutSource, Options, Listener)}, ending early when {@code stop} (null: never) stops; the
     * probe's budget stops it too (a {@link StopSignal#child} of {@code stop}, so that the caller's run goes on).
     */
    public static List<DataCheckEntry> probe(IutSource source, Options options, Listener listener, StopSignal stop)
            throws IutException {
        StopSignal own = stop == null ? new StopSignal() : stop.child();
        try (StopSignal.Timing budget = own.stopAfter(options.budget(),
                StopSignal.budgetRanOut("probe", options.budget()))) {
            return probe(source, options, listener, System::nanoTime, own);
        }
    }

    /** As {@link #probe(IutSource, Options, Listener)}, with the budget kept on {@code clock} (nanoseconds). */
    static List<DataCheckEntry> probe(IutSource source, Options options, Listener listener, LongSupplier clock)
            throws IutException {
        return probe(source, options, listener, clock, new StopSignal());
    }

    private static List<DataCheckEntry> probe(IutSource source, Options options, Listener listener, LongSupplier clock,
            StopSignal stop) throws IutException {
        Prober p = new Prober(source, options, clock, stop);
        try {
            try {
                p.iut = stop.guard(source.open());
                p.info = p.iut.hello();
            } catch (IutException e) {
                if (e.kind() != IutException.Kind.STOPPED) {
                    throw e;
                }
                return notMeasured(stopped(stop));
            }
            Table11[] rows = Table11.values();
            for (int i = 0; i < rows.length; i++) {
                Table11 row = rows[i];
                DataCheckEntry entry;
                if (!options.rows().contains(row)) {
                    entry = p.entry(row, "", DataCheckEntry.NOT_MEASURED, "", "not selected for this run");
                } else if (stop.stopped()) {
                    entry = p.entry(row, "", DataCheckEntry.NOT_MEASURED, "", stopped(stop));
                } else {
                    listener.row(row, i + 1, rows.length);
                    long now = clock.getAsLong();
                    long rowsLeft = Arrays.stream(rows, i, rows.length).filter(options.rows()::contains).count();
                    long rowDeadline = now + Math.max(0, (p.deadline - now) / rowsLeft);
                    int cuts = stop.cuts();
                    p.limitStopped = null;
                    entry = p.measure(row, rowDeadline);
                    boolean cut = stop.cuts() != cuts || p.limitStopped != null;
                    if (cut && !(LIMIT_ROWS.contains(row) && Boolean.TRUE.equals(p.limitStopped))) {
                        // a stop cut this row short: what it recorded since is fclcert's doing, not the IUT's
                        entry = p.entry(row, "", DataCheckEntry.NOT_MEASURED, entry.method(), stopped(stop)
                                + " during this row");
                    }
                }
                p.done.add(entry);
                listener.measured(entry);
            }
            return List.copyOf(p.done);
        } finally {
            if (p.iut != null) {
                p.iut.close();
            }
        }
    }

    private static String stopped(StopSignal stop) {
        return "not measured: the probe was stopped: " + stop.reason();
    }

    /**
     * The rows measured by growing a size ({@link #limit}), whose entry stays "at least" the last size that worked
     * when a stop cuts them short.
     */
    private static final Set<Table11> LIMIT_ROWS = EnumSet.complementOf(EnumSet.of(Table11.DATA_TYPES,
            Table11.LINE_COMMENTS, Table11.EXECUTION_TIME, Table11.MEMORY, Table11.DEGREE_RESOLUTION,
            Table11.IDENTIFIER_LENGTH));
    /**
     * Set by {@link #limit} when a stop ended it: true when a size had worked (its entry then says "at least" that
     * size, and why it stopped), false when none had; null when no stop ended it.
     */
    private Boolean limitStopped;

    /** Every row "not measured", with the reason (the implementation could not be probed at all). */
    public static List<DataCheckEntry> notMeasured(String why) {
        return Arrays.stream(Table11.values()).map(r -> new DataCheckEntry(r.id(), r.item(), "",
                DataCheckEntry.NOT_MEASURED, r.unit(), "", why)).toList();
    }

    // ---------------------------------------------------------------- one attempt

    private enum Result { OK, REJECTED, WRONG, FAULT, UNJUDGED, UNREACHABLE }

    private record Attempt(Result result, String detail) {
        boolean ok() {
            return result == Result.OK;
        }
    }

    /** Loads the program and runs its vectors, comparing each output with the reference. */
    private Attempt attempt(ProbeProgram p) {
        ReferenceJudge.Expected expected = ReferenceJudge.expected(p);
        try {
            return attemptOnce(p, expected);
        } catch (IutException e) {
            if (e.kind() != IutException.Kind.GAVE_UP) {
                return fault(e);
            }
            try {
                reopen();
                return attemptOnce(p, expected);
            } catch (IutException again) {
                return fault(again);
            }
        }
    }

    private Attempt attemptOnce(ProbeProgram p, ReferenceJudge.Expected expected) throws IutException {
        LoadOutcome outcome = iut.load(p.fcl());
        if (outcome instanceof LoadOutcome.Rejected r) {
            return new Attempt(Result.REJECTED, "rejected cleanly ('" + shorten(r.message()) + "')");
        }
        if (expected.outputs().isEmpty()) {
            return new Attempt(Result.UNJUDGED, expected.whyNot());
        }
        List<Map<String, Double>> want = expected.outputs().get();
        for (int i = 0; i < p.vectors().size(); i++) {
            Map<String, Double> got = iut.eval(null, p.vectors().get(i));
            Optional<String> diff = ReferenceJudge.compare(want.get(i), got);
            if (diff.isPresent()) {
                return new Attempt(Result.WRONG, "SILENTLY WRONG RESULT: loaded, but after evaluation " + (i + 1)
                        + " " + diff.get());
            }
        }
        return new Attempt(Result.OK, "");
    }

    private static Attempt fault(IutException e) {
        String message = e.getMessage() == null ? "" : e.getMessage();
        if (e.kind() == IutException.Kind.EVAL_ERROR && message.startsWith(WORKLOAD_REJECTED)) {
            // the workload never loaded: saying "loaded, then refused to evaluate" would contradict the reason
            return new Attempt(Result.FAULT, "rejected at load (" + shorten(message.substring(WORKLOAD_REJECTED.length())) + ")");
        }
        String what = switch (e.kind()) {
            case EVAL_ERROR -> "loaded, then refused to evaluate";
            case CRASH -> "crashed";
            case TIMEOUT -> "timed out";
            case PROTOCOL -> "broke the protocol";
            case GAVE_UP -> "gave up (restart budget used up)";
            case INFRA -> "could not be reached";
            case STOPPED -> "was stopped by fclcert";
        };
        return new Attempt(Result.FAULT, what + " (" + shorten(e.getMessage()) + ")");
    }

    private void reopen() throws IutException {
        iut.close();
        iut = stop.guard(source.open());
        iut.hello();
    }

    private static String shorten(String s) {
        String one = s == null ? "" : s.replaceAll("\\s+", " ").strip();
        return one.length() <= 160 ? one : one.substring(0, 160) + "…";
    }

    // ---------------------------------------------------------------- rows

    private DataCheckEntry measure(Table11 row, long rowDeadline) {
        return switch (row) {
            case DATA_TYPES -> dataTypes();
            case LINE_COMMENTS -> comments();
            case EXECUTION_TIME -> executionTime(rowDeadline);
            case MEMORY -> memory();
            case DEGREE_RESOLUTION -> resolution(rowDeadline);
            case IDENTIFIER_LENGTH -> identifiers(rowDeadline);
            case INPUTS -> limit(row, 1, n -> Optional.of(Families.inputs(n)), rowDeadline,
                    "inputs x1…xn with one ramp term each; rules switch y to a value of their own for the first, two"
                            + " middle and the last input");
            case TERMS_PER_INPUT -> limit(row, 1, n -> Optional.of(Families.termsPerInput(n)), rowDeadline,
                    "one input with n triangle terms peaking at 1…n; rules on the first, two middle and the last term"
                            + " select distinct output values at x = the term's peak");
            case TERMS_ALL_INPUTS -> limit(row, 1, n -> {
                long per = measured(Table11.TERMS_PER_INPUT);
                return (n + per - 1) / per > measured(Table11.INPUTS) ? Optional.empty()
                        : Optional.of(Families.termsAllInputs(n, per));
            }, rowDeadline, "n triangle terms over inputs holding as many terms as max-terms-per-input found; sampled"
                    + " terms select distinct output values");
            case POINTS_PER_INPUT_TERM -> limit(row, 2, n -> Optional.of(Families.pointsPerInputTerm(n)), rowDeadline,
                    "one input term of n points, degrees 0 and 1 alternating at x = 0, 1, 2, …; its degree is read"
                            + " through a second rule (y = d / (d + 0.5)) at sampled points and a quarter past them");
            case POINTS_ALL_INPUT_TERMS -> limit(row, 2, n -> Families.pointsAllInputTerms(n,
                    measured(Table11.POINTS_PER_INPUT_TERM), measured(Table11.TERMS_PER_INPUT),
                    measured(Table11.INPUTS)), rowDeadline, "n points over zig-zag input terms as large as"
                    + " max-points-per-input-term found, on as few inputs as the measured limits allow; sampled terms"
                    + " read through the degree meter");
            case OUTPUTS -> limit(row, 1, n -> Optional.of(Families.outputs(n)), rowDeadline,
                    "outputs y1…yn with one singleton each (value i); rules conclude the first, two middle and the last"
                            + " output, every output is compared (the others must give DEFAULT 0)");
            case TERMS_PER_OUTPUT -> limit(row, 1, n -> Optional.of(Families.termsPerOutput(n)), rowDeadline,
                    "one output with n singletons (value = its number); sampled terms are selected one at a time");
            case TERMS_ALL_OUTPUTS -> limit(row, 1, n -> Families.termsAllOutputs(n,
                    measured(Table11.TERMS_PER_OUTPUT), measured(Table11.OUTPUTS)), rowDeadline,
                    "n singletons over outputs holding as many terms as max-terms-per-output found");
            case POINTS_PER_OUTPUT_TERM -> limit(row, 1, n -> Optional.of(Families.pointsPerOutputTerm(n)),
                    rowDeadline, "1: a singleton (CoGS); n ≥ 2: one output term of n points with uneven peaks, CoG"
                            + " over RANGE (0 .. n-1), evaluated fully fired and clipped at 0.5");
            case POINTS_ALL_OUTPUT_TERMS -> limit(row, 1, n -> Families.pointsAllOutputTerms(n,
                    measured(Table11.POINTS_PER_OUTPUT_TERM), measured(Table11.TERMS_PER_OUTPUT),
                    measured(Table11.OUTPUTS)), rowDeadline, "n points over output terms as large as"
                    + " max-points-per-output-term found (singletons when that is 1), on as few outputs as allowed");
            case RULE_BLOCKS -> limit(row, 1, Families::ruleBlocks, rowDeadline,
                    "n rule blocks of one rule each; the first, two middle and the last block read an input of their"
                            + " own and conclude a value of their own, the others IF x IS hi THEN y IS base");
            case RULES_PER_BLOCK -> limit(row, 1, n -> Families.rules(n, n, 1), rowDeadline,
                    "one rule block of n rules; the first, two middle and the last rule read an input of their own and"
                            + " conclude a value of their own, the others IF x IS hi THEN y IS base");
            case SUBCONDITIONS -> limit(row, 1, n -> Optional.of(Families.subconditions(n,
                    measured(Table11.INPUTS))), rowDeadline, "one rule x1 IS hi AND … AND xn IS hi (over at most"
                    + " max-input-variables inputs, wrapping around); sampled inputs lowered one at a time, the rule's"
                    + " degree read through the degree meter");
            case RULES_TOTAL -> limit(row, 1, n -> Families.rules(n, measured(Table11.RULES_PER_BLOCK),
                    measured(Table11.RULE_BLOCKS)), rowDeadline, "n rules in blocks as large as max-rules-per-block"
                    + " found; sampled rules conclude values of their own");
            case SUBCONCLUSIONS -> limit(row, 1, n -> Optional.of(Families.subconclusions(n,
                    measured(Table11.OUTPUTS))), rowDeadline, "one rule THEN y1 IS on, …, yn IS on (over at most"
                    + " max-output-variables outputs, wrapping around), each output a value of its own");
            case NESTING -> limit(row, 1, n -> Optional.of(Families.nesting(n)), rowDeadline,
                    "IF (((x IS hi))) with n pairs of parentheses, the degree read through the degree meter");
        };
    }

    /** The largest size that worked for an earlier row (its value), or the cap when it was not measured. */
    private long measured(Table11 row) {
        for (DataCheckEntry e : done) {
            if (e.id().equals(row.id()) && !e.bound().equals(DataCheckEntry.NOT_MEASURED)) {
                try {
                    return Math.max(1, Long.parseLong(e.value()));
                } catch (NumberFormatException notANumber) {
                    return 1;
                }
            }
        }
        return options.cap();
    }

    private DataCheckEntry entry(Table11 row, String value, String bound, String method, String note) {
        Long declared = info == null ? null : declaredLimit(row);
        return new DataCheckEntry(row.id(), row.item(), value, bound, row.unit(), method, note,
                declared == null ? "" : String.valueOf(declared));
    }

    private Long declaredLimit(Table11 row) {
        for (Map.Entry<String, Long> e : info.declaredLimits().entrySet()) {
            if (e.getKey().equalsIgnoreCase(row.id())) {
                return e.getValue();
            }
        }
        return null;
    }

    private boolean outOfTime(long rowDeadline) {
        return clock.getAsLong() > rowDeadline;
    }

    /** Grows the size 1, 2, 4, … (from {@code min}) to the cap, then bisects to the boundary. */
    private DataCheckEntry limit(Table11 row, int min, IntFunction<Optional<ProbeProgram>> family, long rowDeadline,
            String method) {
        long cap = Math.min(options.cap(), Integer.MAX_VALUE);
        String fullMethod = method + "; sizes " + min + ", " + (2L * min) + ", " + (4L * min) + ", … up to the cap ("
                + cap + "), then bisection; a size counts only if it loads and evaluates like the reference";
        int lastOk = 0;
        int firstFail = -1;
        Attempt failure = null;
        boolean budgetHit = false;
        boolean stopped = false;
        long n = min;
        long lastNanos = 0;   // how long the last attempt took; the first attempt of a row always runs
        while (true) {
            // a size twice the last one takes at least twice as long: do not start what cannot end in time
            if (lastNanos > 0 && clock.getAsLong() + 2 * lastNanos > rowDeadline) {
                budgetHit = true;
                break;
            }
            long t0 = clock.getAsLong();
            int cuts = stop.cuts();
            Attempt a = stop.stopped() ? null : attemptSize(family, (int) n);
            lastNanos = Math.max(1, clock.getAsLong() - t0);
            if (a == null || stop.cuts() != cuts) {
                stopped = true;   // the attempt did not run, or the stop cut it short: it says nothing
                break;
            }
            if (a.ok()) {
                lastOk = (int) n;
                if (n >= cap) {
                    break;
                }
                n = Math.min(2 * n, cap);
            } else {
                firstFail = (int) n;
                failure = a;
                break;
            }
        }
        while (!budgetHit && !stopped && firstFail > 0 && firstFail - Math.max(lastOk, min - 1) > 1) {
            // bisection sizes are below the failing one: the last attempt bounds the next
            if (clock.getAsLong() + lastNanos > rowDeadline) {
                budgetHit = true;
                break;
            }
            int mid = (Math.max(lastOk, min - 1) + firstFail) >>> 1;
            long t0 = clock.getAsLong();
            int cuts = stop.cuts();
            Attempt a = stop.stopped() ? null : attemptSize(family, mid);
            lastNanos = Math.max(1, clock.getAsLong() - t0);
            if (a == null || stop.cuts() != cuts) {
                stopped = true;
                break;
            }
            if (a.ok()) {
                lastOk = mid;
            } else {
                firstFail = mid;
                failure = a;
            }
        }
        if (stopped) {
            limitStopped = lastOk > 0;
            return limitEntry(row, min, cap, lastOk, firstFail, failure, "the probe was stopped: " + stop.reason()
                    + ", during this row", fullMethod);
        }
        return limitEntry(row, min, cap, lastOk, firstFail, failure, budgetHit ? "probe budget ran out for this row"
                : null, fullMethod);
    }

    private Attempt attemptSize(IntFunction<Optional<ProbeProgram>> family, int n) {
        Optional<ProbeProgram> p = family.apply(n);
        if (p.isEmpty()) {
            return new Attempt(Result.UNREACHABLE, "cannot be laid out within the per-variable and per-block limits"
                    + " measured before");
        }
        return attempt(p.get());
    }

    private DataCheckEntry limitEntry(Table11 row, int min, long cap, int lastOk, int firstFail, Attempt failure,
            String cutShort, String method) {
        Long declared = declaredLimit(row);
        String value = lastOk == 0 ? "0" : String.valueOf(lastOk);
        List<String> notes = new ArrayList<>();
        String bound;
        if (cutShort != null) {
            bound = DataCheckEntry.AT_LEAST;
            notes.add(cutShort + (firstFail > 0 ? " (fails at " + firstFail + ": " + failure.detail() + ")" : ""));
        } else if (firstFail < 0) {
            bound = DataCheckEntry.AT_LEAST;
            notes.add("reached the cap of " + cap + " (--probe-cap)");
        } else if (failure.result() == Result.UNJUDGED) {
            bound = DataCheckEntry.AT_LEAST;
            notes.add("at " + firstFail + " the implementation loads what the reference cannot judge (the reference"
                    + " rejects it: " + shorten(failure.detail()) + "): a natural bound of fclcert's reference");
        } else if (failure.result() == Result.UNREACHABLE) {
            bound = DataCheckEntry.AT_LEAST;
            notes.add("bounded by the rows it is made of: " + firstFail + " " + failure.detail());
        } else {
            bound = DataCheckEntry.EXACT;
            notes.add((lastOk == 0 ? "even the smallest program (" + min + " " + row.unit() + ") fails: "
                    : "at " + firstFail + ": ") + failure.detail());
        }
        if (declared != null) {
            if (lastOk < declared && bound.equals(DataCheckEntry.EXACT)) {
                notes.add(0, "DECLARED LIMIT NOT MET: the implementation declares " + declared + " but works only up to "
                        + lastOk);
            } else if (lastOk < declared) {
                notes.add("declared " + declared + ", not reached by the probe");
            } else {
                notes.add("declared " + declared + ": met");
            }
        }
        return entry(row, value, bound, method, String.join("; ", notes));
    }

    // ---------------------------------------------------------------- the other rows

    private DataCheckEntry dataTypes() {
        List<String> accepted = new ArrayList<>();
        List<String> others = new ArrayList<>();
        for (String type : DATA_TYPES) {
            Attempt a = attempt(Families.dataType(type));
            if (a.ok()) {
                accepted.add(type);
            } else {
                others.add(type + ": " + a.detail());
            }
        }
        return entry(Table11.DATA_TYPES, accepted.isEmpty() ? "none" : String.join(", ", accepted),
                DataCheckEntry.EXACT, "for each of " + String.join(", ", DATA_TYPES) + ": one input and one output of"
                        + " that type, y from 20 to 100 as x goes from 0 to 100, evaluated at 0, 25, 50, 100",
                others.isEmpty() ? "all accepted and evaluated correctly" : String.join("; ", others));
    }

    /** The comment forms of the line-comments row: name, and how to put it into the meter program. */
    static final String[][] COMMENT_FORMS = {
        {"(* *) on one line", "VAR_INPUT", "(* a comment on its own line *)\nVAR_INPUT"},
        {"(* *) across lines", "FUZZIFY x", "(* a comment\n   across two lines *)\nFUZZIFY x"},
        {"(* *) after a statement", "METHOD: CoGS;", "METHOD: CoGS; (* after a statement *)"},
        {"//", "VAR_OUTPUT", "// a comment to the end of the line\nVAR_OUTPUT"},
    };

    private DataCheckEntry comments() {
        String base = Families.meterProgram("REAL", "REAL");
        List<String> accepted = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        for (String[] form : COMMENT_FORMS) {
            String text = base.replaceFirst(java.util.regex.Pattern.quote(form[1]),
                    java.util.regex.Matcher.quoteReplacement(form[2]));
            Attempt a = attempt(new ProbeProgram(text, Families.meterVectors(0.25, 0.5, 1), base));
            if (a.ok()) {
                accepted.add(form[0]);
            } else {
                notes.add(form[0] + " not accepted: " + a.detail());
            }
        }
        String value = accepted.isEmpty() ? "NO" : "YES: " + String.join(", ", accepted);
        return entry(Table11.LINE_COMMENTS, value, DataCheckEntry.EXACT, "the same program with each comment form"
                + " inserted; a form counts when the program loads and evaluates like the program without it",
                String.join("; ", notes));
    }

    private static final String WORKLOAD_REJECTED = "the workload was rejected: ";

    private ImplementationUnderTest loadWorkload() throws IutException {
        LoadOutcome o = iut.load(Families.workload());
        if (o instanceof LoadOutcome.Rejected r) {
            throw new IutException(IutException.Kind.EVAL_ERROR, WORKLOAD_REJECTED + r.message());
        }
        return iut;
    }

    private static Map<String, Double> workloadVector(int k) {
        return Families.vector("x1", (k * 37 % 401) / 100.0, "x2", (k * 53 % 401) / 100.0, "x3",
                (k * 71 % 401) / 100.0);
    }

    private String memoryNote = "";
    private long heapGrowth = -1;

    private DataCheckEntry executionTime(long rowDeadline) {
        String method = "the workload (3 inputs × 3 terms, 27 rules of 3 subconditions, 5 singletons, CoGS): "
                + WARMUP_EVALS + " evaluations of warm-up, then up to " + TIMED_EVALS + " timed ones; median and 95th"
                + " percentile of each evaluation's wall-clock time as fclcert sees it (in process for reference and"
                + " java IUTs, the full round trip for process IUTs; plus the IUT's own elapsedMs when it reports it)";
        try {
            Runtime rt = Runtime.getRuntime();
            System.gc();
            long before = rt.totalMemory() - rt.freeMemory();
            loadWorkload();
            ProbeProgram check = new ProbeProgram(Families.workload(),
                    java.util.stream.IntStream.range(0, 50).mapToObj(Prober::workloadVector).toList());
            List<Map<String, Double>> want = ReferenceJudge.expected(check).outputs().orElseThrow();
            String wrong = "";
            for (int k = 0; k < WARMUP_EVALS; k++) {
                Map<String, Double> got = iut.eval(null, workloadVector(k % 50));
                if (k < 50 && wrong.isEmpty()) {
                    wrong = ReferenceJudge.compare(want.get(k), got).map(d -> "WRONG RESULTS on the workload: " + d)
                            .orElse("");
                }
            }
            long after = rt.totalMemory() - rt.freeMemory();
            heapGrowth = Math.max(0, after - before);
            double[] ms = new double[TIMED_EVALS];
            double[] own = new double[TIMED_EVALS];
            int count = 0;
            int owned = 0;
            for (; count < TIMED_EVALS && !outOfTime(rowDeadline); count++) {
                long t0 = System.nanoTime();
                iut.eval(null, workloadVector(count));
                ms[count] = (System.nanoTime() - t0) / 1e6;
                OptionalDouble side = iut.lastEvalMillis();
                if (side.isPresent()) {
                    own[owned++] = side.getAsDouble();
                }
            }
            if (count == 0) {
                return entry(Table11.EXECUTION_TIME, "", DataCheckEntry.NOT_MEASURED, method,
                        "probe budget ran out before timing");
            }
            double[] times = Arrays.copyOf(ms, count);
            Arrays.sort(times);
            String value = "median " + ms(times[count / 2]) + ", p95 " + ms(times[(int) Math.min(count - 1,
                    Math.ceil(0.95 * count) - 1)]);
            List<String> notes = new ArrayList<>();
            if (owned > 0) {
                double[] o = Arrays.copyOf(own, owned);
                Arrays.sort(o);
                notes.add("IUT-side elapsedMs: median " + ms(o[owned / 2]) + ", p95 "
                        + ms(o[(int) Math.min(owned - 1, Math.ceil(0.95 * owned) - 1)]));
            }
            notes.add(count + " timed evaluations" + (count < TIMED_EVALS ? " (probe budget ran out)" : ""));
            if (!wrong.isEmpty()) {
                notes.add(0, wrong);
            }
            return entry(Table11.EXECUTION_TIME, value, DataCheckEntry.EXACT, method, String.join("; ", notes));
        } catch (IutException e) {
            memoryNote = "the workload failed: " + fault(e).detail();
            return entry(Table11.EXECUTION_TIME, "", DataCheckEntry.NOT_MEASURED, method, memoryNote);
        }
    }

    private static String ms(double v) {
        return String.format(Locale.ROOT, v >= 1 ? "%.2f ms" : "%.4f ms", v);
    }

    private DataCheckEntry memory() {
        var rss = iut.peakMemoryBytes();
        if (rss.isPresent()) {
            return entry(Table11.MEMORY, String.valueOf(rss.getAsLong() / 1024), DataCheckEntry.EXACT,
                    "peak resident set size (VmHWM of /proc/PID/status) of the IUT process and its children so far",
                    "approximate: the whole process (interpreter or runtime included), after the probes up to here");
        }
        if (heapGrowth >= 0) {
            return entry(Table11.MEMORY, String.valueOf(heapGrowth / 1024), DataCheckEntry.EXACT,
                    "in process: growth of the used Java heap while loading the workload and evaluating it "
                            + WARMUP_EVALS + " times", "approximate: JVM-wide heap, garbage collection makes it noisy");
        }
        return entry(Table11.MEMORY, "", DataCheckEntry.NOT_MEASURED, "", memoryNote.isEmpty()
                ? "not measurable for this IUT: it reports no process memory (only a process IUT on Linux does) and"
                        + " the in-process heap was not sampled (the workload was not run)"
                : memoryNote);
    }

    private DataCheckEntry resolution(long rowDeadline) {
        String method = "ramp term (0, 0) (1, 1) swept in " + SWEEP_STEPS + " steps plus 8 steps of 1e-9; its degree d"
                + " is read back from y = d / (d + 0.5) (a second rule fires lo := 0 at degree 0.5); the step is the"
                + " smallest difference between distinct degrees";
        try {
            String base = Families.meterProgram("REAL", "REAL");
            if (iut.load(base) instanceof LoadOutcome.Rejected r) {
                return entry(Table11.DEGREE_RESOLUTION, "", DataCheckEntry.NOT_MEASURED, method,
                        "the sweep program was rejected: " + shorten(r.message()));
            }
            iut.eval(null, Families.vector("z", 0.5));
            TreeSet<Double> degrees = new TreeSet<>();
            double maxError = 0;
            for (int k = 0; k <= SWEEP_STEPS + 8 && !outOfTime(rowDeadline); k++) {
                double x = k <= SWEEP_STEPS ? (double) k / SWEEP_STEPS : 0.5 + (k - SWEEP_STEPS) * 1e-9;
                double y = iut.eval(null, Families.vector("x", x)).entrySet().stream()
                        .filter(e -> e.getKey().equalsIgnoreCase("y")).mapToDouble(Map.Entry::getValue).findFirst()
                        .orElse(Double.NaN);
                double d = 0.5 * y / (1 - y);
                maxError = Math.max(maxError, Double.isFinite(d) ? Math.abs(d - x) : Double.POSITIVE_INFINITY);
                degrees.add(d);
            }
            double step = Double.POSITIVE_INFINITY;
            Double previous = null;
            for (double d : degrees) {
                if (previous != null && d - previous > 1e-15) {
                    step = Math.min(step, d - previous);
                }
                previous = d;
            }
            String err = String.format(Locale.ROOT, "largest degree error %.3g", maxError);
            if (degrees.size() > SWEEP_STEPS + 8 && maxError < 1e-9) {
                return entry(Table11.DEGREE_RESOLUTION, "continuous (double)", DataCheckEntry.EXACT, method,
                        "every step resolved, down to 1e-9; " + err);
            }
            long levels = Math.round(1 / step);
            return entry(Table11.DEGREE_RESOLUTION, "≈ 1/" + levels, DataCheckEntry.EXACT, method,
                    degrees.size() + " distinct degrees over " + (SWEEP_STEPS + 9) + " inputs; " + err);
        } catch (IutException e) {
            return entry(Table11.DEGREE_RESOLUTION, "", DataCheckEntry.NOT_MEASURED, method, fault(e).detail());
        }
    }

    private DataCheckEntry identifiers(long rowDeadline) {
        long now = clock.getAsLong();
        DataCheckEntry longest = limit(Table11.IDENTIFIER_LENGTH, 1, n -> Optional.of(Families.longNames(n)),
                now + (rowDeadline - now) / 2, "");
        DataCheckEntry distinct = limit(Table11.IDENTIFIER_LENGTH, 1, n -> Optional.of(Families.distinctNames(n)),
                rowDeadline, "");
        Attempt cased = attempt(Families.mixedCase());
        String caseNote = cased.ok() ? "identifiers are case-insensitive, as FCL requires"
                : "NON-CONFORMANT: identifiers are case-sensitive (Temp declared, TEMP and temp used: "
                + cased.detail() + ")";
        String value = longest.value() + " accepted, distinct up to " + distinct.value();
        String bound = longest.bound().equals(DataCheckEntry.EXACT) && distinct.bound().equals(DataCheckEntry.EXACT)
                ? DataCheckEntry.EXACT : DataCheckEntry.AT_LEAST;
        return entry(Table11.IDENTIFIER_LENGTH, value, bound, "names of n characters for the input, its term, the"
                + " output and the rule block (longest accepted), and two inputs whose names differ only in their last"
                + " character selecting different values (distinct); sizes 1, 2, 4, … up to the cap, then bisection;"
                + " plus one program declaring Temp and using TEMP and temp",
                caseNote + "; longest: " + longest.note() + "; distinct: " + distinct.note());
    }
}
