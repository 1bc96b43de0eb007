package org.fclcert.maven;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fclcert.harness.CaseStatus;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;

/**
 * The decision behind {@code fclcert:verify}: does a certification report meet the project's bar?
 * Kept apart from the mojo so that it is tested without a Maven runtime.
 */
final class ReportGate {
    enum FailOn {
        NONE, BASIC, CLAIMED, ANY;

        static FailOn byWord(String word) {
            return valueOf(word.trim().toUpperCase(Locale.ROOT));
        }
    }

    private ReportGate() {
    }

    /**
     * Why the report does not meet {@code failOn}, or empty when it does.
     *
     * @param claims feature ids the project claims; when empty, the claims the implementation made itself
     */
    static Optional<String> failure(Report report, FailOn failOn, List<String> claims) {
        if (reproduction(report) && failOn != FailOn.NONE) {
            // -Dfclcert.cases=ID reruns a few cases: no level verdict can come from them, so the cases themselves
            // decide, and the same command confirms a fix
            List<String> bad = notPassed(report);
            return bad.isEmpty() ? Optional.empty() : Optional.of(bad.size() + " of the " + report.cases().size()
                    + " case(s) selected by fclcert.cases did not pass: " + String.join(", ", bad));
        }
        List<String> problems = new ArrayList<>();
        if (failOn != FailOn.NONE && failOn != FailOn.ANY && !report.basicLevel().conformant()) {
            // the reason names the cases (the first ten): listing them again would print the list twice
            problems.add("Basic Level " + report.basicLevel().sentence() + table8Rows(report));
        }
        if (failOn == FailOn.CLAIMED) {
            List<String> claimed = claims.isEmpty() ? report.iut().claims() : claims;
            for (String id : claimed) {
                problems.addAll(claimProblem(report, id.trim().toUpperCase(Locale.ROOT)));
            }
        }
        if (failOn == FailOn.ANY) {
            List<String> bad = notPassed(report);
            if (!bad.isEmpty()) {
                problems.add(bad.size() + " case(s) did not pass: " + String.join(", ", bad));
            }
        }
        return problems.isEmpty() ? Optional.empty() : Optional.of(String.join("\n", problems));
    }

    /** True when the run was narrowed to named cases ({@code fclcert.cases}): reproducing, not certifying. */
    static boolean reproduction(Report report) {
        return !report.run().selection().cases().isEmpty();
    }

    private static List<String> notPassed(Report report) {
        return report.cases().stream().filter(c -> c.status() == CaseStatus.FAILED || c.status() == CaseStatus.ERRORED)
                .map(c -> c.id() + " " + c.status().name().toLowerCase(Locale.ROOT)).toList();
    }

    private static List<String> claimProblem(Report report, String id) {
        Optional<Report.FeatureRow> row = report.features().stream().filter(f -> f.id().equals(id)).findFirst();
        if (row.isEmpty()) {
            return List.of("claimed " + id + " is not a feature id of Tables 8 to 10");
        }
        Report.FeatureRow f = row.get();
        if (f.status() == FeatureStatus.REALISED) {
            return List.of();
        }
        String cases = f.notPassed().isEmpty() ? "" : "; cases not passed: " + String.join(", ", f.notPassed());
        return List.of("claimed " + id + " (Table " + f.table() + ", " + f.description() + ") is "
                + f.status().label() + cases);
    }

    /** The Table 8 rows that are not realised, named, so that a Basic Level failure says which rows keep it out. */
    private static String table8Rows(Report report) {
        List<String> rows = report.features().stream()
                .filter(f -> f.table() == 8 && f.status() != FeatureStatus.REALISED && f.status() != FeatureStatus.NOT_TESTED)
                .map(f -> f.id() + " (" + f.description() + ": " + f.sentence() + ")").toList();
        return rows.isEmpty() ? "" : "; Table 8 rows not realised: " + String.join(", ", rows);
    }
}
