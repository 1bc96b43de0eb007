package org.fclcert.report;

import java.util.List;
import java.util.Map;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ReferenceTrace;
import org.fclcert.plot.SetPicture;

/**
 * {@code report.html}: one self-contained page (inline style and script, nothing fetched) with the verdict,
 * the three tables in colour, and every case with filters by status and level; cases that did not pass open
 * to show expected against actual, the implementation's error and the program text.
 */
public final class HtmlReport {
    private final Report r;
    private final StringBuilder out = new StringBuilder(64 * 1024);

    private HtmlReport(Report report) {
        this.r = report;
    }

    public static String render(Report report) {
        return new HtmlReport(report).page();
    }

    private static final String STYLE = """
            body{font:15px/1.5 system-ui,-apple-system,'Segoe UI',sans-serif;margin:0;color:#1d2327;background:#f6f7f9}
            main{max-width:1100px;margin:0 auto;padding:24px}
            h1{font-size:1.6em;margin:0 0 4px}h2{margin-top:36px;border-bottom:1px solid #d0d5db;padding-bottom:4px}
            .meta{color:#555;font-size:.9em}.meta code{background:#eceff3;padding:1px 4px;border-radius:3px}
            .verdict{margin:18px 0;padding:14px 18px;border-radius:8px;font-size:1.15em;font-weight:600}
            .verdict.ok{background:#e3f5e6;border:1px solid #7cc68a}.verdict.no{background:#fdeaea;border:1px solid #e39b9b}.verdict.open{background:#eceff3;border:1px solid #b5bcc5}
            .counts span{display:inline-block;margin-right:14px}
            table{border-collapse:collapse;width:100%;background:#fff;margin:8px 0 16px;font-size:.9em}
            th,td{border:1px solid #dde1e6;padding:5px 6px;text-align:left;vertical-align:top}
            th{background:#eef1f5;font-weight:600}
            .st{font-weight:600;border-radius:4px;padding:1px 7px}
            .realised,.passed{background:#dff3e3;color:#185c26}.partial{background:#fff1cc;color:#6d5200}
            .not-realised,.failed{background:#fadddd;color:#8a1c1c}.errored{background:#f3dcf5;color:#6a1b73}
            .not-tested,.not-determined,.skipped,.unsupported,.not-run{background:#eceff3;color:#555}
            .filters{background:#fff;border:1px solid #dde1e6;border-radius:6px;padding:10px 12px;margin:10px 0}
            .filters label{margin-right:14px;white-space:nowrap}
            details{background:#fff;border:1px solid #dde1e6;border-radius:6px;margin:6px 0;padding:6px 10px}
            details[open]{box-shadow:0 1px 4px rgba(0,0,0,.08)}summary{cursor:pointer}
            pre{background:#f3f5f8;padding:8px 10px;overflow:auto;font-size:.85em;border-radius:4px}
            .cmd{font-family:ui-monospace,monospace;font-size:.85em;background:#1d2327;color:#e8eaed;padding:6px 9px;border-radius:4px;display:block;overflow:auto}
            .small{font-size:.85em;color:#555}.hidden{display:none}
            ul.trace{margin:4px 0 8px;font-size:.9em}figure.set{margin:8px 0;overflow:auto}figure.set svg{max-width:100%;height:auto}
            """;

    private static final String SCRIPT = """
            function applyFilters(){
              var st={},lv={};
              document.querySelectorAll('input[data-status]').forEach(function(i){st[i.dataset.status]=i.checked;});
              document.querySelectorAll('input[data-level]').forEach(function(i){lv[i.dataset.level]=i.checked;});
              var q=document.getElementById('q').value.toLowerCase(),shown=0;
              document.querySelectorAll('.case').forEach(function(c){
                var ok=st[c.dataset.status]&&lv[c.dataset.level]&&(q===''||c.dataset.id.toLowerCase().indexOf(q)>=0);
                c.classList.toggle('hidden',!ok);if(ok)shown++;});
              document.getElementById('shown').textContent=shown;
            }
            document.querySelectorAll('.filters input').forEach(function(i){i.addEventListener('input',applyFilters);});
            function openTarget(){
              var t=location.hash&&document.getElementById(location.hash.substring(1));
              if(t&&t.tagName==='DETAILS'){t.open=true;t.classList.remove('hidden');t.scrollIntoView();}
            }
            window.addEventListener('hashchange',openTarget);
            applyFilters();openTarget();
            """;

