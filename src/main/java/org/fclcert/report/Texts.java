package org.fclcert.report;

import java.util.Map;
import java.util.stream.Collectors;

/** Small text helpers shared by the renderers. */
final class Texts {
    private Texts() {
    }

    /** Expected/actual values for people: {@code valve = 74.8, flow = 1.0} or the sentence itself. */
    static String describe(Object value) {
        if (value == null) {
            return "";
        }
        if (value instanceof Map<?, ?> map) {
            return map.entrySet().stream().map(e -> e.getKey() + " = " + e.getValue())
                    .collect(Collectors.joining(", "));
        }
        return value.toString();
    }

    static String html(String s) {
        if (s == null) {
            return "";
        }
        StringBuilder b = new StringBuilder(s.length() + 16);
        for (char ch : s.toCharArray()) {
            switch (ch) {
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '&' -> b.append("&amp;");
                case '"' -> b.append("&quot;");
                case '\'' -> b.append("&#39;");
                default -> b.append(allowedInXml(ch) ? ch : '\uFFFD');
            }
        }
        return b.toString();
    }

    /** Replaces characters XML 1.0 forbids (an implementation's garbage output may contain them). */
    static String xmlSafe(String s) {
        if (s == null) {
            return "";
        }
        StringBuilder b = new StringBuilder(s.length());
        s.chars().forEach(ch -> b.append(allowedInXml((char) ch) ? (char) ch : '\uFFFD'));
        return b.toString();
    }

    private static boolean allowedInXml(char ch) {
        return ch == '\t' || ch == '\n' || ch == '\r' || (ch >= 0x20 && ch != 0xFFFE && ch != 0xFFFF);
    }

    /**
     * Untrusted text (an implementation's name, version, claims, messages) in report.md, in a table cell or
     * after a list marker: one line (a newline cannot start a forged {@code # heading} or
     * {@code **Basic Level: conformant**} line), every character with a Markdown or HTML meaning backslash-escaped
     * (no emphasis, links such as {@code [x](javascript:…)}, autolinks, raw HTML or entities), control
     * characters shown visibly ({@code \0}, {@code \e}, {@code \x07}) rather than written.
     */
    /**
     * A table cell of fclcert's own Markdown (the comparison page's links and bold marks): one line, pipes
     * escaped, nothing else touched. Text from an implementation goes through {@link #cell} instead.
     */
    static String tableCell(String s) {
        return s == null ? "" : s.replace("\r", "").replace("\n", " ").replace("|", "\\|");
    }

