package org.fclcert.report;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Predicate;
import org.fclcert.harness.CaseResult;
import org.fclcert.probe.DataCheckEntry;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.RejectionPlace;
import org.fclcert.harness.Flags;
import org.fclcert.harness.PlannedCase;
import org.fclcert.harness.PresentedStatus;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.RunHeader;
import org.fclcert.harness.Runner;
import org.fclcert.model.Feature;

/** Builds the verdicts of clause 6.1 from case results (complete or not). */
public final class ReportBuilder {
    private ReportBuilder() {
    }

    public static Report build(ResultsFile file, Instant generatedAt) {
        return build(file.header(), file.results(), file.problems(), file.dataCheckList(), generatedAt);
    }

    public static Report build(RunHeader header, List<CaseResult> results, List<String> problems,
            List<DataCheckEntry> dataCheckList, Instant generatedAt) {
        List<CaseResult> cases = complete(header, results);
        boolean complete = cases.stream().noneMatch(c -> c.status() == CaseStatus.SKIPPED && isUnrun(c));
        List<CaseResult> counted = cases.stream().filter(c -> !c.interpretation()).toList();
        boolean semantic = header.presentAs() != null;
        List<Report.FeatureRow> features = featureRows(header, counted, semantic);
        return new Report(Report.FORMAT_VERSION, generatedAt.toString(), header.iut(), header.toolkit(),
                header.corpus(), new Report.Run(header.startedAt(), complete, header.selection(), problems),
                summary(cases), rejections(cases), basicLevel(header, counted), features, dataCheckList, interpretation(cases),
                claims(header.iut().claims(), features), Causes.of(cases), cases,
                semantic ? semantic(header.presentAs(), cases) : null);
    }

    static final String NOT_RUN = "not run: the run ended before this case";

    private static boolean isUnrun(CaseResult c) {
        return NOT_RUN.equals(c.message()) || c.message() != null && c.message().startsWith(Runner.STOPPED);
    }

    /** Planned order, the last result per id, and a skipped entry for every planned case with no result. */
    private static List<CaseResult> complete(RunHeader header, List<CaseResult> results) {
        Map<String, CaseResult> byId = new LinkedHashMap<>();
        results.forEach(r -> byId.put(r.id(), r));
        List<CaseResult> ordered = new ArrayList<>();
        Set<String> placed = new java.util.HashSet<>();
        for (PlannedCase p : header.selection().planned()) {
            if (!placed.add(p.id())) {
                continue;   // a damaged or forged header that plans a case twice: each case is reported once
            }
            CaseResult r = byId.remove(p.id());
            ordered.add(r != null ? r : CaseResult.skipped(p, NOT_RUN));
        }
        ordered.addAll(byId.values());
        return ordered;
    }

    private static Report.Summary summary(List<CaseResult> cases) {
        return new Report.Summary(cases.size(), count(cases, CaseStatus.PASSED), count(cases, CaseStatus.FAILED),
                count(cases, CaseStatus.ERRORED), count(cases, CaseStatus.SKIPPED),
                cases.stream().mapToInt(c -> orZero(c.setup().crashes())).sum(),
                cases.stream().mapToInt(c -> orZero(c.setup().restarts())).sum());
    }

    private static int orZero(Integer count) {
        return count == null ? 0 : Math.max(0, count);
    }

    private static Report.Rejections rejections(List<CaseResult> cases) {
        int at = 0;
        int other = 0;
        int unlocated = 0;
        for (CaseResult c : cases) {
            RejectionPlace place = c.verdict().rejection();
            if (place == null) {
                continue;
            }
            switch (place) {
                case AT_ERROR_LINE -> at++;
                case OTHER_LINE -> other++;
                case UNLOCATED -> unlocated++;
            }
        }
        return new Report.Rejections(at + other + unlocated, at, other, unlocated);
    }

    private static int count(List<CaseResult> cases, CaseStatus status) {
        return (int) cases.stream().filter(c -> c.status() == status).count();
    }

