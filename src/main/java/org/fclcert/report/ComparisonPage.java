package org.fclcert.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.fclcert.probe.DataCheckEntry;

/**
 * {@code reports/index.md} and {@code index.html}: several certifications side by side — a summary (the table the
 * README shows), every Table 8/9/10 row with each implementation's verdict(s), the telling deviations with their
 * cases and values, the causes of failure, and the Table 11 figures. Made only from the reports' own content (no
 * clock), so the same reports always give the same page. Format: {@code docs/report-format.md}, "Comparison page".
 */
public final class ComparisonPage {
    private static final Pattern CODE = Pattern.compile("`([^`]+)`");
    private static final Pattern BOLD = Pattern.compile("\\*\\*([^*]+)\\*\\*");
    private static final Pattern LINK = Pattern.compile("\\[([^\\]]+)\\]\\(([^)\\s]+)\\)");

    /** One certification: its report and the link (relative to the page) of its report.md. */
    public record Entry(Report report, String link) {
        public Entry {
            Objects.requireNonNull(report, "report");
            Objects.requireNonNull(link, "link");
        }

        String title() {
            return report.iut().name() + " " + report.iut().version();
        }
    }

    private sealed interface Block {
    }

    private record Heading(int level, String text) implements Block {
    }

    private record Para(String text) implements Block {
    }

    private record Table(List<String> head, List<List<String>> rows) implements Block {
    }

    private record Bullets(List<String> items) implements Block {
    }

    private final List<Entry> entries;
    private final List<Block> blocks = new ArrayList<>();

    private ComparisonPage(List<Entry> entries) {
        this.entries = List.copyOf(entries);
    }

    /** Markdown of the page. */
    public static String markdown(List<Entry> entries) {
        return new ComparisonPage(entries).build().renderMarkdown();
    }

    /** HTML of the page (self-contained, no scripts). */
    public static String html(List<Entry> entries) {
        return new ComparisonPage(entries).build().renderHtml();
    }

    /** Only the summary table, as Markdown: what the README shows and {@code fclcert compare} prints. */
    public static String summaryMarkdown(List<Entry> entries) {
        ComparisonPage page = new ComparisonPage(entries);
        page.summary();
        return page.renderMarkdown();
    }

    private ComparisonPage build() {
        blocks.add(new Heading(1, "FCL implementations side by side"));
        String corpora = entries.stream().map(e -> e.report().corpus().cases() + " cases, sha256 `"
                + e.report().corpus().sha256().substring(0, Math.min(12, e.report().corpus().sha256().length())) + "…`")
                .distinct().reduce((a, b) -> a + "; " + b).orElse("");
        blocks.add(new Para("IEC 61131-7 certifications by fclcert, each of the corpus programs exactly as the standard"
                + " writes them (the language verdict). Corpus: " + corpora + "."
                + (entries.stream().map(e -> e.report().corpus().sha256()).distinct().count() > 1
                        ? " **The reports were made from different corpora**: compare with care." : "")
                + " Made by `fclcert compare` from the report directories; `scripts/regenerate-reports` rewrites"
                + " them all."));
        summary();
        features();
        deviations();
        causes();
        dataCheckList();
        return this;
    }

    private List<String> head(String first) {
        List<String> head = new ArrayList<>();
        head.add(first);
        entries.forEach(e -> head.add("[" + e.title() + "](" + e.link() + ")"));
        return head;
    }