    private String page() {
        out.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">")
                .append("<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">")
                .append("<title>FCL compliance: ").append(Texts.html(r.iut().name())).append("</title>")
                .append("<style>").append(STYLE).append("</style></head><body><main>\n");
        header();
        causes();   // what is wrong comes first, before the tables a reader scrolls past
        table(8, "Table 8: Basic Level language elements (mandatory)");
        table(9, "Table 9: Extension Level, Standard Extensions");
        table(10, "Table 10: Open Level features");
        dataCheckList();
        claimsAndInterpretation();
        export();
        cases();
        out.append("</main><script>").append(SCRIPT).append("</script></body></html>\n");
        return out.toString();
    }

    private void header() {
        out.append("<h1>FCL compliance statement: ").append(Texts.html(r.iut().name() + " " + r.iut().version()))
                .append("</h1>\n<p class=\"meta\">IEC 61131-7 clause 6.1, measured by fclcert ")
                .append(Texts.html(r.toolkit().version())).append(" on the run of ").append(Texts.html(r.run().startedAt()))
                .append("<br>Implementation: ").append(Texts.html(Texts.implementation(r)).replaceAll("`([^`]*)`", "<code>$1</code>"))
                .append(" · corpus <code>").append(Texts.html(r.corpus().dir())).append("</code>, ")
                .append(r.corpus().cases()).append(" cases, sha256 <code>").append(Texts.html(r.corpus().sha256()))
                .append("</code></p>\n");
        out.append("<p class=\"small\">Isolation: ").append(Texts.html(Texts.isolation(r))).append("</p>\n");
        List<String> unseen = org.fclcert.iut.Iuts.unobservable(r.iut().spec());
        if (!unseen.isEmpty()) {
            out.append("<p class=\"small\">What the adapter cannot observe: ").append(Texts.html(String.join("; ", unseen)))
                    .append("</p>\n");
        }
        if (r.origin() != null) {
            r.origin().warnings().forEach(w -> out.append("<div class=\"verdict no\">").append(Texts.html(w))
                    .append("</div>\n"));
        }
        boolean ok = r.basicLevel().conformant();
        out.append("<div class=\"verdict ").append(ok ? "ok" : r.basicLevel().notDetermined() ? "open" : "no")
                .append("\">Basic Level: ").append(r.basicLevel().verdict()).append("<div class=\"small\">")
                .append(Texts.html(r.basicLevel().reason())).append("</div></div>\n");
        if (r.origin() != null) {
            out.append("<details><summary>Provenance</summary><ul class=\"small\">");
            r.origin().lines().forEach(l -> out.append("<li>").append(Texts.html(l.strip())).append("</li>"));
            out.append("</ul></details>\n");
        }
        Report.Summary s = r.summary();
        out.append("<p class=\"counts\"><span><b>").append(s.cases()).append("</b> cases</span>")
                .append(count("passed", s.passed())).append(count("failed", s.failed()))
                .append(count("errored", s.errored())).append(count("skipped", s.skipped())).append("</p>\n");
        out.append("<p class=\"small tally\">Counted as in junit.xml and the Maven log: ")
                .append(Texts.html(Tally.of(r).sentence())).append("</p>\n");
        if (r.rejections().rejected() > 0) {
            out.append("<p>Negative cases: ").append(Texts.html(r.rejections().sentence()))
                    .append(r.rejections().doubtful() ? " <span class=\"small\">(" + Texts.html(Report.REJECTION_CAVEAT)
                            + ")</span>" : "").append("</p>\n");
        }
        if (!r.run().complete()) {
            out.append("<p><b>Incomplete run:</b> some selected cases were not run (shown as skipped).</p>\n");
        }
        if (!r.run().selection().whole()) {
            out.append("<p><b>Partial selection:</b> a verdict whose cases did not all run is not determined.</p>\n");
        }
    }

    private static String count(String status, int n) {
        return "<span><span class=\"st " + status + "\">" + n + " " + status + "</span></span>";
    }

