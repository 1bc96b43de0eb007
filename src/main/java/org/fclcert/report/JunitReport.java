package org.fclcert.report;

import java.io.StringWriter;
import java.util.List;
import java.util.Locale;
import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamWriter;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.PresentedStatus;

/**
 * {@code junit.xml} (and the same as {@code TEST-fclcert.xml}, the name Surefire and the surefire-report
 * plugin look for) in the Surefire shape CI servers read: one testcase per case, classname
 * {@code fclcert.<first feature tested>} (the feature row, e.g. {@code fclcert.E-ACCU-NSUM}; a negative case,
 * which tests no row, {@code fclcert.<level>.negative}); a {@code failure} for a wrong result or a wrongly
 * accepted/rejected program, an {@code error} for a crash, timeout or protocol fault, {@code skipped} with
 * its reason. A case of the Extension or Open Level none of whose features the implementation claims is
 * skipped too, its reason saying so and what it gave, so that a build that {@code verify} passes is green
 * in CI as well.
 */
public final class JunitReport {
    private JunitReport() {
    }

    public static String render(Report r) {
        StringWriter text = new StringWriter();
        try {
            XMLStreamWriter x = XMLOutputFactory.newFactory().createXMLStreamWriter(text);
            x.writeStartDocument("UTF-8", "1.0");
            x.writeCharacters("\n");
            x.writeStartElement("testsuite");
            x.writeAttribute("name", "fclcert certify " + safe(r.iut().name()));
            Counts counts = counts(r);
            x.writeAttribute("tests", String.valueOf(counts.tests()));
            x.writeAttribute("failures", String.valueOf(counts.failures()));
            x.writeAttribute("errors", String.valueOf(counts.errors()));
            x.writeAttribute("skipped", String.valueOf(counts.skipped()));
            x.writeAttribute("time", seconds(r.cases().stream().mapToLong(c -> millis(c)).sum()));
            x.writeAttribute("timestamp", r.generatedAt());
            properties(x, r);
            for (CaseResult c : r.cases()) {
                testcase(x, c, unclaimed(r, c));
            }
            for (CaseResult c : r.cases()) {
                if (c.presented() != null) {
                    presentedTestcase(x, c);
                }
            }
            x.writeEndElement();
            x.writeEndDocument();
            x.close();
        } catch (XMLStreamException e) {
            throw new IllegalStateException("writing XML to a string cannot fail", e);
        }
        return text + "\n";
    }

    /** The counts as the JUnit file has them (Surefire's "Tests run, Failures, Errors, Skipped"). */
    public record Counts(int tests, int failures, int errors, int skipped) {
        /** {@code Tests run: 193, Failures: 0, Errors: 0, Skipped: 12}, as Surefire prints it. */
        public String surefireLine() {
            return "Tests run: " + tests + ", Failures: " + failures + ", Errors: " + errors + ", Skipped: " + skipped;
        }
    }

    public static Counts counts(Report r) {
        Tally t = Tally.of(r);
        // a presented run's second testcase per positive case counts too, as it does in the file
        Report.SemanticAxis sem = r.semantic() != null ? r.semantic() : new Report.SemanticAxis("", 0, 0, 0, 0, 0, 0);
        return new Counts(t.cases() + sem.cases(), t.failures() + sem.failed(), t.errors() + sem.errored(),
                t.unclaimed() + t.notRun() + sem.skipped() + sem.notPresentable());
    }

    /** The JUnit class of a case: its feature row, or for a negative case {@code fclcert.<level>.negative}. */
    public static String className(CaseResult c) {
        return "fclcert." + (c.tests().isEmpty() ? safe(c.level()) + ".negative" : c.tests().get(0).toUpperCase(Locale.ROOT));
    }

    /**
     * Why a case that did not pass counts as skipped: an Extension or Open Level case none of whose features its
     * failure is attributed to ({@link Attribution}) the implementation claims (null for a Basic Level case, a passed
     * one, or a claimed feature's).
     */
    static String unclaimed(Report r, CaseResult c) {
        if (c.status() == CaseStatus.PASSED || c.status() == CaseStatus.SKIPPED || "basic".equals(c.level())
                || c.tests().isEmpty()) {
            return null;
        }
        List<String> claims = r.iut().claims() == null ? List.of() : r.iut().claims();
        // the rows the failure is attributed to (E-RANGE-004, rejected for its RANGE, is E-RANGE's failure even though
        // it also tests the claimed B-DEFAULT-VALUE); a case attributed to none is judged by all it tests
        List<String> rows = Attribution.rows(c);
        List<String> judged = rows.isEmpty() ? c.tests() : rows;
        if (judged.stream().anyMatch(t -> claims.contains(t.toUpperCase(Locale.ROOT)))) {
            return null;
        }
        return "not claimed: " + r.iut().name() + " does not claim " + String.join(", ", judged) + " ("
                + c.status().word() + ": " + c.message() + ")";
    }