    private void summary() {
        List<List<String>> rows = new ArrayList<>();
        int total = entries.isEmpty() ? 0 : entries.get(0).report().summary().cases();
        rows.add(row("Cases (" + total + ")", e -> {
            Report.Summary s = e.report().summary();
            return s.passed() == s.cases() ? s.passed() + " passed"
                    : s.passed() + " passed, " + s.failed() + " failed, " + s.errored() + " errored"
                            + (s.skipped() > 0 ? ", " + s.skipped() + " skipped" : "");
        }));
        rows.add(row("Negative cases rejected", e -> {
            Report.Rejections r = e.report().rejections();
            return r.rejected() + (r.doubtful() ? ": " + r.atErrorLine() + " at the error's line, " + r.otherLine()
                    + " elsewhere, " + r.unlocated() + " without a line" : ", all at the error's line");
        }));
        rows.add(row("Basic Level (Table 8)", e -> {
            Report.BasicLevel b = e.report().basicLevel();
            return b.conformant() ? "conformant" : b.notDetermined() ? "not determined (" + b.run() + " of "
                    + b.required() + " run)" : "**not conformant** (" + b.passed() + " of " + b.required()
                    + " Basic cases passed)";
        }));
        rows.add(row("Standard Extensions realised (Table 9)", e -> realised(e.report(), 9)));
        rows.add(row("Open Level realised (Table 10)", e -> realised(e.report(), 10)));
        if (entries.stream().anyMatch(e -> e.report().semantic() != null)) {
            rows.add(row("Semantic axis: positive cases in the library's layout", e -> {
                Report.SemanticAxis a = e.report().semantic();
                return a == null ? "not run" : a.passed() + " of " + (a.cases() - a.notPresentable()) + " passed ("
                        + a.presentAs() + " layout; " + a.notPresentable() + " not presentable)";
            }));
            for (int table : new int[] {8, 9, 10}) {
                rows.add(row("Semantic axis: Table " + table + " rows realised", e -> semanticRealised(e.report(),
                        table)));
            }
        }
        rows.add(row("Most common cause of failure", e -> e.report().causes().isEmpty() ? "none"
                : e.report().causes().get(0).sentence()));
        rows.add(row("FCL export (clause 6 e)", ComparisonPage::export));
        rows.add(row("Execution time (Table 11)", e -> measured(e.report(), "execution-time-ms")));
        rows.add(row("Memory (Table 11)", e -> measured(e.report(), "memory-kb")));
        rows.add(row("Identifiers (Table 11)", e -> measured(e.report(), "identifier-length")));
        blocks.add(new Table(head(""), rows));
    }

    private interface Cell {
        String of(Entry e);
    }

    private List<String> row(String label, Cell cell) {
        List<String> row = new ArrayList<>();
        row.add(label);
        entries.forEach(e -> row.add(cell.of(e)));
        return row;
    }

    private static String realised(Report r, int table) {
        long rows = r.features().stream().filter(f -> f.table() == table).count();
        long realised = r.features().stream().filter(f -> f.table() == table && f.status() == FeatureStatus.REALISED)
                .count();
        return realised + " of " + rows;
    }

    /** Rows realised on the semantic axis, of those with a presented case. */
    private static String semanticRealised(Report r, int table) {
        if (r.semantic() == null) {
            return "not run";
        }
        List<Report.FeatureRow> rows = r.features().stream()
                .filter(f -> f.table() == table && f.semantic() != null && f.semantic().total() > 0).toList();
        long realised = rows.stream().filter(f -> f.semantic().status() == FeatureStatus.REALISED).count();
        return realised + " of " + rows.size() + " with a presentable case";
    }

    private static String export(Entry e) {
        int passed = 0;
        int failed = 0;
        int unsupported = 0;
        for (CaseResult c : e.report().cases()) {
            if (CaseFacts.exportStatus(c) == ExportStatus.PASSED) {
                passed++;
            } else if (CaseFacts.exportStatus(c) == ExportStatus.FAILED) {
                failed++;
            } else if (CaseFacts.exportStatus(c) == ExportStatus.UNSUPPORTED) {
                unsupported++;
            }
        }
        if (passed + failed + unsupported == 0) {
            return "not checked (no program loaded)";
        }
        if (unsupported > 0 && passed + failed == 0) {
            return "not offered";
        }
        return passed + " of " + (passed + failed) + " exports read back and evaluate alike";
    }

