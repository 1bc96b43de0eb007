package org.fclcert.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ExportStatus;
import org.junit.jupiter.api.Test;

/** The report's header line and the reasons given for exports that were not checked. */
class ReportTextsTest {
    private static CaseResult notExported(String id, CaseStatus status, Object expected) {
        return MadeResults.made(id, "basic", List.of("B-FB"), List.of(), status, "m", expected, null, ExportStatus.NOT_RUN,
                null);
    }

    @Test
    void exportsNotCheckedSayWhy() {
        List<CaseResult> cases = List.of(
                notExported("B-FB-001", CaseStatus.FAILED, "load and evaluate"),
                notExported("B-FB-002", CaseStatus.FAILED, "load and evaluate"),
                notExported("N-C001-001", CaseStatus.PASSED, "reject FCL-C001 at line 3"),
                notExported("B-FB-003", CaseStatus.ERRORED, null));
        assertEquals("4 not-run (2: the program was rejected at load; 1: a negative case (nothing to export); 1: the"
                + " implementation broke down during the case).", Texts.exportSummary(cases));
    }

    @Test
    void theHeaderNamesTheImplementationThenHowItWasReached() {
        Report r = ComparisonPageTest.report("jfuzzylite", List.of());
        assertEquals("jfuzzylite 1.0, reached as `jfuzzylite`", Texts.implementation(r));
        String md = MarkdownReport.render(r);
        assertTrue(md.contains("\n- Implementation: jfuzzylite 1.0, reached as `jfuzzylite`\n"), md);
        // a built-in adapter says what it cannot see of its library
        assertTrue(md.contains("\n- What the adapter cannot observe: jfuzzylite builds only the first function block of a"
                + " program; its variables start at NaN"), md);
        assertTrue(HtmlReport.render(r).contains("What the adapter cannot observe: jfuzzylite builds only"));
        assertTrue(!MarkdownReport.render(ComparisonPageTest.report("process:x", List.of())).contains("cannot observe"));
    }
}