    private static void properties(XMLStreamWriter x, Report r) throws XMLStreamException {
        x.writeCharacters("\n  ");
        x.writeStartElement("properties");
        property(x, "iut.name", r.iut().name());
        property(x, "iut.version", r.iut().version());
        property(x, "iut.spec", r.iut().spec());
        property(x, "iut.isolation", Texts.isolation(r));
        property(x, "toolkit.version", r.toolkit().version());
        property(x, "corpus.sha256", r.corpus().sha256());
        property(x, "basicLevel.conformant", String.valueOf(r.basicLevel().conformant()));
        property(x, "basicLevel.verdict", r.basicLevel().verdict());
        Tally t = Tally.of(r);
        property(x, "fclcert.passed", String.valueOf(t.passed()));
        property(x, "fclcert.failures", String.valueOf(t.failures()));
        property(x, "fclcert.errors", String.valueOf(t.errors()));
        property(x, "fclcert.unclaimed", String.valueOf(t.unclaimed()));
        property(x, "fclcert.notRun", String.valueOf(t.notRun()));
        if (r.origin() != null) {
            if (r.origin().provenance() != null) {
                property(x, "run.seed", r.origin().provenance().seed());
            }
            property(x, "results.digest", String.valueOf(r.origin().digest()));
            property(x, "run.endedAt", String.valueOf(r.origin().endedAt()));
            for (int i = 0; i < r.origin().lines().size(); i++) {
                property(x, "provenance." + (i + 1), r.origin().lines().get(i).strip());
            }
            for (int i = 0; i < r.origin().warnings().size(); i++) {
                property(x, "warning." + (i + 1), r.origin().warnings().get(i));
            }
        }
        x.writeCharacters("\n  ");
        x.writeEndElement();
    }

    private static void property(XMLStreamWriter x, String name, String value) throws XMLStreamException {
        x.writeCharacters("\n    ");
        x.writeEmptyElement("property");
        x.writeAttribute("name", name);
        x.writeAttribute("value", safe(value));
    }

    private static void testcase(XMLStreamWriter x, CaseResult c, String unclaimed) throws XMLStreamException {
        x.writeCharacters("\n  ");
        x.writeStartElement("testcase");
        x.writeAttribute("name", c.id() + (c.title() == null ? "" : ": " + safe(c.title())));
        x.writeAttribute("classname", className(c));
        x.writeAttribute("time", seconds(millis(c)));
        if (unclaimed != null) {
            x.writeEmptyElement("skipped");
            x.writeAttribute("message", safe(unclaimed));
            x.writeEndElement();
            return;
        }
        switch (c.status()) {
            case FAILED -> outcome(x, "failure", "wrong-result", c);
            case ERRORED -> outcome(x, "error", "implementation-fault", c);
            case SKIPPED -> {
                x.writeEmptyElement("skipped");
                x.writeAttribute("message", safe(c.message()));
            }
            case PASSED -> {
            }
        }
        x.writeEndElement();
    }

    /** The semantic axis of a case: its own testcase, classname {@code fclcert.semantic.<layout>.<level>.<feature>}. */
    private static void presentedTestcase(XMLStreamWriter x, CaseResult c) throws XMLStreamException {
        CaseResult.Presented p = c.presented();
        x.writeCharacters("\n  ");
        x.writeStartElement("testcase");
        x.writeAttribute("name", c.id() + " [semantic, " + safe(p.dialect()) + " layout]"
                + (c.title() == null ? "" : ": " + safe(c.title())));
        x.writeAttribute("classname", "fclcert.semantic." + safe(p.dialect()) + "." + safe(c.level()) + "."
                + (c.tests().isEmpty() ? "other" : c.tests().get(0).toUpperCase(Locale.ROOT)));
        x.writeAttribute("time", "0.000");
        switch (p.status()) {
            case FAILED, ERRORED -> {
                x.writeStartElement(p.status() == PresentedStatus.FAILED ? "failure" : "error");
                x.writeAttribute("message", safe(p.message()));
                x.writeAttribute("type", p.status() == PresentedStatus.FAILED ? "wrong-result" : "implementation-fault");
                StringBuilder detail = new StringBuilder();
                java.util.Optional.ofNullable(p.evidence().mismatch()).ifPresent(m -> detail.append("expected: ").append(Texts.describe(m.expected()))
                        .append("\nactual:   ").append(Texts.describe(m.actual())).append('\n'));
                if (p.evidence().error() != null) {
                    detail.append(p.evidence().error()).append('\n');
                }
                x.writeCharacters(safe(detail.toString()));
                x.writeEndElement();
            }
            case SKIPPED, NOT_PRESENTABLE -> {
                x.writeEmptyElement("skipped");
                x.writeAttribute("message", safe(p.message()));
            }
            case PASSED -> {
            }
        }
        x.writeEndElement();
    }

    private static void outcome(XMLStreamWriter x, String element, String type, CaseResult c)
            throws XMLStreamException {
        x.writeStartElement(element);
        x.writeAttribute("message", safe(c.message()));
        x.writeAttribute("type", type);
        StringBuilder detail = new StringBuilder();
        c.mismatch().ifPresent(m -> detail.append("expected: ").append(Texts.describe(m.expected()))
                .append("\nactual:   ").append(Texts.describe(m.actual())).append('\n'));
        if (c.evidence().error() != null) {
            detail.append(c.evidence().error()).append('\n');
        }
        x.writeCharacters(safe(detail.toString()));
        x.writeEndElement();
    }

    private static long millis(CaseResult c) {
        return c.setup().durationMs() == null ? 0 : c.setup().durationMs();
    }

    private static String seconds(long millis) {
        return String.format(Locale.ROOT, "%.3f", millis / 1000.0);
    }

    private static String safe(String s) {
        return Texts.xmlSafe(s);
    }
}