    private static Report.BasicLevel basicLevel(RunHeader header, List<CaseResult> counted) {
        List<CaseResult> basic = counted.stream().filter(c -> "basic".equals(c.level())).toList();
        List<CaseResult> ran = basic.stream().filter(c -> c.status() != CaseStatus.SKIPPED).toList();
        int required = header.corpus().basicCases();
        int passed = count(basic, CaseStatus.PASSED);
        List<String> failed = ran.stream().filter(c -> c.status() != CaseStatus.PASSED).map(CaseResult::id).toList();
        String reason;
        String verdict;
        if (required == 0) {
            reason = "the corpus has no Basic Level case";
            verdict = Report.BasicLevel.NOT_DETERMINED;
        } else if (!failed.isEmpty()) {
            // a Basic case that ran and did not pass decides the verdict, whatever did not run
            reason = failed.size() + " of " + ran.size() + " Basic Level cases run did not pass: " + list(failed)
                    + (ran.size() < required ? "; " + ran.size() + " of " + required + " run" : "");
            verdict = Report.BasicLevel.NOT_CONFORMANT;
        } else if (ran.size() < required) {
            reason = ran.size() + " of " + required + " run";
            verdict = Report.BasicLevel.NOT_DETERMINED;
        } else {
            reason = "all " + required + " Basic Level cases passed";
            verdict = Report.BasicLevel.CONFORMANT;
        }
        boolean conformant = Report.BasicLevel.CONFORMANT.equals(verdict);
        return new Report.BasicLevel(conformant, required, ran.size(), passed, reason, verdict);
    }

    /** At most ten ids, then how many more: a reason stays one readable line. */
    private static String list(List<String> ids) {
        return org.fclcert.model.Names.listed(ids, 10);
    }

    /** The positive cases' semantic results; a positive case without one (a run cut short) counts as skipped. */
    private static Report.SemanticAxis semantic(String presentAs, List<CaseResult> cases) {
        List<PresentedStatus> s = cases.stream().filter(c -> !c.interpretation()).filter(ReportBuilder::positive)
                .map(ReportBuilder::presentedStatus).toList();
        return new Report.SemanticAxis(presentAs, s.size(), count(s, PresentedStatus.PASSED),
                count(s, PresentedStatus.FAILED), count(s, PresentedStatus.ERRORED), count(s, PresentedStatus.SKIPPED),
                count(s, PresentedStatus.NOT_PRESENTABLE));
    }

    /**
     * A case of the semantic axis: in a presented run every positive case carries its semantic result (skipped
     * when it never ran after the implementation was given up); a case the run never reached is left out.
     */
    private static boolean positive(CaseResult c) {
        return c.presentedResult().isPresent();
    }

    private static PresentedStatus presentedStatus(CaseResult c) {
        return c.presentedResult().map(CaseResult.Presented::status).orElse(PresentedStatus.SKIPPED);
    }

    private static int count(List<PresentedStatus> statuses, PresentedStatus status) {
        return (int) statuses.stream().filter(s -> s == status).count();
    }

    /** The semantic verdict of a row; {@code incomplete}: not all the cases the row needs ran, so not determined. */
    private static Report.Semantic semanticRow(List<CaseResult> evidence, boolean incomplete) {
        List<CaseResult> positive = evidence.stream().filter(ReportBuilder::positive).toList();
        int notPresentable = (int) positive.stream()
                .filter(c -> presentedStatus(c) == PresentedStatus.NOT_PRESENTABLE).count();
        List<CaseResult> presented = positive.stream()
                .filter(c -> presentedStatus(c) != PresentedStatus.NOT_PRESENTABLE).toList();
        int passed = (int) presented.stream().filter(c -> presentedStatus(c) == PresentedStatus.PASSED).count();
        FeatureStatus status = FeatureStatus.of(passed, presented.size());
        if (incomplete && status != FeatureStatus.NOT_TESTED) {
            status = FeatureStatus.NOT_DETERMINED;
        }
        return new Report.Semantic(status, passed, presented.size(),
                notPresentable, presented.stream().filter(c -> presentedStatus(c) != PresentedStatus.PASSED)
                        .map(CaseResult::id).toList());
    }

