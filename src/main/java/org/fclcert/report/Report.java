package org.fclcert.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.List;
import org.fclcert.harness.CaseResult;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.harness.RunHeader;

/**
 * A certification report: what was run against what, the verdicts, and every case result. This record is
 * exactly what {@code report.json} holds (schema in {@code docs/report-format.md}); the other renderings are
 * made from it.
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Report(
        int formatVersion,
        String generatedAt,
        RunHeader.Iut iut,
        RunHeader.Toolkit toolkit,
        RunHeader.CorpusInfo corpus,
        Run run,
        Summary summary,
        Rejections rejections,
        BasicLevel basicLevel,
        List<FeatureRow> features,
        List<DataCheckEntry> dataCheckList,
        List<InterpretationEntry> interpretation,
        Claims claims,
        List<Causes.Cause> causes,
        List<CaseResult> cases,
        SemanticAxis semantic,
        Origin origin) {

    public static final int FORMAT_VERSION = 1;

    public Report {
        features = List.copyOf(features);
        dataCheckList = List.copyOf(dataCheckList);
        interpretation = List.copyOf(interpretation);
        causes = causes == null ? List.of() : List.copyOf(causes);
        cases = List.copyOf(cases);
    }

    /** A report without its origin (see {@link Origin#apply}). */
    public Report(int formatVersion, String generatedAt, RunHeader.Iut iut, RunHeader.Toolkit toolkit,
            RunHeader.CorpusInfo corpus, Run run, Summary summary, Rejections rejections, BasicLevel basicLevel,
            List<FeatureRow> features, List<DataCheckEntry> dataCheckList, List<InterpretationEntry> interpretation,
            Claims claims, List<Causes.Cause> causes, List<CaseResult> cases, SemanticAxis semantic) {
        this(formatVersion, generatedAt, iut, toolkit, corpus, run, summary, rejections, basicLevel, features,
                dataCheckList, interpretation, claims, causes, cases, semantic, null);
    }

    /** A report of the language axis only. */
    public Report(int formatVersion, String generatedAt, RunHeader.Iut iut, RunHeader.Toolkit toolkit,
            RunHeader.CorpusInfo corpus, Run run, Summary summary, Rejections rejections, BasicLevel basicLevel,
            List<FeatureRow> features, List<DataCheckEntry> dataCheckList, List<InterpretationEntry> interpretation,
            Claims claims, List<Causes.Cause> causes, List<CaseResult> cases) {
        this(formatVersion, generatedAt, iut, toolkit, corpus, run, summary, rejections, basicLevel, features,
                dataCheckList, interpretation, claims, causes, cases, null);
    }

    /** What the two axes of a feature row mean, for every rendering. */
    public static final String LANGUAGE_AXIS = "language: reads the standard's text (the clause 6 statement)";
    public static final String SEMANTIC_AXIS = "semantic: computes the standard's results on programs it can read"
            + " (the positive cases written in the library's layout)";

    /**
     * The semantic axis of the run ({@code --present-as}), absent when the run had none: the layout, and what
     * became of the positive cases presented in it ({@code notPresentable}: the layout cannot say the program).
     */
    public record SemanticAxis(String presentAs, int cases, int passed, int failed, int errored, int skipped,
            int notPresentable) {
        /** {@code semantic axis (fuzzylite layout): 90 presented, 70 passed, 20 failed, …}. */
        public String sentence() {
            return "Semantic axis (" + presentAs + " layout): " + (cases - notPresentable) + " of " + cases
                    + " positive cases presented, " + passed + " passed, " + failed + " failed, " + errored
                    + " errored, " + skipped + " skipped, " + notPresentable + " not presentable";
        }
    }


    /** How the run went: when, with which filters, whether every selected case ran, problems reading results. */
    public record Run(String startedAt, boolean complete, RunHeader.Selection selection, List<String> problems) {
        public Run {
            problems = List.copyOf(problems);
        }
    }

    /**
     * The case counts, and how often the implementation broke down (crashed, hung or broke the protocol, each
     * costing its case) and was restarted over the run: the sums of the cases' own counts.
     */
    public record Summary(int cases, int passed, int failed, int errored, int skipped, int crashes, int restarts) {
        public Summary(int cases, int passed, int failed, int errored, int skipped) {
            this(cases, passed, failed, errored, skipped, 0, 0);
        }
    }

    /**
     * The negative cases the implementation rejected, by where it placed the rejection ({@link
     * org.fclcert.harness.RejectionPlace}): only {@code atErrorLine} shows the error itself was found.
     */
    public record Rejections(int rejected, int atErrorLine, int otherLine, int unlocated) {
        /** {@code 72 negative cases rejected: 8 at the error's line, 4 at another line, 60 without a line}. */
        public String sentence() {
            return rejected + " negative case(s) rejected: " + atErrorLine + " at the error's line, " + otherLine
                    + " at another line, " + unlocated + " without a line";
        }

        /** True when some rejections may have been for another reason than the case's error. */
        public boolean doubtful() {
            return otherLine + unlocated > 0;
        }
    }

    /** Why a rejection elsewhere than at the error's line is weak evidence, for the reports. */
    public static final String REJECTION_CAVEAT = "a rejection at another line or without a line shows the program"
            + " was refused, not that this case's error was found (the implementation may not read the program at all)";

    /**
     * Clause 6.1 b): conformant only when every Basic Level case of the corpus (not flagged interpretation)
     * was run and passed. {@code required} is that number in the corpus, {@code run} how many were run (a case the
     * run never reached is not run). {@code verdict}: {@value #CONFORMANT}, {@value #NOT_CONFORMANT} (a Basic
     * case that ran did not pass) or {@value #NOT_DETERMINED} (none that ran failed, but not all ran).
     */
    public record BasicLevel(boolean conformant, int required, int run, int passed, String reason, String verdict) {
        public static final String CONFORMANT = "conformant";
        public static final String NOT_CONFORMANT = "not conformant";
        public static final String NOT_DETERMINED = "not determined";

        public BasicLevel {
            if (verdict == null) {   // a report.json written before the field existed
                verdict = conformant ? CONFORMANT : passed < run ? NOT_CONFORMANT : NOT_DETERMINED;
            }
        }

        public BasicLevel(boolean conformant, int required, int run, int passed, String reason) {
            this(conformant, required, run, passed, reason, null);
        }

        /** True when the run cannot say whether the implementation is conformant: no failure, not every case run. */
        @com.fasterxml.jackson.annotation.JsonIgnore
        public boolean notDetermined() {
            return NOT_DETERMINED.equals(verdict);
        }

        /** {@code not determined (1 of 92 run)}, {@code conformant (all 92 Basic Level cases passed)}: for every front end. */
        public String sentence() {
            return verdict + " (" + reason + ")";
        }
    }

    /**
     * One row of Table 8, 9 or 10 with the cases that are evidence for it (interpretation cases excluded).
     * {@code status} and the counts are the language verdict: the corpus programs as the standard writes them.
     * {@code semantic} is the second verdict — the same cases sent in the implementation's own layout — when
     * that axis was run; null (absent from report.json) otherwise.
     */
    public record FeatureRow(String id, int table, String level, String element, String description,
            FeatureStatus status, int passed, int failed, int errored, int skipped, List<String> cases,
            List<String> notPassed, @JsonInclude(JsonInclude.Include.NON_NULL) Semantic semantic,
            int required, int run, @JsonInclude(JsonInclude.Include.NON_EMPTY) List<String> notCounted) {
        // required: the cases of its level or below the verdict needs (-1: unknown, a results file without
        // corpus.rowCases narrowed by a selection); run: how many of them ran
        public FeatureRow {
            cases = List.copyOf(cases);
            notPassed = List.copyOf(notPassed);
            notCounted = notCounted == null ? List.of() : List.copyOf(notCounted);
        }

        /** A row without the counts of what its verdict needs (a report.json written before they existed). */
        public FeatureRow(String id, int table, String level, String element, String description,
                FeatureStatus status, int passed, int failed, int errored, int skipped, List<String> cases,
                List<String> notPassed, Semantic semantic) {
            this(id, table, level, element, description, status, passed, failed, errored, skipped, cases, notPassed,
                    semantic, 0, 0, List.of());
        }

        /** A row with the language verdict only. */
        public FeatureRow(String id, int table, String level, String element, String description,
                FeatureStatus status, int passed, int failed, int errored, int skipped, List<String> cases,
                List<String> notPassed) {
            this(id, table, level, element, description, status, passed, failed, errored, skipped, cases, notPassed,
                    null, 0, 0, List.of());
        }

        /**
         * The row's verdict in words, naming its cases: {@code partial (2 of 3 passed; not passed: E-X-001)},
         * {@code not determined (1 of 6 run)}, with the cases whose failure counts against another row.
         */
        public String sentence() {
            StringBuilder s = new StringBuilder(status.label());
            List<String> parts = new java.util.ArrayList<>();
            int counted = passed + failed + errored;
            if (status == FeatureStatus.NOT_DETERMINED || status == FeatureStatus.NOT_TESTED) {
                if (required > 0) {
                    parts.add(run + " of " + required + " run");
                } else if (required < 0) {
                    parts.add(run + " run");
                }
            } else if (counted > 0) {
                parts.add(passed + " of " + counted + " passed");
            }
            if (!notPassed.isEmpty()) {
                parts.add("not passed: " + String.join(", ", notPassed));
            }
            if (!notCounted.isEmpty()) {
                parts.add("not counted: " + String.join(", ", notCounted));
            }
            return parts.isEmpty() ? s.toString() : s.append(" (").append(String.join("; ", parts)).append(')').toString();
        }
    }

    /**
     * The semantic verdict of a feature row: of {@code total} positive cases the implementation's dialect can
     * express ({@code --present-as}), {@code passed} computed the standard's values when sent in that layout;
     * {@code notPresentable} cases the layout cannot say are left out of {@code total}; {@code notPassed} names
     * the presented cases that did not pass.
     */
    public record Semantic(FeatureStatus status, int passed, int total, int notPresentable,
            List<String> notPassed) {
        public Semantic {
            notPassed = notPassed == null ? List.of() : List.copyOf(notPassed);
        }

        public Semantic(FeatureStatus status, int passed, int total) {
            this(status, passed, total, 0, List.of());
        }
    }

    /**
     * A case that depends on a reading of the standard: shown on its own, counted against no verdict. {@code
     * cause} is set when the implementation rejected the program at load (a reason of its own dialect, which
     * says nothing about the point the case depends on); null otherwise.
     */
    public record InterpretationEntry(String id, String title, String flag, String status, String message,
            String cause) {
        /** Rejected at load: the case never reached the point it depends on. */
        @com.fasterxml.jackson.annotation.JsonIgnore
        public boolean rejectedAtLoad() {
            return cause != null;
        }
    }

    /**
     * The implementation's claims (feature ids from {@code hello}) against the measurements: {@code confirmed}
     * realised as claimed, {@code notRealised} claimed but partial or not realised (with the row's status),
     * {@code untested} claimed but without a case in this run, {@code unknown} not a feature id of the
     * catalogue, {@code unclaimed} realised Extension or Open Level features the implementation did not claim,
     * {@code notDetermined} claimed rows whose cases did not all run ({@code "E-COG (1 of 6 run)"}).
     */
    public record Claims(List<String> claimed, List<String> confirmed, List<String> notRealised,
            List<String> untested, List<String> unknown, List<String> unclaimed, List<String> notDetermined) {
        public Claims {
            claimed = List.copyOf(claimed);
            confirmed = List.copyOf(confirmed);
            notRealised = List.copyOf(notRealised);
            untested = List.copyOf(untested);
            unknown = List.copyOf(unknown);
            unclaimed = List.copyOf(unclaimed);
            notDetermined = notDetermined == null ? List.of() : List.copyOf(notDetermined);
        }

        public Claims(List<String> claimed, List<String> confirmed, List<String> notRealised, List<String> untested,
                List<String> unknown, List<String> unclaimed) {
            this(claimed, confirmed, notRealised, untested, unknown, unclaimed, List.of());
        }
    }
}