    private static String measured(Report r, String id) {
        return r.dataCheckList().stream().filter(d -> d.id().equals(id)).findFirst()
                .map(d -> {
                    String value = Texts.measured(d);
                    return d.note().startsWith("NON-CONFORMANT") ? value + " (**" + d.note().replaceFirst(":.*", "")
                            .toLowerCase(Locale.ROOT) + "**: " + firstClause(d.note().replaceFirst("^[^:]*: ", "")) + ")"
                            : value;
                })
                .orElse("not measured");
    }

    private static String firstClause(String note) {
        int cut = note.indexOf(" (");
        return cut > 0 ? note.substring(0, cut) : note;
    }

    private void features() {
        blocks.add(new Heading(2, "Tables 8, 9 and 10, row by row"));
        boolean semantic = entries.stream().flatMap(e -> e.report().features().stream()).anyMatch(f -> f.semantic() != null);
        blocks.add(new Para("Each cell is the **language** verdict: the corpus cases of the row as the standard writes"
                + " them, passed of run." + (semantic ? " Where the semantic axis was run, the **semantic** verdict"
                + " follows it: the same cases sent in the implementation's own layout." : " The semantic axis (the"
                + " same cases in each library's own layout) was not run for these reports.")));
        Set<String> ids = new LinkedHashSet<>();
        entries.forEach(e -> e.report().features().forEach(f -> ids.add(f.id())));
        for (int table : List.of(8, 9, 10)) {
            List<List<String>> rows = new ArrayList<>();
            for (String id : ids) {
                Optional<Report.FeatureRow> any = entries.stream().flatMap(e -> e.report().features().stream())
                        .filter(f -> f.id().equals(id) && f.table() == table).findFirst();
                if (any.isEmpty()) {
                    continue;
                }
                rows.add(row(id + ": " + any.get().description(), e -> e.report().features().stream()
                        .filter(f -> f.id().equals(id)).findFirst().map(ComparisonPage::verdict).orElse("–")));
            }
            blocks.add(new Heading(3, "Table " + table));
            blocks.add(new Table(head("Feature"), rows));
        }
    }

    private static String verdict(Report.FeatureRow f) {
        String language = mark(f.status()) + " " + Texts.passedOfCounted(f);
        if (f.semantic() == null) {
            return language;
        }
        return "language: " + language + "; semantic: " + mark(f.semantic().status()) + " " + f.semantic().passed()
                + "/" + f.semantic().total();
    }

    private static String mark(FeatureStatus s) {
        return s == FeatureStatus.REALISED || s == FeatureStatus.NOT_TESTED || s == FeatureStatus.NOT_DETERMINED
                ? s.label() : "**" + s.label() + "**";
    }

    /** Positive cases on which some implementation computed something else than the standard, or broke down. */
    private void deviations() {
        blocks.add(new Heading(2, "Telling deviations"));
        Map<String, CaseResult> titled = new LinkedHashMap<>();
        for (Entry e : entries) {
            for (CaseResult c : e.report().cases()) {
                if (telling(c)) {
                    titled.putIfAbsent(c.id(), c);
                }
            }
        }
        if (titled.isEmpty()) {
            blocks.add(new Para("No implementation computed a wrong value, refused to evaluate or broke down on a program"
                    + " it had accepted."));
            return;
        }
        blocks.add(new Para("Cases where an implementation loaded the program and then computed another value than the"
                + " standard (the first wrong output: its value, the standard's, and the step), refused to evaluate, or"
                + " broke down. \"as the standard\" means the case passed; \"rejected\" that the program did not load."));
        List<List<String>> rows = new ArrayList<>();
        titled.values().stream().sorted((a, b) -> a.id().compareTo(b.id())).forEach(first -> {
            List<String> row = new ArrayList<>();
            row.add(first.id() + ": " + first.title());
            for (Entry e : entries) {
                row.add(e.report().cases().stream().filter(c -> c.id().equals(first.id())).findFirst()
                        .map(ComparisonPage::outcome).orElse("not run"));
            }
            rows.add(row);
        });
        blocks.add(new Table(head("Case"), rows));
    }