    /**
     * One row per catalogue feature. Its evidence is every case whose {@code tests} name it; a case that did not
     * pass counts against it only when {@link Attribution} attributes the failure to it (else it is listed as not
     * counted); the row is decided only when every case of its level or below that the corpus has for it ran
     * ({@code corpus.rowCases}), else it is not determined.
     */
    private static List<Report.FeatureRow> featureRows(RunHeader header, List<CaseResult> counted, boolean semantic) {
        List<Report.FeatureRow> rows = new ArrayList<>();
        for (Feature f : Feature.values()) {
            List<CaseResult> evidence = counted.stream().filter(testing(f)).toList();
            if (f.dialectSyntax() && evidence.isEmpty() && !header.corpus().rowCases().containsKey(f.id())) {
                // a dialect's own syntax (Feature#dialectSyntax): a row only where the corpus has a case written in a
                // dialect for it (conformance/README.md, "Open Level methods and dialects")
                continue;
            }
            List<CaseResult> deciding = evidence.stream().filter(c -> Attribution.decides(c.level(), f)).toList();
            int run = (int) deciding.stream().filter(c -> c.status() != CaseStatus.SKIPPED).count();
            int required = rowCases(header, f, deciding.size());
            int passed = count(evidence, CaseStatus.PASSED);
            List<CaseResult> against = evidence.stream().filter(c -> Attribution.rows(c).contains(f.id())).toList();
            List<String> notCounted = evidence.stream()
                    .filter(c -> c.status() == CaseStatus.FAILED || c.status() == CaseStatus.ERRORED)
                    .filter(c -> !against.contains(c))
                    .map(c -> c.id() + " (" + Attribution.notCountedBecause(c, f) + ")").toList();
            FeatureStatus status;
            if (required < 0 || run < required) {
                status = run == 0 && passed == 0 ? FeatureStatus.NOT_TESTED : FeatureStatus.NOT_DETERMINED;
            } else if (passed + against.size() == 0) {
                status = notCounted.isEmpty() ? FeatureStatus.NOT_TESTED : FeatureStatus.NOT_DETERMINED;
            } else {
                status = FeatureStatus.of(passed, passed + against.size());
            }
            rows.add(new Report.FeatureRow(f.id(), f.table(), f.level().word(), f.element(), f.description(),
                    status, passed, count(against, CaseStatus.FAILED), count(against, CaseStatus.ERRORED),
                    count(evidence, CaseStatus.SKIPPED), evidence.stream().map(CaseResult::id).toList(),
                    against.stream().map(CaseResult::id).toList(),
                    semantic ? semanticRow(evidence, required < 0 || run < required) : null,
                    required, run, notCounted));
        }
        return rows;
    }

    /**
     * How many cases the row's verdict needs: the corpus's count from the run header; for a header without it, the
     * planned cases when nothing narrowed the run, else -1: unknown, so never decided.
     */
    private static int rowCases(RunHeader header, Feature f, int planned) {
        Integer known = header.corpus().rowCases().get(f.id());
        if (known != null) {
            return Math.max(known, planned);
        }
        if (!header.corpus().rowCases().isEmpty() || header.selection().whole()) {
            return planned;
        }
        return -1;
    }

    private static Predicate<CaseResult> testing(Feature f) {
        return c -> c.tests().stream().anyMatch(t -> t.equalsIgnoreCase(f.id()));
    }

    private static List<Report.InterpretationEntry> interpretation(List<CaseResult> cases) {
        return cases.stream().filter(CaseResult::interpretation)
                .map(c -> new Report.InterpretationEntry(c.id(), c.title(), interpretationFlag(c), c.status().word(),
                        c.message(), Causes.rejectionCause(c).orElse(null)))
                .toList();
    }

    private static String interpretationFlag(CaseResult c) {
        return Flags.interpretation(c.flags()).orElse("interpretation");
    }

    private static Report.Claims claims(List<String> claimed, List<Report.FeatureRow> rows) {
        Map<String, Report.FeatureRow> byId = new LinkedHashMap<>();
        rows.forEach(r -> byId.put(r.id(), r));
        List<String> confirmed = new ArrayList<>();
        List<String> notRealised = new ArrayList<>();
        List<String> untested = new ArrayList<>();
        List<String> unknown = new ArrayList<>();
        List<String> notDetermined = new ArrayList<>();
        Set<String> claimedIds = new TreeSet<>(String.CASE_INSENSITIVE_ORDER);
        for (String id : claimed) {
            Report.FeatureRow row = byId.get(id.toUpperCase(Locale.ROOT));
            claimedIds.add(id);
            if (row == null) {
                unknown.add(id);
            } else if (row.status() == FeatureStatus.REALISED) {
                confirmed.add(row.id());
            } else if (row.status() == FeatureStatus.NOT_TESTED) {
                untested.add(row.id());
            } else if (row.status() == FeatureStatus.NOT_DETERMINED) {
                notDetermined.add(row.id() + (row.required() < 0 ? " (" + row.run() + " run)"
                        : row.run() < row.required() ? " (" + row.run() + " of " + row.required() + " run)"
                        : " (its failures count against other rows)"));
            } else {
                notRealised.add(row.id() + " (" + row.status().label() + ")");
            }
        }
        List<String> unclaimed = rows.stream()
                .filter(r -> r.table() != 8 && r.status() == FeatureStatus.REALISED && !claimedIds.contains(r.id()))
                .map(Report.FeatureRow::id).toList();
        return new Report.Claims(claimed, confirmed, notRealised, untested, unknown, unclaimed, notDetermined);
    }
}