    private void table(int table, String title) {
        out.append("<h2>").append(Texts.html(title)).append("</h2>\n");
        List<Report.FeatureRow> rows = r.features().stream().filter(f -> f.table() == table).toList();
        if (table == 9) {
            List<String> realised = rows.stream().filter(f -> f.status() == FeatureStatus.REALISED)
                    .map(Report.FeatureRow::id).toList();
            out.append("<p>Standard Extensions realised: ")
                    .append(realised.isEmpty() ? "none" : Texts.html(String.join(", ", realised))).append("</p>\n");
        }
        boolean semantic = r.semantic() != null;
        if (semantic) {
            out.append("<p class=\"small\"><b>").append(Texts.html(Report.LANGUAGE_AXIS)).append("</b>; <b>")
                    .append(Texts.html(Report.SEMANTIC_AXIS)).append("</b> (").append(Texts.html(r.semantic()
                    .presentAs())).append(" layout).</p>\n");
        }
        // a partial run tests a few rows: those lead, the untested ones are folded away
        List<Report.FeatureRow> untested = rows.stream().filter(f -> Texts.folded(r, f)).toList();
        List<Report.FeatureRow> shown = rows.stream().filter(f -> !untested.contains(f)).toList();
        if (!shown.isEmpty()) {
            featureRows(shown, semantic);
        }
        if (!untested.isEmpty()) {
            out.append("<details class=\"untested\"><summary>").append(untested.size()).append(" of ").append(rows.size())
                    .append(" rows not tested in this run (partial selection)</summary>\n");
            featureRows(untested, semantic);
            out.append("</details>\n");
        }
    }

    private void featureRows(List<Report.FeatureRow> rows, boolean semantic) {
        out.append("<table><tr><th>Language element</th><th>Feature</th><th>")
                .append(semantic ? "Language verdict" : "Verdict").append("</th><th>Passed</th>")
                .append("<th>Not passed</th>")
                .append(semantic ? "<th>Semantic verdict</th><th>Passed</th><th>Not passed</th><th>Not presentable</th>"
                        : "")
                .append("</tr>\n");
        for (Report.FeatureRow f : rows) {
            out.append("<tr><td>").append(Texts.html(f.element())).append("</td><td><b>").append(f.id())
                    .append("</b> ").append(Texts.html(f.description())).append("</td><td><span class=\"st ")
                    .append(f.status().word()).append("\">").append(f.status().label())
                    .append(Texts.html(Texts.runOfRequired(f))).append("</span></td><td>")
                    .append(f.passed()).append(" / ").append(f.passed() + f.failed() + f.errored()).append("</td><td>")
                    .append(links(f.notPassed()))
                    .append(f.notCounted().isEmpty() ? "" : (f.notPassed().isEmpty() ? "" : "; ")
                            + "<span class=\"small\">not counted: " + Texts.html(String.join(", ", f.notCounted()))
                            + "</span>")
                    .append("</td>");
            if (semantic && f.semantic() != null) {
                Report.Semantic sem = f.semantic();
                out.append("<td><span class=\"st ").append(sem.status().word()).append("\">")
                        .append(sem.status().label()).append("</span></td><td>").append(sem.passed()).append(" / ")
                        .append(sem.total()).append("</td><td>").append(links(sem.notPassed())).append("</td><td>")
                        .append(sem.notPresentable()).append("</td>");
            } else if (semantic) {
                out.append("<td></td><td></td><td></td><td></td>");
            }
            out.append("</tr>\n");
        }
        out.append("</table>\n");
    }

    /** Table 11 as measured: one row per item, the declared limit beside the measured one. */
    private void dataCheckList() {
        out.append("<h2>Data check list (Table 11)</h2>\n");
        if (r.dataCheckList().isEmpty()) {
            out.append("<p>Not measured in this run.</p>\n");
            return;
        }
        out.append("<table><tr><th>Technical data</th><th>Measured</th><th>Declared</th><th>Note</th>")
                .append("<th>How</th></tr>\n");
        for (org.fclcert.probe.DataCheckEntry d : r.dataCheckList()) {
            String flag = d.note().contains("NOT MET") || d.note().contains("WRONG") || d.note().contains("NON-CONFORMANT")
                    ? " class=\"st failed note\"" : "";   // a sentence, not a badge: it wraps
            out.append("<tr><td>").append(Texts.html(d.item())).append("</td><td><b>")
                    .append(Texts.html(Texts.measured(d))).append("</b></td><td>").append(Texts.html(d.declared()))
                    .append("</td><td><span").append(flag).append('>').append(Texts.html(d.note()))
                    .append("</span></td><td><details class=\"how\"><summary>how</summary><small>")
                    .append(Texts.html(d.method())).append("</small></details></td></tr>\n");
        }
        out.append("</table>\n");
    }

