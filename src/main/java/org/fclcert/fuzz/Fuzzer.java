package org.fclcert.fuzz;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.model.Feature;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.write.CanonicalWriter;

/**
 * Differential testing of an implementation against the reference on generated programs. Program {@code i}
 * of a run is generated from {@code (seed, i)} alone, and so are its steps, so a seed reproduces a run: the
 * same programs in the same order, whatever the number of jobs (with several jobs the budget may end the run
 * at a slightly different program). Each job drives its own session of the implementation. A disagreement
 * that switching off the feature of a known finding explains is counted as that finding; any other is shrunk
 * to a minimal case and deduplicated by its isolated feature and kind of deviation.
 */
public final class Fuzzer {
    /**
     * @param budget       how long to generate programs (shrinking the last findings may take a little longer)
     * @param maxPrograms  stop after this many programs (0 = no limit)
     * @param shrinkTime   the longest one finding is shrunk
     * @param maxShrinks   the most disagreements shrunk in one run; later unexplained ones are only counted
     * @param maxFindings  stop generating once this many distinct findings are known (0 = no limit)
     * @param layout       the library layout programs are sent in ({@code --present-as}); empty: standard FCL
     */
    public record Options(long seed, Duration budget, long maxPrograms, FuzzSettings settings, int jobs,
            Duration shrinkTime, int maxShrinks, int maxFindings, Optional<Dialect> layout) {
        public Options {
            if (jobs < 1) {
                throw new IllegalArgumentException("jobs must be at least 1");
            }
            if (layout.isPresent() && layout.get() == Dialect.STRICT) {
                throw new IllegalArgumentException("standard FCL is sent without a layout");
            }
        }

        public static Options of(long seed, Duration budget, FuzzSettings settings, int jobs) {
            Duration shrink = Duration.ofSeconds(Math.max(15, Math.min(60, budget.toSeconds() / 3)));
            return new Options(seed, budget, 0, settings, jobs, shrink, 40, 0, Optional.empty());
        }

        public Options withMaxPrograms(long n) {
            return new Options(seed, budget, n, settings, jobs, shrinkTime, maxShrinks, maxFindings, layout);
        }

        public Options withMaxFindings(int n) {
            return new Options(seed, budget, maxPrograms, settings, jobs, shrinkTime, maxShrinks, n, layout);
        }

        /** Programs sent in this library's layout ({@code --present-as}); empty: as standard FCL. */
        public Options withLayout(Optional<Dialect> l) {
            return new Options(seed, budget, maxPrograms, settings, jobs, shrinkTime, maxShrinks, maxFindings, l);
        }
    }

    /** Counters of a run, as shown while it goes and in the summary. */
    /**
     * @param referenceMillis      time the jobs spent on the reference side (generating, checking, judging and
     *                             evaluating steps, presenting), summed over jobs
     * @param implementationMillis time the jobs spent waiting for the implementation (load and every step)
     * @param shrinkMillis         time spent deciding whether a disagreement is known, and shrinking it
     */
    public record Progress(long programs, long vectors, int findings, long disagreements, long elapsedMillis,
            long unfairSteps, long programsWithoutSteps, long generatorBugs, int restarts, long notPresentable,
            long referenceMillis, long implementationMillis, long shrinkMillis) {
        public double programsPerSecond() {
            return elapsedMillis == 0 ? 0 : programs * 1000.0 / elapsedMillis;
        }

        public double vectorsPerSecond() {
            return elapsedMillis == 0 ? 0 : vectors * 1000.0 / elapsedMillis;
        }
    }

    /**
     * The whole result.
     *
     * @param notPresentable     per reason (the writer's {@code FCL-X1nn} code, or a fault of fclcert's: see {@link
     *                           Presentation}), how many generated programs were not sent because the layout of
     *                           {@code --present-as} could not say them
     * @param presentationFaults the first programs a writer and fclcert's reader of its dialect disagreed on
     * @param stopped            why the run was stopped before its budget or program count ran out ({@link #stop})
     */
    public record Result(IutInfo iut, Options options, Instant started, Progress progress, List<Finding> findings,
            long unexplained, List<String> generatorBugs, List<String> infrastructureErrors,
            Map<String, Long> notPresentable, List<String> presentationFaults, Optional<String> stopped) {
    }

