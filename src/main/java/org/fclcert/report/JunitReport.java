package org.fclcert.report;

import java.io.StringWriter;
import java.util.Locale;
import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamWriter;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.PresentedStatus;

/**
 * {@code junit.xml} in the Surefire shape CI servers read: one testcase per case, classname
 * {@code fclcert.<level>.<first feature tested>}; a {@code failure} for a wrong result or a wrongly
 * accepted/rejected program, an {@code error} for a crash, timeout or protocol fault, {@code skipped} with
 * its reason.
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
            Report.SemanticAxis sem = r.semantic() != null ? r.semantic() : new Report.SemanticAxis("", 0, 0, 0, 0, 0, 0);
            x.writeAttribute("tests", String.valueOf(r.summary().cases() + sem.cases()));
            x.writeAttribute("failures", String.valueOf(r.summary().failed() + sem.failed()));
            x.writeAttribute("errors", String.valueOf(r.summary().errored() + sem.errored()));
            x.writeAttribute("skipped", String.valueOf(r.summary().skipped() + sem.skipped() + sem.notPresentable()));
            x.writeAttribute("time", seconds(r.cases().stream().mapToLong(c -> millis(c)).sum()));
            x.writeAttribute("timestamp", r.generatedAt());
            properties(x, r);
            for (CaseResult c : r.cases()) {
                testcase(x, c);
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

    private static void properties(XMLStreamWriter x, Report r) throws XMLStreamException {
        x.writeCharacters("\n  ");
        x.writeStartElement("properties");
        property(x, "iut.name", r.iut().name());
        property(x, "iut.version", r.iut().version());
        property(x, "iut.spec", r.iut().spec());
        property(x, "toolkit.version", r.toolkit().version());
        property(x, "corpus.sha256", r.corpus().sha256());
        property(x, "basicLevel.conformant", String.valueOf(r.basicLevel().conformant()));
        x.writeCharacters("\n  ");
        x.writeEndElement();
    }

    private static void property(XMLStreamWriter x, String name, String value) throws XMLStreamException {
        x.writeCharacters("\n    ");
        x.writeEmptyElement("property");
        x.writeAttribute("name", name);
        x.writeAttribute("value", safe(value));
    }

    private static void testcase(XMLStreamWriter x, CaseResult c) throws XMLStreamException {
        x.writeCharacters("\n  ");
        x.writeStartElement("testcase");
        x.writeAttribute("name", c.id() + (c.title() == null ? "" : ": " + safe(c.title())));
        x.writeAttribute("classname", "fclcert." + safe(c.level()) + "."
                + (c.tests().isEmpty() ? "other" : c.tests().get(0).toUpperCase(Locale.ROOT)));
        x.writeAttribute("time", seconds(millis(c)));
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