    private static String links(List<String> ids) {
        StringBuilder b = new StringBuilder();
        ids.forEach(id -> b.append(b.length() == 0 ? "" : ", ").append("<a href=\"#case-").append(Texts.html(id))
                .append("\">").append(Texts.html(id)).append("</a>"));
        return b.toString();
    }

    private void claimsAndInterpretation() {
        Report.Claims c = r.claims();
        out.append("<h2>Claims</h2>\n<p>");
        if (c.claimed().isEmpty()) {
            out.append("The implementation claims no feature.");
        } else {
            out.append("Claimed: ").append(Texts.html(String.join(", ", c.claimed()))).append("<br>Confirmed: ")
                    .append(Texts.html(String.join(", ", c.confirmed()))).append("<br><b>Claimed but not realised:</b> ")
                    .append(c.notRealised().isEmpty() ? "none" : Texts.html(String.join(", ", c.notRealised())));
            if (!c.notDetermined().isEmpty()) {
                out.append("<br>Claimed, not determined: ").append(Texts.html(String.join(", ", c.notDetermined())));
            }
            if (!c.untested().isEmpty()) {
                out.append("<br>Claimed, no case in this run: ").append(Texts.html(String.join(", ", c.untested())));
            }
            if (!c.unknown().isEmpty()) {
                out.append("<br>Unknown ids claimed: ").append(Texts.html(String.join(", ", c.unknown())));
            }
        }
        out.append("</p>\n<h2>Cases that depend on an interpretation</h2>\n");
        if (r.interpretation().isEmpty()) {
            out.append("<p>None in this run.</p>\n");
            return;
        }
        out.append("<p class=\"small\">Reported apart; counted against no verdict.</p>");
        List<Report.InterpretationEntry> telling = r.interpretation().stream().filter(i -> !i.rejectedAtLoad()).toList();
        if (telling.isEmpty()) {
            out.append("<p>No case reached the point it depends on.</p>\n");
        } else {
            out.append("<table><tr><th>Case</th><th>Point</th><th>Status</th><th>Message</th></tr>\n");
            telling.forEach(i -> out.append("<tr><td>").append(links(List.of(i.id()))).append("</td><td>")
                    .append(Texts.html(i.flag())).append("</td><td><span class=\"st ").append(i.status()).append("\">")
                    .append(i.status()).append("</span></td><td>").append(Texts.html(i.message())).append("</td></tr>\n"));
            out.append("</table>\n");
        }
        List<Report.InterpretationEntry> rejected = r.interpretation().stream()
                .filter(Report.InterpretationEntry::rejectedAtLoad).toList();
        if (!rejected.isEmpty()) {
            out.append("<p>Rejected at load for a reason of the implementation's own dialect, so they say nothing about"
                    + " the point they depend on: ");
            for (int k = 0; k < rejected.size(); k++) {
                out.append(k == 0 ? "" : ", ").append(links(List.of(rejected.get(k).id()))).append(" (")
                        .append(Texts.html(rejected.get(k).cause())).append(')');
            }
            out.append(".</p>\n");
        }
    }

    private void export() {
        out.append("<h2>FCL export (clause 6 e)</h2>\n<p>").append(Texts.html(Texts.exportSummary(r.cases())))
                .append("</p>\n");
    }

    private void causes() {
        out.append("<h2>Failures by cause</h2>\n");
        if (r.causes().isEmpty()) {
            out.append("<p>No case failed or errored.</p>\n");
            return;
        }
        out.append("<table><tr><th>Cases</th><th>Outcome</th><th>Cause</th><th>Case ids</th></tr>\n");
        r.causes().forEach(c -> out.append("<tr><td>").append(c.count()).append("</td><td>").append(Texts.html(c.kind()))
                .append("</td><td>").append(Texts.html(c.cause()).replaceAll("`([^`]*)`", "<code>$1</code>"))
                .append("</td><td>").append(links(c.cases())).append("</td></tr>\n"));
        out.append("</table>\n");
    }