    private final CanonicalWriter writer = new CanonicalWriter();
    private final FairnessJudge fairness;
    private final AtomicLong nextProgram = new AtomicLong();
    private final AtomicLong programs = new AtomicLong();
    private final AtomicLong vectors = new AtomicLong();
    private final AtomicLong disagreements = new AtomicLong();
    private final AtomicLong unfair = new AtomicLong();
    private final AtomicLong noSteps = new AtomicLong();
    private final AtomicLong unexplained = new AtomicLong();
    private final AtomicLong shrinks = new AtomicLong();
    private final AtomicLong notPresentable = new AtomicLong();
    private final AtomicLong referenceNanos = new AtomicLong();
    private final AtomicLong implementationNanos = new AtomicLong();
    private final AtomicLong shrinkNanos = new AtomicLong();
    private final Map<String, Long> notPresentableBy = new TreeMap<>();
    private final List<String> presentationFaults = new ArrayList<>();
    private Presentation presentation = Presentation.standard();
    private final List<String> generatorBugs = new ArrayList<>();
    private final List<String> infrastructure = new ArrayList<>();
    private final Map<String, Finding> findings = new LinkedHashMap<>();
    private final List<IutSession> sessions = new ArrayList<>();
    private volatile Instant start;
    /** Why the run was stopped from outside ({@link #stop}), or null while it runs. */
    private volatile String stopped;

    public Fuzzer() {
        this(new ScreenedFairness());
    }

    public Fuzzer(FairnessJudge fairness) {
        this.fairness = fairness;
    }

    /**
     * Stops the run from another thread (the command line's answer to a signal): no program is started after this,
     * a shrink under way ends with the smallest case found so far, and what a program under way does from now on
     * (an implementation that dies of the same Ctrl-C) is not held against the implementation. {@link #run} then
     * returns with everything found so far and {@link Result#stopped()} saying why. Only the first stop counts.
     */
    public synchronized void stop(String why) {
        if (stopped == null) {
            stopped = why;
        }
    }

    /**
     * After {@link #stop}, for an implementation that does not answer: closes every session (ending its process), so
     * that the jobs waiting on it return at once instead of at the request's timeout.
     */
    public void abandon() {
        synchronized (sessions) {
            sessions.forEach(IutSession::close);
        }
    }

    private boolean stopRequested() {
        return stopped != null;
    }

