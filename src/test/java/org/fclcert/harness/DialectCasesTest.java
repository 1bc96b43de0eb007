package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fclcert.corpus.Corpus;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.report.FeatureStatus;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Corpus cases written in a library's dialect ({@code dialect:} in the metadata, conformance/README.md): sent as they
 * are only to an implementation that reads the dialect (the reference reads every one; a library adapter its own
 * layout; a vendor's implementation none), reported as not presentable to the others, and shown in their Table 10
 * rows.
 */
class DialectCasesTest {
    private static List<RunCase> dialectCases;

    @BeforeAll
    static void corpus() throws Exception {
        dialectCases = RunCases.from(Corpus.load(Path.of("conformance")).cases()).stream().filter(RunCase::inDialect)
                .toList();
        assertTrue(dialectCases.size() >= 20, "dialect cases: " + dialectCases.size());
    }

    @Test
    void whoReadsWhichDialectIsDrawnFromTheListOfImplementations() {
        for (Dialect d : Dialect.values()) {
            assertTrue(Iuts.reads("reference", d), d.cliName());
            assertEquals(d == Dialect.STRICT, Iuts.reads("java:com.example.Fcl", d), d.cliName());
            assertEquals(d == Dialect.STRICT, Iuts.reads("process:python3 my_iut.py", d), d.cliName());
            assertEquals(d == Dialect.STRICT || d == Dialect.FUZZYLITE, Iuts.reads("fuzzylite", d), d.cliName());
            assertEquals(d == Dialect.STRICT || d == Dialect.FUZZYLITE, Iuts.reads("jfuzzylite:/x.jar", d), d.cliName());
            assertEquals(d == Dialect.STRICT || d == Dialect.FLL, Iuts.reads("pyfuzzylite", d), d.cliName());
            assertEquals(d == Dialect.STRICT, Iuts.reads("no-such-kind", d), d.cliName());
        }
    }

    /** A stand-in that records how it was sent each program and answers every evaluation with nothing. */
    private static final class Recorder extends ScriptedIut {
        final List<String> sent = new ArrayList<>();

        Recorder() {
            super(fcl -> new LoadOutcome.Loaded(List.of("fb")), (call, in) -> Map.of());
        }

        @Override
        public LoadOutcome load(String fcl) throws IutException {
            sent.add("load");
            return super.load(fcl);
        }

        @Override
        public LoadOutcome loadWritten(String text, Dialect layout) throws IutException {
            sent.add("loadWritten " + layout.cliName());
            return super.load(text);
        }
    }

    private static List<CaseResult> run(ImplementationUnderTest iut, String spec, List<RunCase> cases) throws Exception {
        RunHeader header = header(iut, spec, cases);
        return new Runner(RunListener.NONE).run(iut, header, cases, new ResultSink() {
            @Override
            public void header(RunHeader h) {
            }

            @Override
            public void accept(CaseResult result) {
            }
        });
    }

    private static RunHeader header(ImplementationUnderTest iut, String spec, List<RunCase> cases) throws Exception {
        return RunHeaders.of(iut.hello(), spec, null, "conformance", "", cases, cases,
                List.of(List.of(), List.of(), List.of()));
    }

    @Test
    void anImplementationThatDoesNotReadTheDialectIsNeverSentTheCaseAndNoRowCountsIt() throws Exception {
        Recorder vendor = new Recorder();
        List<CaseResult> results = run(vendor, "process:python3 my_iut.py", dialectCases);
        assertEquals(List.of(), vendor.sent, "a vendor's implementation was sent a dialect's text");
        for (CaseResult r : results) {
            assertEquals(CaseStatus.SKIPPED, r.status(), r.id());
            assertTrue(r.message().startsWith("not presentable: the case is written in "), r.id() + ": " + r.message());
            assertTrue(r.message().contains("which this implementation is not sent"),
                    r.id() + ": " + r.message());
        }
        Report report = ReportBuilder.build(header(vendor, "process:python3 my_iut.py", dialectCases), results,
                List.of(), List.of(), Instant.now());
        assertTrue(report.run().complete(), "a case not presentable is not a case the run did not reach");
        Report.FeatureRow tsukamoto = row(report, "O-TSUKAMOTO");
        assertEquals(FeatureStatus.NOT_TESTED, tsukamoto.status());
        assertEquals(0, tsukamoto.failed() + tsukamoto.errored());
    }

    @Test
    void theLibraryWhoseDialectItIsGetsTheTextAsWrittenInItsLayout() throws Exception {
        Recorder fuzzylite = new Recorder();
        RunCase one = dialectCases.get(0);
        List<CaseResult> results = run(fuzzylite, "fuzzylite", List.of(one));
        assertFalse(fuzzylite.sent.isEmpty(), "fuzzylite was not sent the case");
        fuzzylite.sent.forEach(s -> assertEquals("loadWritten fuzzylite", s));
        assertFalse(fuzzylite.sent.contains("load"), "the dialect's text went through the standard's load");
        // it answers nothing, so the case fails: sent, judged, and counted against its row
        assertEquals(CaseStatus.FAILED, results.get(0).status(), results.get(0).message());
    }

    @Test
    void theReferencePassesEveryDialectCaseAndItsTable10RowsAreRealised() throws Exception {
        try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
            List<CaseResult> results = run(reference, "reference", dialectCases);
            for (CaseResult r : results) {
                assertEquals(CaseStatus.PASSED, r.status(), r.id() + ": " + r.message());
                assertEquals(org.fclcert.harness.ExportStatus.NOT_RUN, r.export().status(), r.id());
            }
            Report report = ReportBuilder.build(header(reference, "reference", dialectCases), results, List.of(),
                    List.of(), Instant.now());
            for (String id : List.of("O-TSUKAMOTO", "O-TAKAGI-SUGENO", "O-SHAPE-GAUSSIAN", "O-SHAPE-BELL", "O-HEDGE-VERY")) {
                Report.FeatureRow r = row(report, id);
                assertEquals(10, r.table(), id);
                assertEquals(FeatureStatus.REALISED, r.status(), id + ": " + r);
            }
            // a dialect's own construct no case tests keeps no row
            assertTrue(report.features().stream().noneMatch(f -> f.id().equals("O-FFLL-TERM-ONLY-CONDITION")));
        }
    }

    @Test
    void aCaseWithFreshVectorsKeepsItsTextAndSaysWhyItIsNotDisguised() throws Exception {
        try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
            RunCase c = dialectCases.stream().filter(x -> x.id().equals("O-SHAPE-GAUSSIAN-001")).findFirst().orElseThrow();
            RunHeader header = header(reference, "reference", List.of(c));
            CaseResult r = new Runner(RunListener.NONE).withSeed(99).run(reference, header, List.of(c), new ResultSink() {
                @Override
                public void header(RunHeader h) {
                }

                @Override
                public void accept(CaseResult result) {
                }
            }).get(0);
            assertEquals(CaseStatus.PASSED, r.status(), r.message());
            assertTrue(r.verdict().notes().stream().anyMatch(n -> n.contains("sent undisguised")), r.verdict().notes().toString());
        }
    }

    private static Report.FeatureRow row(Report r, String id) {
        return r.features().stream().filter(f -> f.id().equals(id)).findFirst()
                .orElseThrow(() -> new AssertionError("no row " + id));
    }
}
