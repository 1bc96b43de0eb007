package org.fclcert.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.harness.PresentedStatus;
import org.fclcert.harness.ReferenceTrace;

/**
 * {@code report.md}: the compliance statement in the shape clause 6.1 asks for — the Basic Level verdict
 * with Table 8 row by row, the Standard Extensions realised (Table 9), the Open Level features (Table 10) —
 * then the evidence: claims, interpretation-dependent cases, export, data check list, and the failures
 * grouped by feature with a command that reproduces each.
 */
public final class MarkdownReport {
    private final Report r;
    private final StringBuilder out = new StringBuilder();

    private MarkdownReport(Report report) {
        this.r = report;
    }

    public static String render(Report report) {
        return new MarkdownReport(report).all();
    }

    private String all() {
        header();
        table8();
        table9();
        table10();
        claims();
        interpretation();
        export();
        dataCheckList();
        causes();
        failures();
        semanticFailures();
        notes();
        return out.toString();
    }

    private void line(String s) {
        out.append(s).append('\n');
    }

    private void header() {
        line("# FCL compliance statement: " + Texts.cell(r.iut().name()) + " " + Texts.cell(r.iut().version()));
        line("");
        line("IEC 61131-7 (clause 6.1), measured by fclcert " + Texts.cell(r.toolkit().version()) + " on the run of "
                + Texts.cell(r.run().startedAt()) + ".");
        line("");
        if (r.origin() != null) {
            r.origin().warnings().forEach(w -> line("**" + Texts.cell(w) + "**\n"));
        }
        line("- Implementation: " + Texts.implementation(r, Texts::cell));
        line("- Isolation: " + Texts.cell(Texts.isolation(r)));
        java.util.List<String> unseen = org.fclcert.iut.Iuts.unobservable(r.iut().spec());
        if (!unseen.isEmpty()) {
            line("- What the adapter cannot observe: " + String.join("; ", unseen));
        }
        line("- Corpus: `" + code(r.corpus().dir()) + "`, " + r.corpus().cases() + " cases, sha256 `"
                + code(r.corpus().sha256()) + "`");
        Report.Summary s = r.summary();
        line("- Cases run: " + s.cases() + ": " + s.passed() + " passed, " + s.failed() + " failed, " + s.errored()
                + " errored, " + s.skipped() + " skipped");
        line("- Counted as in junit.xml and the Maven log: " + Tally.of(r).sentence());
        if (r.rejections().rejected() > 0) {
            line("- Negative cases: " + r.rejections().sentence()
                    + (r.rejections().doubtful() ? " (" + Report.REJECTION_CAVEAT + ")" : ""));
        }
        if (!r.run().selection().whole()) {
            line("- Selection: " + Texts.cell(selection()) + " (a partial run: a verdict whose cases did not all run is not determined)");
        }
        if (!r.run().complete()) {
            line("- **Incomplete run**: some selected cases were not run; they are reported as skipped.");
        }
        r.run().problems().forEach(p -> line("- Results file problem: " + Texts.cell(p)));
        line("");
        Report.BasicLevel b = r.basicLevel();
        line("**Basic Level: " + (Report.BasicLevel.NOT_CONFORMANT.equals(b.verdict()) ? "NOT conformant" : b.verdict())
                + "** (" + Texts.cell(b.reason()) + ").");
        line("");
        if (r.origin() != null) {
            line("Provenance:");
            line("");
            r.origin().lines().forEach(l -> line("- " + Texts.cell(l.strip())));
            line("");
        }
        if (r.semantic() != null) {
            line("Two verdicts per feature row: **" + Report.LANGUAGE_AXIS + "**; **" + Report.SEMANTIC_AXIS + "**.");
            line("");
            line("- " + r.semantic().sentence());
            line("");
        }
    }

    /**
     * Text inside a code span: a results file read back (report --from) may hold anything where a path or digest
     * stands, and a backtick or line break would end the span.
     */
    private static String code(String s) {
        return s == null ? "" : s.replaceAll("[`\\p{Cntrl}]", "?");
    }

    private String selection() {
        List<String> parts = new ArrayList<>();
        if (!r.run().selection().levels().isEmpty()) {
            parts.add("--level " + String.join(",", r.run().selection().levels()));
        }
        if (!r.run().selection().features().isEmpty()) {
            parts.add("--feature " + String.join(" ", r.run().selection().features()));
        }
        if (!r.run().selection().cases().isEmpty()) {
            parts.add("--case " + String.join(" ", r.run().selection().cases()));
        }
        return String.join(" ", parts);
    }

