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

    /** The command that reruns one case against the same implementation and corpus. */
    static String repro(Report report, String caseId) {
        StringBuilder b = new StringBuilder("./fclcert certify --iut ").append(shellQuote(report.iut().spec()));
        if (report.iut().classpath() != null) {
            b.append(" --classpath ").append(shellQuote(report.iut().classpath()));
        }
        String dir = report.corpus().dir();
        // the default corpus is conformance/ at a checkout's root, else the bundled one: neither needs naming
        if (dir != null && !dir.equals("conformance") && !dir.equals(org.fclcert.corpus.BundledCorpus.NAME)) {
            b.append(" --corpus ").append(shellQuote(dir));
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
}