    /** Program {@code index} of the run with this seed. */
    public static long programSeed(long seed, long index) {
        long z = seed + (index + 1) * 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /**
     * Runs until the budget or the program count is used up.
     *
     * @param progress called about every {@code interval} from the calling thread
     * @throws IutException of kind INFRA when not even the first session can be opened
     */
    public Result run(IutSession.Factory factory, Options options, Duration interval, Consumer<Progress> progress)
            throws IutException, InterruptedException {
        start = Instant.now();
        presentation = new Presentation(options.layout());
        IutSession first = new IutSession(factory);
        IutInfo info;
        try {
            info = first.iut().hello();
        } catch (IutException e) {
            first.close();
            throw new IutException(IutException.Kind.INFRA, "the implementation did not answer hello: " + e.getMessage(),
                    e.stderrTail());
        }
        sessions.add(first);
        Instant end = start.plus(options.budget());
        ProgramGenerator generator = new ProgramGenerator(options.settings());
        List<Thread> threads = new ArrayList<>();
        for (int j = 0; j < options.jobs(); j++) {
            int job = j;
            Thread t = new Thread(() -> job(job == 0 ? first : null, factory, options, generator, end), "fuzz-" + j);
            t.setDaemon(true);
            threads.add(t);
            t.start();
        }
        for (Thread t : threads) {
            while (t.isAlive()) {
                t.join(interval.toMillis());
                if (t.isAlive()) {
                    progress.accept(progress());
                }
            }
        }
        synchronized (sessions) {
            sessions.forEach(IutSession::close);
        }
        List<Finding> list;
        synchronized (findings) {
            list = new ArrayList<>(findings.values());
        }
        list.sort(Comparator.comparingLong(Finding::programIndex));
        synchronized (generatorBugs) {
            return new Result(info, options, start, progress(), List.copyOf(list), unexplained.get(),
                    List.copyOf(generatorBugs), List.copyOf(infrastructure), java.util.Collections.unmodifiableMap(new TreeMap<>(notPresentableBy)),
                    List.copyOf(presentationFaults), Optional.ofNullable(stopped));
        }
    }

    public Progress progress() {
        int n;
        synchronized (findings) {
            n = findings.size();
        }
        int restarts;
        synchronized (sessions) {
            restarts = sessions.stream().mapToInt(IutSession::restarts).sum();
        }
        long elapsed = start == null ? 0 : Duration.between(start, Instant.now()).toMillis();
        return new Progress(programs.get(), vectors.get(), n, disagreements.get(), elapsed, unfair.get(), noSteps.get(),
                generatorBugs.size(), restarts, notPresentable.get(), referenceNanos.get() / 1_000_000,
                implementationNanos.get() / 1_000_000, shrinkNanos.get() / 1_000_000);
    }

    private void job(IutSession given, IutSession.Factory factory, Options options, ProgramGenerator generator,
            Instant end) {
        IutSession session = given;
        try {
            if (session == null) {
                session = new IutSession(factory);
                synchronized (sessions) {
                    sessions.add(session);
                }
            }
            VectorGenerator vectorGenerator = new VectorGenerator(counting());
            while (Instant.now().isBefore(end) && !stopRequested()) {
                long index = nextProgram.getAndIncrement();
                if (options.maxPrograms() > 0 && index >= options.maxPrograms() || enoughFindings(options)) {
                    break;
                }
                one(session, options, generator, vectorGenerator, index);
            }
        } catch (IutException e) {
            if (stopRequested()) {
                return;     // the session was closed by abandon(), or the implementation died of the same signal
            }
            synchronized (generatorBugs) {
                infrastructure.add("job " + Thread.currentThread().getName() + ": " + e.getMessage());
            }
        } catch (RuntimeException e) {
            synchronized (generatorBugs) {
                infrastructure.add("job " + Thread.currentThread().getName() + ": internal error: " + e);
            }
        }
    }

    private boolean enoughFindings(Options options) {
        synchronized (findings) {
            return options.maxFindings() > 0 && findings.size() >= options.maxFindings();
        }
    }

    private FairnessJudge counting() {
        return (program, before, step) -> {
            boolean fair = fairness.fair(program, before, step);
            if (!fair) {
                unfair.incrementAndGet();
            }
            return fair;
        };
    }

    /** A generated program ready to be sent: its text, model, reference, fair steps, expected values, text as sent. */
    private record Prepared(long seed, String text, Program program, ReferenceProgram ref,
            List<java.util.Map<String, Double>> steps, List<ReferenceProgram.Step> expected, Presentation.Sent sent) {
    }

    private void one(IutSession session, Options options, ProgramGenerator generator, VectorGenerator vg, long index)
            throws IutException {
        long t0 = System.nanoTime();
        Prepared p = prepare(options, generator, vg, index);
        long t1 = System.nanoTime();
        referenceNanos.addAndGet(t1 - t0);
        if (p == null) {
            return;
        }
        Optional<Deviation> d = Trial.run(session, p.ref(), p.sent(), p.expected());
        if (stopRequested()) {
            return;     // what the implementation did while the run was being stopped is not counted
        }
        long t2 = System.nanoTime();
        implementationNanos.addAndGet(t2 - t1);
        programs.incrementAndGet();
        vectors.addAndGet(d.isEmpty() ? p.steps().size() : d.get().step() + 1);     // the vectors the IUT evaluated
        if (d.isPresent()) {
            try {
                disagreement(session, options, index, p, d.get());
            } finally {
                shrinkNanos.addAndGet(System.nanoTime() - t2);
            }
        }
    }

    /** The reference side of one program; null when there is nothing to send (counted why). */
    private Prepared prepare(Options options, ProgramGenerator generator, VectorGenerator vg, long index) {
        long seed = programSeed(options.seed(), index);
        Program generated = generator.generate(seed);
        String text = writer.write(generated);
        Analysis analysis = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", text);
        if (analysis.program().isEmpty()) {
            synchronized (generatorBugs) {
                generatorBugs.add("program " + index + " (seed " + seed + "): " + analysis.diagnostics().get(0));
            }
            return null;
        }
        Program program = analysis.program().get();
        Presentation.Outcome written = presentation.write(program);
        if (written.sent().isEmpty()) {
            notPresented(index, written);
            return null;
        }
        ReferenceProgram ref = new ReferenceProgram(program);
        List<java.util.Map<String, Double>> steps = vg.steps(ref, new Random(seed ^ 0x5DEECE66DL));
        if (steps.isEmpty()) {
            noSteps.incrementAndGet();
            return null;
        }
        List<ReferenceProgram.Step> expected;
        try {
            expected = ref.run(steps);
        } catch (EvaluationException e) {
            noSteps.incrementAndGet();
            return null;
        }
        Presentation.Outcome presented = presentation.vouch(written, expected);
        if (presented.sent().isEmpty()) {
            notPresented(index, presented);
            return null;
        }
        return new Prepared(seed, text, program, ref, steps, expected, presented.sent().get());
    }

    /** A new disagreement: a known finding again, or shrunk into a finding of its own. */
    private void disagreement(IutSession session, Options options, long index, Prepared p, Deviation deviation)
            throws IutException {
        disagreements.incrementAndGet();
        Shrinker.Case raw = new Shrinker.Case(p.program(), p.steps());
        if (known(session, raw, deviation)) {
            return;
        }
        if (shrinks.incrementAndGet() > options.maxShrinks()) {
            unexplained.incrementAndGet();
            return;
        }
        long foundAfter = Duration.between(start, Instant.now()).toMillis();
        Instant deadline = Instant.now().plus(options.shrinkTime());
        Shrinker.Result shrunk = new Shrinker(session, fairness, presentation, 4000, deadline, this::stopRequested).shrink(raw, deviation);
        Feature feature = Isolation.feature(shrunk.minimal(), shrunk.deviation(), presentation);
        Finding f = new Finding(feature, deviation.kind(), shrunk.minimal(), shrunk.deviation(), deviation, index, p.seed(),
                (int) p.text().lines().count(), shrunk.tried(), 0, foundAfter,
                Duration.between(start, Instant.now()).toMillis() - foundAfter);
        synchronized (findings) {
            Finding before = findings.get(f.key());
            if (before == null) {
                findings.put(f.key(), f);
            } else if (f.programIndex() < before.programIndex()) {
                findings.put(f.key(), new Finding(f.feature(), f.kind(), f.minimal(), f.deviation(), f.original(),
                        f.programIndex(), f.programSeed(), f.originalLines(), f.shrinkTrials(), before.duplicates() + 1,
                        f.foundAfterMillis(), f.shrinkMillis()));
            } else {
                findings.put(f.key(), before.withDuplicate());
            }
        }
    }

    private void notPresented(long index, Presentation.Outcome o) {
        notPresentable.incrementAndGet();
        synchronized (notPresentableBy) {
            notPresentableBy.merge(o.reason(), 1L, Long::sum);
            if (Presentation.FAULTS.contains(o.reason()) && presentationFaults.size() < 5) {
                presentationFaults.add("program " + index + ": " + o.reason() + ": " + o.detail());
            }
        }
    }

    /**
     * True when the disagreement is a known finding of the same kind again: a refusal that says the same (numbers
     * aside) or quotes the same token of the language (not a name of the program), a small error on an output whose METHOD is a finding, or one that goes away when the feature of a
     * finding is switched off.
     */
    private boolean known(IutSession session, Shrinker.Case raw, Deviation d) throws IutException {
        List<Finding> same;
        synchronized (findings) {
            same = findings.values().stream().filter(f -> f.kind() == d.kind()).toList();
        }
        if (!Isolation.valueKind(d.kind())) {
            String signature = Isolation.signature(d);
            Optional<String> token = Isolation.quotedToken(d, raw.program());
            for (Finding f : same) {
                if (Isolation.signature(f.original()).equals(signature) || Isolation.signature(f.deviation()).equals(signature)
                        || token.isPresent() && token.equals(Isolation.quotedToken(f.deviation(), f.minimal().program()))) {
                    synchronized (findings) {
                        findings.put(f.key(), findings.get(f.key()).withDuplicate());
                    }
                    return true;
                }
            }
        }
        // a small error on an output whose METHOD is already a finding (a sampling library errs so on every such output)
        Optional<Feature> method = Isolation.smallErrorOfMethod(raw, d);
        for (Finding f : same) {
            if (method.isPresent() && f.feature() == method.get()) {
                synchronized (findings) {
                    findings.put(f.key(), findings.get(f.key()).withDuplicate());
                }
                return true;
            }
        }
        java.util.Set<Feature> used = new FeatureDetector().detect(raw.program()).features();
        Shrinker probe = new Shrinker(session, fairness, presentation, Integer.MAX_VALUE, Instant.MAX, this::stopRequested);
        for (Finding f : same) {
            if (!used.contains(f.feature())) {
                continue;
            }
            Optional<Program> ablated = Ablation.without(raw.program(), f.feature());
            if (ablated.isEmpty()) {
                continue;
            }
            Optional<Shrinker.Case> valid = Shrinker.validate(new Shrinker.Case(ablated.get(), raw.steps()));
            if (valid.isPresent() && probe.test(valid.get(), d.kind()).isEmpty()) {
                synchronized (findings) {
                    findings.put(f.key(), findings.get(f.key()).withDuplicate());
                }
                return true;
            }
        }
        return false;
    }
}