    private void table8() {
        line("## Table 8: Basic Level language elements (mandatory)");
        line("");
        featureTable(8);
    }

    private void table9() {
        line("## Table 9: Standard Extensions realised");
        line("");
        realisedList(9, "No Standard Extension is realised.");
        line("All Table 9 rows:");
        line("");
        featureTable(9);
    }

    private void table10() {
        line("## Table 10: Open Level features realised");
        line("");
        realisedList(10, "No Open Level feature is realised.");
        line("All Table 10 rows fclcert can recognise:");
        line("");
        featureTable(10);
    }

    private void realisedList(int table, String none) {
        List<String> realised = rows(table).stream().filter(f -> f.status() == FeatureStatus.REALISED)
                .map(f -> f.id() + " (" + f.description() + ")").toList();
        line(realised.isEmpty() ? none : "Realised:");
        line("");
        realised.forEach(x -> line("- " + x));
        if (!realised.isEmpty()) {
            line("");
        }
    }

    private List<Report.FeatureRow> rows(int table) {
        return r.features().stream().filter(f -> f.table() == table).toList();
    }

    private void featureTable(int table) {
        List<Report.FeatureRow> folded = rows(table).stream().filter(f -> Texts.folded(r, f)).toList();
        List<Report.FeatureRow> shown = rows(table).stream().filter(f -> !folded.contains(f)).toList();
        if (!shown.isEmpty()) {
            if (r.semantic() != null) {
                semanticFeatureTable(shown);
            } else {
                languageFeatureTable(shown);
            }
        }
        if (!folded.isEmpty()) {
            line("Not tested in this run (partial selection): " + folded.stream().map(Report.FeatureRow::id)
                    .collect(java.util.stream.Collectors.joining(", ")) + ".");
            line("");
        }
    }

    private void languageFeatureTable(List<Report.FeatureRow> rows) {
        line("| Language element | Feature | Verdict | Passed | Not passed |");
        line("| --- | --- | --- | --- | --- |");
        for (Report.FeatureRow f : rows) {
            line("| " + Texts.cell(f.element()) + " | " + f.id() + ": " + Texts.cell(f.description()) + " | "
                    + verdict(f.status()) + Texts.runOfRequired(f) + " | " + Texts.passedOfCounted(f) + " | "
                    + Texts.cell(Texts.notPassedText(f)) + " |");
        }
        line("");
    }

    private static String verdict(FeatureStatus status) {
        return status == FeatureStatus.REALISED || status == FeatureStatus.NOT_TESTED
                || status == FeatureStatus.NOT_DETERMINED ? status.label()
                : "**" + status.label() + "**";
    }