    private static boolean telling(CaseResult c) {
        if (c.interpretation() || c.status() == CaseStatus.PASSED || c.status() == CaseStatus.SKIPPED) {
            return false;
        }
        String m = c.message() == null ? "" : c.message();
        if (m.startsWith("rejected a program") || m.startsWith("accepted a program")) {
            return false;
        }
        return !(CaseFacts.expected(c) instanceof String);   // negative cases are in the causes
    }

    private static String outcome(CaseResult c) {
        String m = c.message() == null ? "" : c.message();
        if (c.status() == CaseStatus.PASSED) {
            return "as the standard";
        }
        if (c.status() == CaseStatus.SKIPPED) {
            return "skipped";
        }
        if (m.startsWith("rejected a program")) {
            return "rejected";
        }
        if (c.status() == CaseStatus.ERRORED) {
            return "errored: " + Causes.classify(c)[1];
        }
        if (CaseFacts.expected(c) instanceof Map<?, ?> expected && CaseFacts.actual(c) instanceof Map<?, ?> actual) {
            // the output furthest off (another may differ only within the tolerance)
            Object worstName = null;
            double worst = -1;
            double want = 0;
            double have = 0;
            for (Map.Entry<?, ?> e : expected.entrySet()) {
                if (e.getValue() instanceof Number w && actual.get(e.getKey()) instanceof Number h) {
                    double off = Double.isNaN(h.doubleValue()) != Double.isNaN(w.doubleValue()) ? Double.MAX_VALUE
                            : Math.abs(h.doubleValue() - w.doubleValue()) / Math.max(1, Math.abs(w.doubleValue()));
                    if (off > worst) {
                        worst = off;
                        worstName = e.getKey();
                        want = w.doubleValue();
                        have = h.doubleValue();
                    }
                }
            }
            if (worstName != null && worst > 0) {
                return "**" + number(have) + "** where the standard gives " + number(want) + " (" + worstName
                        + (CaseFacts.step(c) == null ? "" : ", step " + CaseFacts.step(c)) + ")";
            }
        }
        return Causes.classify(c)[0] + ": " + Causes.classify(c)[1];
    }

