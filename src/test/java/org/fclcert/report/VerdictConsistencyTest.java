package org.fclcert.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.stream.Stream;
import org.fclcert.harness.ResultsFile;
import org.junit.jupiter.api.Test;

/**
 * No verdict contradicts a row (issue 29), over every committed report under reports/: each rebuilt from its
 * results.jsonl with today's rules (what scripts/regenerate-reports will write) and each report.json as committed read
 * back. The vendor personas (the Python example and the Java SPI engine) are held to the same invariants in
 * {@code VendorWalkthroughTest} and the Maven integration test {@code vendor-spi-only}.
 */
class VerdictConsistencyTest {
    private static List<Path> committed() throws Exception {
        try (Stream<Path> dirs = Files.list(Path.of("reports"))) {
            return dirs.filter(d -> Files.isRegularFile(d.resolve("results.jsonl"))).sorted().toList();
        }
    }

    @Test
    void everyCommittedReportRebuiltFromItsResultsIsConsistent() throws Exception {
        List<Path> dirs = committed();
        assertTrue(dirs.size() >= 4, "reports/ holds " + dirs);
        for (Path dir : dirs) {
            Report r = ReportBuilder.build(ResultsFile.read(dir.resolve("results.jsonl")), Instant.EPOCH);
            assertEquals(List.of(), VerdictInvariants.violations(r), dir.toString());
            assertFalse(r.basicLevel().notDetermined(), dir + " is a whole run");
        }
    }

    /**
     * The libraries' committed results, rebuilt: what they said is what their causes quote, and a row is held only
     * to failures attributed to it.
     */
    @Test
    void theCommittedLibrariesCausesQuoteTheirOwnMessages() throws Exception {
        Report fuzzylite = ReportBuilder.build(ResultsFile.read(Path.of("reports/fuzzylite-6.0/results.jsonl")),
                Instant.EPOCH);
        assertTrue(fuzzylite.causes().stream().anyMatch(c -> c.cause().startsWith("fuzzylite: [factory error]"
                + " constructor of Defuzzifier <CoGS> not registered")), fuzzylite.causes().toString());
        fuzzylite.causes().stream().filter(c -> c.kind().equals("rejected at load"))
                .forEach(c -> assertTrue(c.cause().startsWith("fuzzylite: "), c.sentence()));
    }

    @Test
    void everyCommittedReportJsonReadsBackWithAVerdict() throws Exception {
        for (Path dir : committed()) {
            Report r = JsonReport.read(dir.resolve("report.json"));
            assertTrue(List.of("conformant", "not conformant").contains(r.basicLevel().verdict()), dir.toString());
        }
    }
}
