package org.fclcert.report;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ReferenceTrace;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;

/**
 * Which feature rows a case that did not pass counts against: the one place that decides it, read by the
 * feature rows ({@link ReportBuilder}) and by the causes of wrong values ({@link Causes}), so that the rows, the
 * Basic verdict and the causes cannot tell different stories.
 *
 * <p>A failure is attributed to the rows its {@code tests} name, narrowed by two pieces of evidence:
 * <ol>
 * <li><b>Level.</b> Only rows of the case's own level or above: an Extension case that also tests a Table 8 row
 * (E-RANGE-004 tests B-DEFAULT-VALUE) needs its Extension features to run at all, so its failure never counts
 * against the Basic row — the Basic verdict, which needs exactly the Basic cases, then always agrees with Table 8.</li>
 * <li><b>The failing step.</b> A wrong value at a step where the reference evaluator's outcome for every wrong
 * output was the DEFAULT value (or NC) isolates B-DEFAULT-VALUE (or B-DEFAULT-NC) when the case tests it; a wrong
 * defuzzified value isolates the case's other tested rows.</li>
 * </ol>
 * A failure left with no row counts against none; the rows it tests list it as not counted, with the reason.
 */
final class Attribution {
    static final String DEFAULT_VALUE = "B-DEFAULT-VALUE";
    static final String DEFAULT_NC = "B-DEFAULT-NC";

    private Attribution() {
    }

    /** The rows (catalogue ids, in the case's order) a failed or errored case counts against; empty for others. */
    static List<String> rows(CaseResult c) {
        if (c.status() != CaseStatus.FAILED && c.status() != CaseStatus.ERRORED) {
            return List.of();
        }
        ConformanceLevel level = level(c);
        List<String> candidates = new ArrayList<>();
        for (String t : c.tests()) {
            Feature.byId(t.toUpperCase(Locale.ROOT)).filter(f -> level == null || f.level().compareTo(level) >= 0)
                    .ifPresent(f -> candidates.add(f.id()));
        }
        return isolated(c, candidates);
    }

    /** Whether a case of this level can decide a row of that level (rows are decided by cases at or below it). */
    static boolean decides(String caseLevel, Feature row) {
        ConformanceLevel level = level(caseLevel);
        return level == null || level.compareTo(row.level()) <= 0;
    }

    /** Why a failure of {@code c}, which tests {@code row}, does not count against it. */
    static String notCountedBecause(CaseResult c, Feature row) {
        List<String> rows = rows(c);
        if (!decides(c.level(), row)) {
            return "a case of the " + c.level() + " level: it needs more than " + row.level().word()
                    + " level features to run";
        }
        return rows.isEmpty() ? "its failing step isolates no row it tests"
                : "its failing step isolates " + String.join(", ", rows);
    }

    private static List<String> isolated(CaseResult c, List<String> candidates) {
        Optional<Set<String>> outcomes = wrongOutcomes(c);
        if (outcomes.isEmpty() || candidates.size() < 2) {
            return List.copyOf(candidates);
        }
        Set<String> o = outcomes.get();
        if (o.equals(Set.of("default")) && candidates.contains(DEFAULT_VALUE)) {
            return List.of(DEFAULT_VALUE);
        }
        if (o.equals(Set.of("no change")) && candidates.contains(DEFAULT_NC)) {
            return List.of(DEFAULT_NC);
        }
        if (o.equals(Set.of("defuzzified"))) {
            List<String> rest = candidates.stream().filter(r -> !r.equals(DEFAULT_VALUE) && !r.equals(DEFAULT_NC))
                    .toList();
            if (!rest.isEmpty()) {
                return rest;
            }
        }
        return List.copyOf(candidates);
    }

    /** How the reference evaluator got each output the implementation got wrong at the failing step, if known. */
    private static Optional<Set<String>> wrongOutcomes(CaseResult c) {
        ReferenceTrace trace = c.evidence().reference();
        if (trace == null || !(c.mismatch().orElse(null) instanceof CaseResult.Mismatch.Outputs m)) {
            return Optional.empty();
        }
        Set<String> outcomes = new LinkedHashSet<>();
        for (Map.Entry<String, Double> e : m.expected().entrySet()) {
            Double got = m.actual().get(e.getKey());
            if (got != null && got.equals(e.getValue())) {
                continue;
            }
            ReferenceTrace.OutputValue o = trace.output(e.getKey());
            if (o == null) {
                return Optional.empty();
            }
            outcomes.add(o.outcome());
        }
        return outcomes.isEmpty() ? Optional.empty() : Optional.of(outcomes);
    }

    private static ConformanceLevel level(CaseResult c) {
        return level(c.level());
    }

    private static ConformanceLevel level(String word) {
        try {
            return word == null ? null : ConformanceLevel.byWord(word);
        } catch (IllegalArgumentException e) {
            return null;
        }
    }
}