    private void cases() {
        out.append("<h2>Cases</h2>\n<div class=\"filters\">Status: ");
        for (CaseStatus s : CaseStatus.values()) {
            boolean on = s != CaseStatus.PASSED || r.summary().passed() == r.summary().cases();
            out.append("<label><input type=\"checkbox\" data-status=\"").append(s.word()).append('"')
                    .append(on ? " checked" : "").append("> ").append(s.word()).append("</label>");
        }
        out.append(" &nbsp; Level: ");
        for (String level : List.of("basic", "extension", "open")) {
            out.append("<label><input type=\"checkbox\" data-level=\"").append(level).append("\" checked> ")
                    .append(level).append("</label>");
        }
        out.append(" &nbsp; <label>Id: <input id=\"q\" type=\"search\" placeholder=\"e.g. E-COG\"></label>")
                .append(" <span class=\"small\"><span id=\"shown\"></span> shown</span></div>\n");
        r.cases().forEach(this::caseBlock);
    }

    private boolean firstFailureOpened;

    private void caseBlock(CaseResult c) {
        // the first failure is shown open, so that the page opens on what is wrong
        boolean open = !firstFailureOpened && (c.status() == CaseStatus.FAILED || c.status() == CaseStatus.ERRORED);
        firstFailureOpened |= open;
        out.append("<details").append(open ? " open" : "").append(" class=\"case\" id=\"case-").append(Texts.html(c.id())).append("\" data-id=\"")
                .append(Texts.html(c.id())).append("\" data-status=\"").append(c.status().word())
                .append("\" data-level=\"").append(Texts.html(c.level())).append("\"><summary><span class=\"st ")
                .append(c.status().word()).append("\">").append(c.status().word()).append("</span> <b>")
                .append(Texts.html(c.id())).append("</b> ").append(Texts.html(c.title()))
                .append(" <span class=\"small\">").append(Texts.html(c.level())).append(" · ")
                .append(Texts.html(String.join(", ", c.tests()))).append("</span></summary>\n<p>")
                .append(Texts.html(c.message())).append("</p>\n");
        comparison(c);
        reference(c);
        presented(c);
        Double maxError = c.evidence().maxError();
        c.verdict().notes().forEach(n -> out.append("<p class=\"small\">Note: ").append(Texts.html(n)).append("</p>\n"));
        out.append("<p class=\"small\">Tolerance: ").append(Texts.html(c.setup().tolerance())).append(" · max measured error: ")
                .append(maxError == null ? "–" : maxError.toString()).append(" · export: <span class=\"st ")
                .append(c.export().status().word()).append("\">").append(c.export().status().word()).append("</span> ")
                .append(Texts.html(c.export().message())).append("</p>\n");
        if (c.evidence().error() != null) {
            out.append("<p>Implementation error:</p><pre>").append(Texts.html(c.evidence().error())).append("</pre>\n");
        }
        CaseResult.Setup setup = c.setup();
        if (setup.program() != null) {
            out.append("<p>Program (").append(setup.block() == null ? "first function block" : "block "
                    + Texts.html(setup.block())).append("):</p><pre>").append(numbered(setup.program())).append("</pre>\n");
        }
        if (c.status() != CaseStatus.PASSED) {
            out.append("<code class=\"cmd\">").append(Texts.html(Texts.repro(r, c.id()))).append("</code>\n");
        }
        out.append("</details>\n");
    }

    private void comparison(CaseResult c) {
        comparison(c, c.evidence());
    }