    static String cell(String s) {
        if (s == null) {
            return "";
        }
        StringBuilder b = new StringBuilder(s.length() + 16);
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            if (ch == '\r') {
                continue;
            }
            if (ch == '\n' || ch == '\t') {
                b.append(' ');
            } else if ("\\`*_[]<>|&~".indexOf(ch) >= 0) {
                b.append('\\').append(ch);
            } else if (ch == 0) {
                b.append("\\0");
            } else if (ch == 0x1b) {
                b.append("\\e");
            } else if (ch < 0x20 || (ch >= 0x7f && ch <= 0x9f)) {
                b.append(String.format("\\x%02x", (int) ch));
            } else {
                b.append(ch);
            }
        }
        return b.toString();
    }

    /** Quotes a word for a POSIX shell. */
    static String shellQuote(String s) {
        if (s.matches("[A-Za-z0-9_./:=@%+,-]+")) {
            return s;
        }
        return "'" + s.replace("'", "'\\''") + "'";
    }

    /**
     * True for a Table 8/9/10 row that a partial run (a selection) did not test on either axis: the reports
     * show the rows it tested and fold these away.
     */
    static boolean folded(Report r, Report.FeatureRow f) {
        return !r.run().selection().whole() && f.status() == FeatureStatus.NOT_TESTED
                && (f.semantic() == null || f.semantic().status() == FeatureStatus.NOT_TESTED);
    }

    /** How many of the cases a row's verdict needs ran, when not all did: {@code " (1 of 6 run)"}, else "". */
    static String runOfRequired(Report.FeatureRow f) {
        if (f.status() != FeatureStatus.NOT_DETERMINED && f.status() != FeatureStatus.NOT_TESTED) {
            return "";
        }
        return f.required() < 0 ? " (" + f.run() + " run)" : f.run() < f.required() ? " (" + f.run() + " of "
                + f.required() + " run)" : "";
    }

    /** Passed of the cases counted for a row: those that passed and those whose failure is attributed to it. */
    static String passedOfCounted(Report.FeatureRow f) {
        return f.passed() + "/" + (f.passed() + f.failed() + f.errored());
    }

    /** The cases a row names besides its passes: not passed (counted against it), then not counted and why. */
    static String notPassedText(Report.FeatureRow f) {
        String notPassed = String.join(", ", f.notPassed());
        if (f.notCounted().isEmpty()) {
            return notPassed;
        }
        return (notPassed.isEmpty() ? "" : notPassed + "; ") + "not counted: " + String.join(", ", f.notCounted());
    }

    /** The command that reruns one case against the same implementation and corpus. */
    static String repro(Report report, String caseId) {
        String rerun = report.toolkit().rerun();
        if (rerun != null) {
            String seed = report.origin() != null && report.origin().provenance() != null
                    ? " -Dfclcert.seed=" + shellQuote(report.origin().provenance().seed()) : "";
            return rerun.replace(org.fclcert.harness.RunHeader.Toolkit.CASE, caseId) + seed;
        }
        StringBuilder b = new StringBuilder("./fclcert certify --iut ").append(shellQuote(report.iut().spec()));
        if (report.iut().classpath() != null) {
            b.append(" --classpath ").append(shellQuote(report.iut().classpath()));
        }
        String dir = report.corpus().dir();
        // the default corpus is conformance/ at a checkout's root, else the bundled one: neither needs naming
        if (dir != null && !dir.equals("conformance") && !dir.equals(org.fclcert.corpus.BundledCorpus.NAME)) {
            b.append(" --corpus ").append(shellQuote(dir));
        }
        if (report.origin() != null && report.origin().provenance() != null) {
            b.append(" --seed ").append(shellQuote(report.origin().provenance().seed()));
        }
        return b.append(" --case ").append(shellQuote(caseId)).toString();
    }

    /** A data check list value as read: {@code ≥ 64 rules}, {@code 3 points}, {@code not measured}. */
    static String measured(org.fclcert.probe.DataCheckEntry d) {
        if (d.bound().equals(org.fclcert.probe.DataCheckEntry.NOT_MEASURED) || d.value().isEmpty()) {
            return "not measured";
        }
        boolean number = d.value().chars().allMatch(Character::isDigit);
        return (d.bound().equals(org.fclcert.probe.DataCheckEntry.AT_LEAST) && number ? "≥ " : "") + d.value()
                + (number ? " " + d.unit() : "");
    }

    /** Why a case's export was not checked, for the export summary ("72 negative cases", …). */
    static String exportNotRunReason(org.fclcert.harness.CaseResult c) {
        if (c.status() == org.fclcert.harness.CaseStatus.SKIPPED) {
            return "the case was not run";
        }
        if (c.status() == org.fclcert.harness.CaseStatus.ERRORED) {
            return "the implementation broke down during the case";
        }
        if ("load and evaluate".equals(CaseFacts.expected(c))) {
            return "the program was rejected at load";
        }
        if (CaseFacts.expected(c) instanceof String) {
            return "a negative case (nothing to export)";
        }
        return "not checked";
    }

    /** {@code 193 not-run (121: the program was rejected at load; 72: a negative case (nothing to export))}. */
    static String exportSummary(java.util.List<org.fclcert.harness.CaseResult> cases) {
        java.util.Map<org.fclcert.harness.ExportStatus, Integer> counts = new java.util.LinkedHashMap<>();
        cases.forEach(c -> counts.merge(CaseFacts.exportStatus(c), 1, Integer::sum));
        java.util.Map<String, Integer> reasons = new java.util.LinkedHashMap<>();
        cases.stream().filter(c -> CaseFacts.exportStatus(c) == org.fclcert.harness.ExportStatus.NOT_RUN)
                .forEach(c -> reasons.merge(exportNotRunReason(c), 1, Integer::sum));
        String why = reasons.entrySet().stream().sorted(java.util.Map.Entry.<String, Integer>comparingByValue().reversed())
                .map(e -> e.getValue() + ": " + e.getKey()).reduce((a, b) -> a + "; " + b).orElse("");
        return counts.entrySet().stream().map(e -> e.getValue() + " " + e.getKey().word()
                        + (e.getKey() == org.fclcert.harness.ExportStatus.NOT_RUN ? " (" + why + ")"
                        : e.getKey() == org.fclcert.harness.ExportStatus.UNSUPPORTED ? " (the implementation does not export FCL)" : ""))
                .reduce((a, b) -> a + ", " + b).orElse("no case") + ".";
    }

    /**
     * How the implementation was isolated from the host, as recorded (a run without the sandbox says so first;
     * results written before fclcert recorded it say that).
     */
    static String isolation(Report r) {
        org.fclcert.sandbox.Isolation isolation = r.iut().isolation();
        if (isolation == null) {
            return "not recorded (results written without an isolation record)";
        }
        return (isolation.unisolated() ? "NOT SANDBOXED: " : "") + isolation.description();
    }

    /** The header's implementation line: its name and version, then how it was reached. */
    static String implementation(Report r) {
        return implementation(r, s -> s);
    }

    /** {@link #implementation(Report)} with the implementation's own words (name, version) passed through {@code own}. */
    static String implementation(Report r, java.util.function.UnaryOperator<String> own) {
        String spec = r.iut().spec();
        String command = r.iut().command();
        String how = spec == null || spec.isBlank() ? command : spec;
        // a results file read back may hold anything here: no backtick may end the span, the command is escaped
        String out = own.apply(r.iut().name()) + " " + own.apply(r.iut().version()) + ", reached as `"
                + String.valueOf(how).replaceAll("[`\\p{Cntrl}]", "?") + "`";
        if (command != null && !command.isBlank() && !command.equals(how)) {
            out += " (" + own.apply(command) + ")";
        }
        return out;
    }
}