    static String number(double v) {
        if (Double.isNaN(v)) {
            return "NaN";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        String s = String.format(Locale.ROOT, "%.6g", v);
        if (s.contains("e")) {
            return s.replaceFirst("\\.?0+e", "e");
        }
        return s.contains(".") ? s.replaceFirst("\\.?0+$", "") : s;
    }

    private void causes() {
        blocks.add(new Heading(2, "Causes of failure"));
        for (Entry e : entries) {
            blocks.add(new Heading(3, e.title()));
            List<String> items = e.report().causes().stream().map(Causes.Cause::sentence).toList();
            if (items.isEmpty()) {
                blocks.add(new Para("No case failed or errored."));
            } else {
                blocks.add(new Bullets(items.stream().map(s -> s.replace("\n", " ")).toList()));
            }
        }
    }

    private void dataCheckList() {
        blocks.add(new Heading(2, "Data check list (Table 11)"));
        Map<String, String> items = new LinkedHashMap<>();
        entries.forEach(e -> e.report().dataCheckList().forEach(d -> items.putIfAbsent(d.id(), d.item())));
        if (items.isEmpty()) {
            blocks.add(new Para("Not measured in these reports."));
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        items.forEach((id, item) -> rows.add(row(item, e -> e.report().dataCheckList().stream()
                .filter(d -> d.id().equals(id)).findFirst().map(ComparisonPage::figure).orElse("not measured"))));
        blocks.add(new Table(head("Technical data"), rows));
        blocks.add(new Para("How each row is measured: docs/data-check-list.md; each report's Table 11 gives the notes."));
    }

    private static String figure(DataCheckEntry d) {
        String value = Texts.measured(d);
        if (DataCheckEntry.NOT_MEASURED.equals(d.bound())) {
            return value + (d.note().isBlank() ? "" : " (" + shorten(d.note(), 90) + ")");
        }
        return value;
    }

    private static String shorten(String s, int max) {
        String one = s.replaceAll("\\s+", " ").strip();
        return one.length() <= max ? one : one.substring(0, max) + "…";
    }

    private String renderMarkdown() {
        StringBuilder out = new StringBuilder();
        for (Block b : blocks) {
            if (b instanceof Heading h) {
                out.append("#".repeat(h.level())).append(' ').append(h.text()).append("\n\n");
            } else if (b instanceof Para p) {
                out.append(p.text()).append("\n\n");
            } else if (b instanceof Bullets l) {
                l.items().forEach(i -> out.append("- ").append(i).append('\n'));
                out.append('\n');
            } else if (b instanceof Table t) {
                out.append("| ").append(String.join(" | ", t.head().stream().map(Texts::tableCell).toList())).append(" |\n");
                out.append("|").append(" --- |".repeat(t.head().size())).append('\n');
                t.rows().forEach(r -> out.append("| ").append(String.join(" | ", r.stream().map(Texts::tableCell).toList()))
                        .append(" |\n"));
                out.append('\n');
            }
        }
        return out.toString().stripTrailing() + "\n";
    }

    private String renderHtml() {
        StringBuilder out = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
                + "<title>FCL implementations side by side</title><style>"
                + "body{font:15px/1.45 system-ui,sans-serif;margin:0;color:#1d232b;background:#fff}"
                + "main{max-width:1400px;margin:0 auto;padding:24px}h1{font-size:26px}h2{margin-top:32px;"
                + "border-bottom:1px solid #d6dbe1;padding-bottom:4px}table{border-collapse:collapse;width:100%;"
                + "margin:8px 0 16px}th,td{border:1px solid #d6dbe1;padding:5px 8px;text-align:left;vertical-align:top}"
                + "th{background:#eef2f6}tr:nth-child(even) td{background:#fafbfc}code{background:#eef2f6;"
                + "padding:0 3px;border-radius:3px;font-size:90%}b{color:#a3261d}td:first-child{width:22%}"
                + "</style></head><body><main>\n");
        for (Block b : blocks) {
            if (b instanceof Heading h) {
                out.append("<h").append(h.level()).append('>').append(inline(h.text())).append("</h").append(h.level())
                        .append(">\n");
            } else if (b instanceof Para p) {
                out.append("<p>").append(inline(p.text())).append("</p>\n");
            } else if (b instanceof Bullets l) {
                out.append("<ul>\n");
                l.items().forEach(i -> out.append("<li>").append(inline(i)).append("</li>\n"));
                out.append("</ul>\n");
            } else if (b instanceof Table t) {
                out.append("<table><tr>");
                t.head().forEach(h -> out.append("<th>").append(inline(h)).append("</th>"));
                out.append("</tr>\n");
                for (List<String> r : t.rows()) {
                    out.append("<tr>");
                    r.forEach(c -> out.append("<td>").append(inline(c)).append("</td>"));
                    out.append("</tr>\n");
                }
                out.append("</table>\n");
            }
        }
        return out.append("</main></body></html>\n").toString();
    }

    /** The page's Markdown inline marks as HTML: `code`, **bold**, [text](link); everything else escaped. */
    static String inline(String text) {
        String s = Texts.html(text);
        s = CODE.matcher(s).replaceAll(m -> "<code>" + Matcher.quoteReplacement(m.group(1)) + "</code>");
        s = BOLD.matcher(s).replaceAll(m -> "<b>" + Matcher.quoteReplacement(m.group(1)) + "</b>");
        s = LINK.matcher(s).replaceAll(m -> "<a href=\"" + Matcher.quoteReplacement(
                m.group(2).replaceFirst("\\.md$", ".html")) + "\">" + Matcher.quoteReplacement(m.group(1)) + "</a>");
        return s;
    }
}