    /** The step's inputs and expected against actual, of the language axis or of the semantic one. */
    private void comparison(CaseResult c, CaseResult.Evidence evidence) {
        CaseResult.Step step = evidence.step();
        if (step != null) {
            out.append("<p>Step ").append(step.number()).append(", inputs: <code>")
                    .append(Texts.html(Texts.describe(step.inputs()))).append("</code></p>\n");
        }
        CaseResult.Mismatch mismatch = evidence.mismatch();
        if (mismatch instanceof CaseResult.Mismatch.Outputs outputs) {
            Map<String, Double> expected = outputs.expected();
            Map<?, ?> actual = outputs.actual();
            out.append("<table><tr><th>output</th><th>expected</th><th>actual</th></tr>");
            expected.forEach((name, want) -> out.append("<tr><td>").append(Texts.html(String.valueOf(name)))
                    .append("</td><td>").append(Texts.html(String.valueOf(want))).append("</td><td>")
                    .append(Texts.html(String.valueOf(lookup(actual, String.valueOf(name))))).append("</td></tr>"));
            out.append("</table>\n");
        } else if (mismatch != null) {
            out.append("<table>").append(row("expected", mismatch.expected())).append(row("actual", mismatch.actual()))
                    .append("</table>\n");
            c.expectedRejection().ifPresent(want -> c.programLine(want.line()).ifPresent(text -> out.append(
                    "<p>Line ").append(want.line()).append(", where the error is: <code>").append(Texts.html(text))
                    .append("</code></p>\n")));
        }
    }

    /** The semantic axis of a presented case: how the case fared written in the library's layout, and why not. */
    private void presented(CaseResult c) {
        CaseResult.Presented p = c.presented();
        if (p == null) {
            return;
        }
        out.append("<p><b>Semantic axis</b> (written in ").append(Texts.html(p.dialect()))
                .append("'s layout): <span class=\"st ").append(p.status().word()).append("\">").append(p.status().word())
                .append("</span> ").append(Texts.html(p.message())).append("</p>\n");
        if (p.status() == org.fclcert.harness.PresentedStatus.FAILED
                || p.status() == org.fclcert.harness.PresentedStatus.ERRORED) {
            comparison(c, p.evidence());
            reference(c.id() + " (" + p.dialect() + " layout)", p.evidence());
        }
    }

    /** How many outputs of one case get a picture of their accumulated set. */
    static final int PICTURES_PER_CASE = 3;

    /**
     * What the reference evaluator did at the failing step, and for each output with a wrong value its accumulated
     * set with the standard's value and the implementation's marked (inline SVG, nothing fetched).
     */
    private void reference(CaseResult c) {
        reference(c.id(), c.evidence());
    }

    private void reference(String caseId, CaseResult.Evidence evidence) {
        ReferenceTrace t = evidence.reference();
        if (t == null) {
            return;
        }
        out.append("<p>fclcert's reference evaluator at step ").append(t.step()).append(":</p><ul class=\"trace\">");
        t.lines().forEach(l -> out.append("<li>").append(Texts.html(l)).append("</li>"));
        out.append("</ul>\n");
        if (!(evidence.mismatch() instanceof CaseResult.Mismatch.Outputs outputs)) {
            return;
        }
        int drawn = 0;
        for (Map.Entry<String, Double> want : outputs.expected().entrySet()) {
            Object got = lookup(outputs.actual(), want.getKey());
            ReferenceTrace.OutputValue o = t.output(want.getKey());
            if (o == null || o.set().isEmpty() || want.getValue() == null || got.equals(want.getValue())
                    || drawn++ >= PICTURES_PER_CASE) {
                continue;
            }
            String svg = SetPicture.svg(caseId + ", step " + t.step() + ": accumulated set of " + o.variable(),
                    o.variable(), o.singletons(), o.set(), want.getValue(), got instanceof Double d ? d : null);
            out.append("<figure class=\"set\">").append(svg.substring(svg.indexOf("<svg")))
                    .append("</figure>\n");
        }
    }

    private static Object lookup(Map<?, ?> actual, String name) {
        return actual.entrySet().stream().filter(e -> String.valueOf(e.getKey()).equalsIgnoreCase(name))
                .<Object>map(Map.Entry::getValue).findFirst().orElse("(missing)");
    }

    private static String row(String label, Object value) {
        return "<tr><th>" + label + "</th><td>" + Texts.html(Texts.describe(value)) + "</td></tr>";
    }

    /** The program with its line numbers; the blank lines left where the case's metadata was are skipped. */
    private static String numbered(String program) {
        String[] lines = program.split("\n", -1);
        StringBuilder b = new StringBuilder();
        int width = String.valueOf(lines.length).length();
        int first = 0;
        while (first < lines.length - 1 && lines[first].isBlank()) {
            first++;
        }
        for (int i = first; i < lines.length; i++) {
            b.append(String.format("%" + width + "d  ", i + 1)).append(Texts.html(lines[i])).append('\n');
        }
        return b.toString();
    }
}