    /** Both axes side by side: the language verdict (the standard's text) and the semantic one (the layout). */
    private void semanticFeatureTable(List<Report.FeatureRow> rows) {
        String layout = r.semantic().presentAs();
        line("| Language element | Feature | Language verdict | Passed | Not passed | Semantic verdict (" + layout
                + " layout) | Passed | Not passed | Not presentable |");
        line("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
        for (Report.FeatureRow f : rows) {
            Report.Semantic sem = f.semantic();
            line("| " + Texts.cell(f.element()) + " | " + f.id() + ": " + Texts.cell(f.description()) + " | "
                    + verdict(f.status()) + Texts.runOfRequired(f) + " | " + Texts.passedOfCounted(f) + " | "
                    + Texts.cell(Texts.notPassedText(f)) + " | "
                    + (sem == null ? "" : verdict(sem.status()) + " | " + sem.passed() + "/" + sem.total() + " | "
                            + String.join(", ", sem.notPassed()) + " | " + sem.notPresentable())
                    + " |");
        }
        line("");
    }

    /** The semantic failures: each case's value in the layout against the standard's. */
    private void semanticFailures() {
        if (r.semantic() == null) {
            return;
        }
        line("## Semantic axis: what it computes otherwise (" + r.semantic().presentAs() + " layout)");
        line("");
        List<CaseResult> wrong = r.cases().stream().filter(c -> c.presentedResult().map(p -> p.status()
                == PresentedStatus.FAILED || p.status() == PresentedStatus.ERRORED).orElse(false)).toList();
        if (wrong.isEmpty()) {
            line("Every presented case gave the standard's results.");
        }
        for (CaseResult c : wrong) {
            CaseResult.Presented p = c.presented();
            StringBuilder b = new StringBuilder("- **" + c.id() + "** (" + p.status().word() + "): "
                    + Texts.cell(p.message()));
            java.util.Optional.ofNullable(p.evidence().mismatch()).ifPresentOrElse(m -> b.append(" — expected ").append(Texts.cell(Texts.describe(
                    m.expected()))).append(", got ").append(Texts.cell(Texts.describe(m.actual()))), () -> { });
            line(b.toString());
            if (p.evidence().reference() != null) {
                line("  - fclcert's reference evaluator at step " + p.evidence().reference().step() + ":");
                p.evidence().reference().lines().forEach(l -> line("    - " + Texts.cell(l)));
            }
            p.notes().forEach(n -> line("  - " + Texts.cell(n)));
        }
        line("");
        List<CaseResult> notPresentable = r.cases().stream().filter(c -> c.presentedResult()
                .map(p -> p.status() == PresentedStatus.NOT_PRESENTABLE).orElse(false)).toList();
        if (!notPresentable.isEmpty()) {
            line("### Not presentable in the " + r.semantic().presentAs() + " layout");
            line("");
            notPresentable.forEach(c -> line("- " + c.id() + ": " + Texts.cell(c.presented().message())));
            line("");
        }
    }

    private void claims() {
        Report.Claims c = r.claims();
        line("## Claims");
        line("");
        if (c.claimed().isEmpty()) {
            line("The implementation claims no feature.");
        } else {
            line("- Claimed: " + Texts.cell(String.join(", ", c.claimed())));
            line("- Confirmed: " + none(c.confirmed()));
            line("- **Claimed but not realised**: " + none(c.notRealised()));
            if (!c.notDetermined().isEmpty()) {
                line("- Claimed, not determined: " + String.join(", ", c.notDetermined()));
            }
            if (!c.untested().isEmpty()) {
                line("- Claimed, no case in this run: " + String.join(", ", c.untested()));
            }
            if (!c.unknown().isEmpty()) {
                line("- Unknown feature ids claimed: " + Texts.cell(String.join(", ", c.unknown())));
            }
        }
        if (!c.unclaimed().isEmpty()) {
            line("- Realised but not claimed: " + String.join(", ", c.unclaimed()));
        }
        line("");
    }

    private static String none(List<String> ids) {
        return ids.isEmpty() ? "none" : String.join(", ", ids);
    }

    private void interpretation() {
        line("## Cases that depend on an interpretation of the standard");
        line("");
        if (r.interpretation().isEmpty()) {
            line("None in this run.");
        } else {
            line("Not counted against any verdict (see docs/semantics.md).");
            line("");
            List<Report.InterpretationEntry> telling = r.interpretation().stream().filter(i -> !i.rejectedAtLoad()).toList();
            if (telling.isEmpty()) {
                line("No case reached the point it depends on.");
            } else {
                line("| Case | Point | Status | Message |");
                line("| --- | --- | --- | --- |");
                telling.forEach(i -> line("| " + i.id() + " | " + i.flag() + " | " + i.status() + " | "
                        + Texts.cell(i.message()) + " |"));
            }
            List<String> rejected = r.interpretation().stream().filter(Report.InterpretationEntry::rejectedAtLoad)
                    .map(i -> i.id() + " (" + i.cause() + ")").toList();
            if (!rejected.isEmpty()) {
                line("");
                line("Rejected at load for a reason of the implementation's own dialect, so they say nothing about the"
                        + " point they depend on: " + Texts.cell(String.join(", ", rejected)) + ".");
            }
        }
        line("");
    }

    private void export() {
        line("## FCL export (clause 6 e)");
        line("");
        line(Texts.exportSummary(r.cases()));
        r.cases().stream().filter(c -> c.export().status() == ExportStatus.FAILED)
                .forEach(c -> line("- " + c.id() + ": " + Texts.cell(c.export().message())));
        line("");
    }

    private void dataCheckList() {
        line("## Data check list (Table 11)");
        line("");
        if (r.dataCheckList().isEmpty()) {
            line("Not measured in this run.");
        } else {
            line("| Technical data | Measured | Declared | Note |");
            line("| --- | --- | --- | --- |");
            r.dataCheckList().forEach(d -> line("| " + Texts.cell(d.item()) + " | " + Texts.cell(Texts.measured(d))
                    + " | " + Texts.cell(d.declared()) + " | " + Texts.cell(d.note()) + " |"));
            line("");
            line("How each row is measured: docs/data-check-list.md; the method of each row is in report.json.");
        }
        line("");
    }

    private void causes() {
        line("## Failures by cause");
        line("");
        if (r.causes().isEmpty()) {
            line("No case failed or errored.");
            line("");
            return;
        }
        line("Derived from the implementation's messages, or from the case's feature and the kind of deviation"
                + " (docs/report-format.md, \"Causes\"); interpretation cases are left out.");
        line("");
        line("| Cases | Outcome | Cause | Case ids |");
        line("| --- | --- | --- | --- |");
        r.causes().forEach(c -> line("| " + c.count() + " | " + c.kind() + " | " + Texts.cell(c.cause()) + " | "
                + String.join(", ", c.cases()) + " |"));
        line("");
    }

    private void failures() {
        line("## Failures by feature");
        line("");
        Map<String, List<CaseResult>> groups = new LinkedHashMap<>();
        r.cases().stream().filter(c -> c.status() == CaseStatus.FAILED || c.status() == CaseStatus.ERRORED)
                .forEach(c -> groups.computeIfAbsent(c.tests().isEmpty() ? "(no feature)" : c.tests().get(0),
                        k -> new ArrayList<>()).add(c));
        if (groups.isEmpty()) {
            line("No case failed or errored.");
        }
        groups.forEach((feature, cases) -> {
            line("### " + feature + description(feature));
            line("");
            cases.forEach(this::failure);
            line("");
        });
    }

    /** Observations that do not change a status, e.g. a rejection reported at another line than the error's. */
    private void notes() {
        List<CaseResult> noted = r.cases().stream().filter(c -> !c.verdict().notes().isEmpty()).toList();
        if (noted.isEmpty()) {
            return;
        }
        line("## Notes");
        line("");
        noted.forEach(c -> c.verdict().notes().forEach(n -> line("- " + c.id() + " (" + c.status().word() + "): " + Texts.cell(n))));
        line("");
    }

    private String description(String featureId) {
        return r.features().stream().filter(f -> f.id().equals(featureId)).findFirst()
                .map(f -> ": " + f.description()).orElse("");
    }

    private void failure(CaseResult c) {
        line("- **" + c.id() + "** " + (c.title() == null ? "" : "(" + Texts.cell(c.title()) + ") ")
                + c.status().word() + ": " + Texts.cell(c.message()));
        CaseResult.Step step = c.evidence().step();
        if (step != null && !step.inputs().isEmpty()) {
            line("  - step " + step.number() + ", inputs: " + Texts.cell(Texts.describe(step.inputs())));
        }
        c.mismatch().ifPresent(m -> line("  - expected: " + Texts.cell(Texts.describe(m.expected())) + "; actual: "
                + Texts.cell(Texts.describe(m.actual()))));
        c.expectedRejection().ifPresent(want -> c.programLine(want.line()).ifPresent(text ->
                line("  - line " + want.line() + ", where the error is: `" + text.replace("`", "'") + "`")));
        ReferenceTrace reference = c.evidence().reference();
        if (reference != null) {
            line("  - fclcert's reference evaluator at step " + reference.step() + ":");
            reference.lines().forEach(l -> line("    - " + Texts.cell(l)));
        }
        if (c.tests().size() > 1) {
            line("  - also evidence for: " + String.join(", ", c.tests().subList(1, c.tests().size())));
        }
        String stderr = lastStderrLine(c.evidence().error());
        if (stderr != null) {
            line("  - its last stderr line: `" + stderr.replace("`", "'") + "`");
        }
        line("  - reproduce: `" + code(Texts.repro(r, c.id())) + "` (transcript: `requests/"
                + c.id().replaceAll("[^A-Za-z0-9._-]+", "-") + ".requests.jsonl`)");
    }

    /** The last non-blank line of the stderr tail the harness appends to an implementation's error. */
    private static String lastStderrLine(String error) {
        int marker = error == null ? -1 : error.indexOf("--- stderr");
        if (marker < 0) {
            return null;
        }
        List<String> lines = error.substring(marker).lines().skip(1).filter(l -> !l.isBlank()).toList();
        return lines.isEmpty() ? null : Texts.cell(lines.get(lines.size() - 1).strip());
    }
}
