package org.fclcert.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;

/**
 * What the verdicts of one report must never say against each other (issue 29): the Basic verdict against the
 * Basic cases and the Table 8 rows, each row against its own cases, the claims against the rows, the counts against
 * the cases. Each violation is a sentence naming what contradicts what.
 */
public final class VerdictInvariants {
    private VerdictInvariants() {
    }

    public static List<String> violations(Report r) {
        List<String> v = new ArrayList<>();
        Map<String, CaseResult> byId = r.cases().stream().collect(Collectors.toMap(CaseResult::id, Function.identity()));
        List<CaseResult> basic = r.cases().stream().filter(c -> "basic".equals(c.level()) && !c.interpretation()).toList();
        long basicFailed = basic.stream().filter(c -> c.status() == CaseStatus.FAILED || c.status() == CaseStatus.ERRORED)
                .count();
        long basicRun = basic.stream().filter(c -> c.status() != CaseStatus.SKIPPED).count();
        Report.BasicLevel b = r.basicLevel();
        List<Report.FeatureRow> table8 = r.features().stream().filter(f -> f.table() == 8).toList();
        switch (b.verdict()) {
            case Report.BasicLevel.CONFORMANT -> {
                if (basicFailed > 0 || basicRun < b.required()) {
                    v.add("Basic conformant, but " + basicFailed + " Basic cases failed and " + basicRun + " of "
                            + b.required() + " ran");
                }
                table8.stream().filter(f -> f.status() != FeatureStatus.REALISED && f.status() != FeatureStatus.NOT_TESTED)
                        .forEach(f -> v.add("Basic conformant beside Table 8 row " + f.id() + ": " + f.sentence()));
            }
            case Report.BasicLevel.NOT_CONFORMANT -> {
                if (basicFailed == 0) {
                    v.add("Basic not conformant, but no Basic case that ran failed");
                }
                boolean explained = table8.stream().anyMatch(f -> f.status() == FeatureStatus.PARTIAL
                        || f.status() == FeatureStatus.NOT_REALISED || f.status() == FeatureStatus.NOT_DETERMINED)
                        || basic.stream().anyMatch(c -> c.tests().isEmpty() && c.status() != CaseStatus.PASSED
                                && c.status() != CaseStatus.SKIPPED);
                if (!explained) {
                    v.add("Basic not conformant, but every Table 8 row is realised and no negative case failed");
                }
            }
            case Report.BasicLevel.NOT_DETERMINED -> {
                if (basicFailed > 0 || basicRun >= b.required() && b.required() > 0) {
                    v.add("Basic not determined, but " + basicFailed + " failed and " + basicRun + " of " + b.required()
                            + " ran");
                }
            }
            default -> v.add("unknown Basic verdict " + b.verdict());
        }
        if (b.conformant() != Report.BasicLevel.CONFORMANT.equals(b.verdict())) {
            v.add("basicLevel.conformant " + b.conformant() + " beside verdict " + b.verdict());
        }
        for (Report.FeatureRow f : r.features()) {
            int counted = f.passed() + f.failed() + f.errored();
            for (String id : f.notPassed()) {
                CaseResult c = byId.get(id);
                if (c == null || !f.cases().contains(id) || c.status() == CaseStatus.PASSED || c.status() == CaseStatus.SKIPPED) {
                    v.add(f.id() + " names " + id + " as not passed, which is not a failure of its evidence");
                } else if (!Attribution.rows(c).contains(f.id())) {
                    v.add(f.id() + " counts " + id + ", whose failure is attributed to " + Attribution.rows(c));
                } else if (!"basic".equals(c.level()) && f.table() == 8) {
                    v.add("Table 8 row " + f.id() + " counts " + c.level() + " case " + id);
                }
            }
            boolean decided = f.required() >= 0 && f.run() >= f.required();
            switch (f.status()) {
                case REALISED -> {
                    if (!f.notPassed().isEmpty() || f.passed() == 0 || !decided) {
                        v.add(f.id() + " realised: " + f.sentence());
                    }
                }
                case PARTIAL -> {
                    if (f.passed() == 0 || f.notPassed().isEmpty() || !decided) {
                        v.add(f.id() + " partial: " + f.sentence());
                    }
                }
                case NOT_REALISED -> {
                    if (f.passed() > 0 || f.notPassed().isEmpty() || !decided) {
                        v.add(f.id() + " not realised: " + f.sentence());
                    }
                }
                case NOT_DETERMINED -> {
                    if (decided && counted > 0) {
                        v.add(f.id() + " not determined though decided: " + f.sentence());
                    }
                }
                case NOT_TESTED -> {
                    if (counted > 0) {
                        v.add(f.id() + " not tested though " + counted + " cases count: " + f.sentence());
                    }
                }
            }
        }
        Map<String, Report.FeatureRow> rows = r.features().stream()
                .collect(Collectors.toMap(Report.FeatureRow::id, Function.identity()));
        for (String claim : r.claims().claimed()) {
            Report.FeatureRow f = rows.get(claim.toUpperCase(Locale.ROOT));
            if (f == null) {
                continue;
            }
            boolean listedNot = r.claims().notRealised().stream().anyMatch(s -> s.startsWith(f.id() + " "));
            boolean shouldBe = f.status() == FeatureStatus.PARTIAL || f.status() == FeatureStatus.NOT_REALISED;
            if (listedNot != shouldBe) {
                v.add("claim " + f.id() + (listedNot ? " listed" : " not listed") + " as not realised beside its row: "
                        + f.sentence());
            }
            if (r.claims().confirmed().contains(f.id()) != (f.status() == FeatureStatus.REALISED)) {
                v.add("claim " + f.id() + " confirmed beside its row: " + f.sentence());
            }
            if (f.table() == 8 && shouldBe && b.conformant()) {
                v.add("Basic conformant, but claimed Table 8 row " + f.id() + " is " + f.sentence());
            }
        }
        Tally t = Tally.of(r);
        if (t.passed() + t.failures() + t.errors() + t.unclaimed() + t.notRun() != r.cases().size()) {
            v.add("the tally " + t.sentence() + " does not add up to " + r.cases().size());
        }
        JunitReport.Counts j = JunitReport.counts(r);
        if (r.semantic() == null && (j.failures() != t.failures() || j.errors() != t.errors()
                || j.skipped() != t.unclaimed() + t.notRun())) {
            v.add("junit.xml counts " + j.surefireLine() + " beside " + t.sentence());
        }
        return v;
    }
}
