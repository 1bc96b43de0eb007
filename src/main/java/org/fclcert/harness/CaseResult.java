package org.fclcert.harness;

import com.fasterxml.jackson.databind.annotation.JsonDeserialize;
import com.fasterxml.jackson.databind.annotation.JsonSerialize;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * The outcome of one case, carrying everything the reports need, in four parts: which case it is
 * ({@link PlannedCase}), the {@link Verdict}, the {@link Evidence} measured while it ran, and the
 * {@link Export} check of clause 6 e); plus how it {@link Setup ran}. A case that never ran is
 * {@link #skipped}: it has a verdict and nothing else.
 *
 * <p>On disk this is one flat {@code "type":"case"} line of {@code results.jsonl} and one entry of
 * {@code report.json}'s {@code cases} ({@link CaseResultJson}, fields in {@code docs/report-format.md}).
 */
@JsonSerialize(converter = CaseResultJson.FromResult.class)
@JsonDeserialize(converter = CaseResultJson.ToResult.class)
public record CaseResult(PlannedCase plan, Verdict verdict, Evidence evidence, Export export, Setup setup,
        Presented presented, List<Exchange> replies) {

    public CaseResult {
        Objects.requireNonNull(plan, "plan");
        Objects.requireNonNull(verdict, "verdict");
        evidence = evidence == null ? Evidence.NONE : evidence;
        export = export == null ? Export.NOT_RUN : export;
        setup = setup == null ? Setup.NOT_RUN : setup;
        replies = replies == null ? null : List.copyOf(replies);
    }

    /** A result without recorded replies (see {@link #withReplies}). */
    public CaseResult(PlannedCase plan, Verdict verdict, Evidence evidence, Export export, Setup setup,
            Presented presented) {
        this(plan, verdict, evidence, export, setup, presented, null);
    }

    /**
     * This result with the implementation's replies to the case's requests ({@link Exchange}): the evidence
     * the case line keeps, from which the case is judged again.
     */
    public CaseResult withReplies(List<Exchange> value) {
        return new CaseResult(plan, verdict, evidence, export, setup, presented, value);
    }

    /** A result of the language axis only (no program presented in a library's layout). */
    public CaseResult(PlannedCase plan, Verdict verdict, Evidence evidence, Export export, Setup setup) {
        this(plan, verdict, evidence, export, setup, null);
    }

    /** This result with its semantic axis. */
    public CaseResult withPresented(Presented value) {
        return new CaseResult(plan, verdict, evidence, export, setup, value, replies);
    }

    /** The semantic axis of this case, when the run presented programs in a library's layout. */
    public Optional<Presented> presentedResult() {
        return Optional.ofNullable(presented);
    }

    /**
     * The semantic axis of a positive case ({@code --present-as}): the case's program written in a library's
     * layout by fclcert's writer of it, proved by reading it back, and run on the implementation. {@code status}
     * is {@link PresentedStatus#NOT_PRESENTABLE} (with the writer's reason) when the layout cannot say the
     * program, or fclcert's own reading of the written text does not give the case's expected values.
     *
     * @param dialect  the layout ({@code fuzzylite}, {@code jfuzzylogic}, {@code ffll})
     * @param program  the written text, kept for a presented case that did not pass
     */
    public record Presented(String dialect, PresentedStatus status, String message, List<String> notes,
            Evidence evidence, String program) {
        public Presented {
            Objects.requireNonNull(dialect, "dialect");
            Objects.requireNonNull(status, "status");
            notes = notes == null ? List.of() : List.copyOf(notes);
            evidence = evidence == null ? Evidence.NONE : evidence;
        }
    }

    /**
     * The verdict: status, the one-sentence reason, further notes, and for a negative case the
     * implementation rejected, where it placed the rejection (null otherwise).
     */
    public record Verdict(CaseStatus status, String message, List<String> notes, RejectionPlace rejection) {
        public Verdict {
            Objects.requireNonNull(status, "status");
            notes = notes == null ? List.of() : List.copyOf(notes);
        }
    }

    /**
     * What was seen while the case ran; every part may be absent (null). {@code step}: the first wrong step,
     * or the step at which the implementation broke down; {@code mismatch}: what was expected and what came;
     * {@code error}: the implementation's own error text (with the end of its stderr); {@code maxError}: the
     * largest absolute error over every compared output of the case, whatever its status (+&infin; once an
     * output was not finite, see {@link org.fclcert.corpus.OutputComparison}); {@code reference}: what the
     * reference evaluator did at that step of a positive case that did not pass.
     */
    public record Evidence(Step step, Mismatch mismatch, String error, Double maxError, ReferenceTrace reference) {
        public static final Evidence NONE = new Evidence(null, null, null, null);

        /** Evidence without the reference's trace. */
        public Evidence(Step step, Mismatch mismatch, String error, Double maxError) {
            this(step, mismatch, error, maxError, null);
        }
    }

    /** A step of a positive case: its 1-based number and its inputs. */
    public record Step(int number, Map<String, Double> inputs) {
        public Step {
            inputs = inputs == null ? Map.of() : Collections.unmodifiableMap(new LinkedHashMap<>(inputs));
        }
    }

    /**
     * Expected against actual: the output values of one step of a positive case, or two sentences
     * ({@code reject: FCL-C002 at line 14} / {@code accepted}) for a load or a rejection.
     */
    public sealed interface Mismatch {
        /** The expected side as the reports show it: a map of outputs or a sentence. */
        Object expected();

        /** The actual side as the reports show it. */
        Object actual();

        /** Output values; an implementation may leave an output out, or (over the protocol) send null. */
        record Outputs(Map<String, Double> expected, Map<String, Double> actual) implements Mismatch {
            public Outputs {
                expected = Collections.unmodifiableMap(new LinkedHashMap<>(expected));
                actual = Collections.unmodifiableMap(new LinkedHashMap<>(actual));
            }
        }

        record Sentences(String expected, String actual) implements Mismatch {
        }
    }

    /** The export check of clause 6 e): its status and why. */
    public record Export(ExportStatus status, String message) {
        public static final Export NOT_RUN = new Export(ExportStatus.NOT_RUN, null);

        public Export {
            status = status == null ? ExportStatus.NOT_RUN : status;
        }
    }

    /**
     * How the case was run: the function block evaluated (null: the first), the tolerance described,
     * the program text (kept only for a case that did not pass, so a report can show it), how long it took, and
     * how often the implementation broke down ({@code crashes}: crashed, hung or broke the protocol, its process
     * killed) and was restarted while the case ran (null when it did neither).
     */
    public record Setup(String block, String tolerance, String program, Long durationMs, Integer crashes,
            Integer restarts) {
        public static final Setup NOT_RUN = new Setup(null, null, null, null);

        /** A setup in which the implementation neither broke down nor was restarted. */
        public Setup(String block, String tolerance, String program, Long durationMs) {
            this(block, tolerance, program, durationMs, null, null);
        }
    }

    /** This result with the breakdowns and restarts of the implementation while it ran (none: unchanged). */
    public CaseResult withBreakdowns(int crashes, int restarts) {
        if (crashes == 0 && restarts == 0) {
            return this;
        }
        return new CaseResult(plan, verdict, evidence, export, new Setup(setup.block(), setup.tolerance(),
                setup.program(), setup.durationMs(), crashes, restarts), presented);
    }

    /** A skipped result for a planned case that never ran. */
    public static CaseResult skipped(PlannedCase c, String reason) {
        return new CaseResult(c, new Verdict(CaseStatus.SKIPPED, reason, List.of(), null), Evidence.NONE,
                Export.NOT_RUN, Setup.NOT_RUN);
    }

    public String id() {
        return plan.id();
    }

    public String title() {
        return plan.title();
    }

    /** {@code basic}, {@code extension} or {@code open}. */
    public String level() {
        return plan.level();
    }

    /** The feature ids this case is evidence for, the first being the one it is filed under. */
    public List<String> tests() {
        return plan.tests();
    }

    public List<String> flags() {
        return plan.flags();
    }

    public CaseStatus status() {
        return verdict.status();
    }

    public String message() {
        return verdict.message();
    }

    /** The 1-based steps reported as not judged: the vectors the case flags {@code knife-edge:<n>}. */
    public java.util.SortedSet<Integer> notJudgedSteps() {
        return Flags.knifeEdges(plan.flags());
    }

    public boolean interpretation() {
        return plan.interpretation();
    }

    private static final java.util.regex.Pattern EXPECTED_REJECTION =
            java.util.regex.Pattern.compile("reject: (FCL-[A-Z]+[0-9]+) at line ([0-9]+).*");

    /** The error a negative case expects, as its expected side says it ({@code reject: FCL-C002 at line 14}). */
    public record ExpectedRejection(String code, int line) {
    }

    /** For a negative case: the code and line of the error it expects. */
    public Optional<ExpectedRejection> expectedRejection() {
        if (!(evidence.mismatch() instanceof Mismatch.Sentences m) || m.expected() == null) {
            return Optional.empty();
        }
        java.util.regex.Matcher match = EXPECTED_REJECTION.matcher(m.expected());
        return match.matches() ? Optional.of(new ExpectedRejection(match.group(1), Integer.parseInt(match.group(2))))
                : Optional.empty();
    }

    /** A line (1-based) of the program as sent, stripped, when the result kept the program (cases that did not pass). */
    public Optional<String> programLine(int line) {
        List<String> lines = setup.program() == null ? List.of() : setup.program().lines().toList();
        return line >= 1 && line <= lines.size() ? Optional.of(lines.get(line - 1).strip()) : Optional.empty();
    }

    /** The mismatch, if the case recorded one. */
    public Optional<Mismatch> mismatch() {
        return Optional.ofNullable(evidence.mismatch());
    }
}
